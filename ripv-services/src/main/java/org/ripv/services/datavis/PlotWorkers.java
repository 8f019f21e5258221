package org.ripv.services.datavis;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import org.ripv.service.Availability;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The DataVisServer's plot worker, whichever {@link WorkerMode} it runs: the built-in one (started
 * again when it stopped), {@code octave-cli} on {@code ripvOut.m} (its supervisor restarts it), or
 * one started by hand; how it is started, stopped for a cancelled plot, closed, and what it is
 * doing when asked ({@code ?status}, a plot nobody answered).
 */
final class PlotWorkers {
    private static final Logger log = LoggerFactory.getLogger(PlotWorkers.class);

    private final DataVisServer.Config config;
    private final Path dir;
    private volatile PlotWorker builtin;
    private volatile OctaveWorker octave;

    PlotWorkers(DataVisServer.Config config, Path dir) {
        this.config = config;
        this.dir = dir;
    }

    /** Starts the configured worker in the work directory. */
    void start() throws IOException {
        switch (config.worker()) {
            case BUILTIN -> builtin = PlotWorker.start(dir);
            case OCTAVE -> octave = OctaveWorker.start(dir, config.octave(), config.script());
            case NONE -> log.info("DataVisServer waits for a worker started by hand in {} (e.g. ripvOut.m in MATLAB)", dir);
        }
    }

    /** Before a plot: the built-in worker, started again if it had stopped (or a plot was cancelled). */
    void ensureBuiltin() throws IOException {
        if (config.worker() == WorkerMode.BUILTIN && (builtin == null || !builtin.isAlive())) {
            log.info("the built-in plot worker had stopped (or a plot was cancelled); starting it again");
            builtin = PlotWorker.start(dir);
        }
    }

    /**
     * A cancelled plot's worker: the built-in one is told to stop without waiting for it (it drops
     * the plot it is drawing) and a new one starts with the next request; Octave is killed and its
     * supervisor starts it again.
     */
    void stop() {
        PlotWorker w = builtin;
        if (w != null) {
            builtin = null;
            w.stop();
        }
        OctaveWorker o = octave;
        if (o != null) {
            o.kill();
        }
    }

    void close() {
        PlotWorker w = builtin;
        if (w != null) {
            w.close();
        }
        OctaveWorker o = octave;
        if (o != null) {
            o.close();
        }
    }

    /** The worker's state for {@code ?status}. */
    Availability availability() {
        return switch (config.worker()) {
            case BUILTIN -> {
                PlotWorker w = builtin;
                yield w != null && w.isAlive() ? Availability.available("built-in worker, " + w.plots() + " plot(s) made")
                        : Availability.available("built-in worker stopped; it restarts with the next command");
            }
            case OCTAVE -> {
                OctaveWorker o = octave;
                yield o != null && o.isAlive() ? Availability.available("octave-cli on ripvOut.m, pid " + o.pid())
                        : Availability.notAvailable("octave-cli is not running" + (o == null ? "" : " (" + o.lastExit()
                                + "); it is being restarted"));
            }
            case NONE -> Availability.available("waiting for a worker started by hand in " + dir);
        };
    }

    /** Why no worker answered {@code vis} within {@code timeout}, and what to do. */
    String noAnswer(VisCommand vis, Duration timeout) {
        String s = "no plot worker answered vis:" + vis.file() + " within " + timeout.toSeconds() + " s; ";
        return s + switch (config.worker()) {
            case BUILTIN -> "the built-in worker may be stuck on a very large file; try again, or a longer --timeout";
            case OCTAVE -> {
                OctaveWorker o = octave;
                yield o != null && o.isAlive() ? "octave-cli is running but did not finish (a large plot? raise --timeout)"
                        : "octave-cli is not running" + (o == null ? "" : " (" + o.lastExit() + ")")
                                + ": is Octave installed with gnuplot and fonts? see docs/datavis.md";
            }
            case NONE -> "start one in " + dir + " (MATLAB or octave-cli: cd there and run ripvOut), or run the service with "
                    + "--worker builtin";
        };
    }
}
