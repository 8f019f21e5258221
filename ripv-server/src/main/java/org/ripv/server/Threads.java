package org.ripv.server;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.SynchronousQueue;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The server's shared thread pools, named (for thread dumps) and daemon, made together and shut
 * down together; the lobby hands each part the pools it uses.
 */
final class Threads implements AutoCloseable {
    /** The server's timer: deadlines, sweeps, service checks. */
    final ScheduledExecutorService timers = Executors.newScheduledThreadPool(1, named("ripv-server-timer"));
    /**
     * Calls to services: each is bounded by the RMI deadlines and at most one MailBox query runs
     * per service, so a cached pool grows by one thread per hung service at worst.
     */
    final ExecutorService checkers = Executors.newCachedThreadPool(named("ripv-service-query"));
    /** Taking back timed-out requests from services. */
    final ExecutorService withdrawals = new ThreadPoolExecutor(0, 16, 30, TimeUnit.SECONDS,
            new SynchronousQueue<>(), named("ripv-withdraw"));
    /** The services' liveness checks. */
    final ExecutorService liveness = Executors.newFixedThreadPool(2, named("ripv-service-check"));
    /** The file commands ({@code ?upload}, {@code ?download}, …), off the Post Office's assistant. */
    final ExecutorService fileWork = Executors.newFixedThreadPool(2, named("ripv-file-work"));

    static ThreadFactory named(String name) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, name + "-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        };
    }

    @Override
    public void close() {
        timers.shutdownNow();
        checkers.shutdownNow();
        withdrawals.shutdownNow();
        liveness.shutdownNow();
        fileWork.shutdownNow();
    }
}
