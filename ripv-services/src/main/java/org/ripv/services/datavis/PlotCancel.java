package org.ripv.services.datavis;

import java.io.IOException;
import java.nio.file.WatchService;

/**
 * {@code ?cancel} of the plot that runs now. The request waits on a {@link WatchService} for the
 * worker's answer; cancelling closes it, which ends the wait at once, and the caller stops the
 * worker (a plot cannot be stopped half way otherwise; the worker is started again for the next
 * request). Methods are called from the request's thread and, for {@link #ask}, from RMI's.
 */
final class PlotCancel {
    private WatchService waiting;
    private boolean asked;

    /** A plot starts waiting on {@code watch}. */
    synchronized void begin(WatchService watch) {
        waiting = watch;
        asked = false;
    }

    /** The plot is over. */
    synchronized void end() {
        waiting = null;
    }

    /** True when a plot was waiting and now will not: its wait ends with ClosedWatchServiceException. */
    synchronized boolean ask() {
        if (waiting == null) {
            return false;
        }
        asked = true;
        try {
            waiting.close();
        } catch (IOException e) {
            // closed or not, the request sees asked() and stops
        }
        return true;
    }

    synchronized boolean asked() {
        return asked;
    }
}
