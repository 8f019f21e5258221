package org.ripv.server.handlers;

import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The few threads that write every client's socket (docs/concurrency.md). A client with replies
 * waiting is put once on a shared ready queue; a worker takes it, writes everything it has queued
 * with one flush, and puts it back at the end of the queue if more arrived meanwhile. A console
 * line for 1,000 watchers is thus 1,000 writes by {@link #WORKERS} threads instead of 1,000
 * thread wake-ups.
 *
 * <p>Sockets never block a worker (org.ripv.server.transport): what a socket does not take waits
 * in its connection, and past a bound the writer leaves the rest in the client's queue until the
 * connection has drained. A turn can still be long (a large reply to encode): a check every
 * {@link #STALL_MILLIS} finds a worker that has been on one client for that long; that worker
 * leaves the pool and stays with that client alone (until it has had nothing to write for a
 * while), and a new worker takes its place, so one client never holds the shared writers up.
 */
public final class WriterPool implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(WriterPool.class);
    /** Workers: writes are short and mostly CPU (TLS, system calls), so about the cores, at least two. */
    static final int WORKERS = Math.max(2, Runtime.getRuntime().availableProcessors());
    /** How long one worker may write one client before it is taken out of the pool. */
    static final long STALL_MILLIS = 100;

    private final BlockingQueue<ReplyWriter> ready = new LinkedBlockingQueue<>();
    private final List<Worker> workers = new CopyOnWriteArrayList<>();
    private final AtomicInteger names = new AtomicInteger();
    private final ScheduledFuture<?> check;
    private volatile boolean closed;

    /** @param timers runs the stall check (a few field reads every {@link #STALL_MILLIS}) */
    public WriterPool(ScheduledExecutorService timers) {
        for (int i = 0; i < WORKERS; i++) {
            startWorker();
        }
        check = timers.scheduleWithFixedDelay(this::checkStalls, STALL_MILLIS, STALL_MILLIS, TimeUnit.MILLISECONDS);
    }

    /** A client has replies waiting and no thread on it: a worker will write them. */
    void ready(ReplyWriter writer) {
        ready.add(writer);
    }

    private void startWorker() {
        Worker w = new Worker();
        workers.add(w);
        w.thread.start();
    }

    private void checkStalls() {
        long now = System.nanoTime();
        for (Worker w : workers) {
            long since = w.since;
            if (since != 0 && now - since > TimeUnit.MILLISECONDS.toNanos(STALL_MILLIS) && workers.remove(w)) {
                w.detached = true;
                log.debug("{} has been writing to one client for over {} ms: it stays with that client, a new worker"
                        + " takes its place", w.thread.getName(), STALL_MILLIS);
                if (!closed) {
                    startWorker();
                }
            }
        }
    }

    private final class Worker implements Runnable {
        final Thread thread = new Thread(this, "ripv-socket-writer-" + names.incrementAndGet());
        /** When the current write began (System.nanoTime), or 0 between clients. */
        volatile long since;
        volatile boolean detached;

        Worker() {
            thread.setDaemon(true);
        }

        @Override
        public void run() {
            try {
                while (!closed) {
                    ReplyWriter w = ready.take();
                    since = System.nanoTime();
                    boolean more;
                    try {
                        more = w.turn();
                    } finally {
                        since = 0;
                    }
                    if (detached) {
                        if (more) {
                            w.dedicated(); // this thread is now that client's own writer until it goes quiet
                        }
                        return;
                    }
                    if (more) {
                        ready.add(w); // to the back: one busy client does not hold up the others
                    }
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (RuntimeException e) {
                log.error("{} failed", thread.getName(), e);
                if (!detached && workers.remove(this) && !closed) {
                    startWorker();
                }
            }
        }
    }

    @Override
    public void close() {
        closed = true;
        check.cancel(false);
        workers.forEach(w -> w.thread.interrupt());
        workers.clear();
    }
}
