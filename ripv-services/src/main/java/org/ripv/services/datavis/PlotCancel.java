package org.ripv.services.datavis;

import java.io.IOException;
import java.nio.file.WatchService;

/**
 * {@code ?cancel} of the request that runs now. A plot waits on a {@link WatchService} for the
 * worker's answer; cancelling closes it, which ends the wait at once, and the caller stops the
 * worker (a plot cannot be stopped half way otherwise; the worker is started again for the next
 * request). The server shows the MailBox busy from the moment the request starts, so a cancel is
 * taken from then on, not only once the plot waits: one taken earlier closes the watch as the
 * plot begins to wait, or stops the request before its plot starts. Methods are called from the
 * request's thread and, for {@link #ask}, from RMI's.
 */
final class PlotCancel {
    private boolean running;
    private WatchService waiting;
    private boolean asked;

    /** A request starts: from now on a cancel is taken. */
    synchronized void start() {
        running = true;
        asked = false;
        waiting = null;
    }

    /** The plot starts waiting on {@code watch}; a cancel already taken closes it at once. */
    synchronized void begin(WatchService watch) {
        waiting = watch;
        if (asked) {
            close(watch);
        }
    }

    /** The request is over: there is nothing to cancel until the next one starts. */
    synchronized void end() {
        running = false;
        waiting = null;
    }

    /**
     * True when a request was running and now will not finish: a waiting plot's wait ends with
     * ClosedWatchServiceException, and a request not yet waiting sees {@link #asked()}.
     */
    synchronized boolean ask() {
        if (!running) {
            return false;
        }
        asked = true;
        if (waiting != null) {
            close(waiting);
        }
        return true;
    }

    synchronized boolean asked() {
        return asked;
    }

    private static void close(WatchService watch) {
        try {
            watch.close();
        } catch (IOException e) {
            // closed or not, the request sees asked() and stops
        }
    }
}
