package org.ripv.server.standby;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Stand by, serve while holding the lead, stop serving when it is lost, stand by again — until
 * {@link #stop}. What is served is opened only once the lead is held (so a standby reads none of
 * the state the active server is writing) and closed before standing by again.
 *
 * @param <S> what serving means (a started RIPVServer)
 */
public final class StandbyLoop<S extends AutoCloseable> {
    private static final Logger log = LoggerFactory.getLogger(StandbyLoop.class);

    /** Opens what is served; called on the loop's thread with the lead held. */
    @FunctionalInterface
    public interface Opener<S> {
        S open() throws Exception;
    }

    private final Supplier<Leadership> leads;
    private final Opener<S> opener;
    private final Consumer<S> serving;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private volatile boolean stopping;
    private volatile Leadership lead;
    private volatile S current;

    /**
     * @param leads   a new {@link Leadership} for each round (each is used once)
     * @param opener  starts serving
     * @param serving told each time serving has started (the launcher's "ready" line)
     */
    public StandbyLoop(Supplier<Leadership> leads, Opener<S> opener, Consumer<S> serving) {
        this.leads = leads;
        this.opener = opener;
        this.serving = serving;
    }

    /**
     * Runs until {@link #stop}. A failure to open what is served ends it (a port in use will not
     * free itself), after giving the lead up; so does a database that cannot be reached at the
     * very first try (a wrong URL or password). Later, an unreachable database means standing by.
     */
    public void run() throws Exception {
        boolean first = true;
        try {
            while (!stopping) {
                Leadership l = leads.get();
                lead = l;
                try {
                    l.awaitLead(first);
                    first = false;
                } catch (InterruptedException e) {
                    if (stopping) {
                        return;
                    }
                    throw e;
                }
                S s;
                try {
                    s = opener.open();
                } catch (Exception e) {
                    l.close();
                    throw e;
                }
                current = s;
                if (stopping) {
                    break;
                }
                serving.accept(s);
                String why;
                try {
                    why = l.lost().get();
                } catch (ExecutionException e) {
                    why = e.getCause().toString();
                }
                current = null;
                s.close();
                l.close();
                if (!stopping) {
                    log.warn("stopped serving ({}); standing by for the lead again", why);
                }
            }
        } finally {
            S s = current;
            if (s != null) {
                s.close();
            }
            Leadership l = lead;
            if (l != null) {
                l.close();
            }
            stopped.countDown();
        }
    }

    /** Stops serving (if it does) and standing by; gives the lead up. Waits until the loop has ended. */
    public void stop() {
        stopping = true;
        S s = current;
        if (s != null) {
            try {
                s.close();
            } catch (Exception e) {
                log.warn("stopping: {}", e.toString());
            }
        }
        Leadership l = lead;
        if (l != null) {
            l.close();
        }
        try {
            stopped.await(TimeUnit.SECONDS.toMillis(30), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
