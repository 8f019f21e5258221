package org.ripv.server.store;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Takes items from any thread without waiting and hands them, in batches, to a {@link Sink} on a
 * thread of its own, so that a slow disk or database never holds up the thread that produced
 * them (a log-in, a vehicle's console). A full queue drops items and counts them, and the next
 * batch is told how many. {@link #sync} waits until what was queued before it has been written.
 *
 * @param <T> what is queued
 */
public final class BatchWriter<T> implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(BatchWriter.class);

    /** What the writer thread does; every method runs on that thread only. */
    public interface Sink<T> {
        /** Before the first batch. */
        default void started() {}

        /**
         * Writes a batch (never called with nothing to say). An interrupt while it waits means the
         * writer is closing: one last attempt, then return.
         *
         * @param dropped items refused since the last batch because the queue was full
         */
        void write(List<T> batch, long dropped);

        /** After each round, with or without a batch (at least every second): periodic chores. */
        default void afterRound() {}
    }

    /** A {@link #sync} waiting in line. */
    private record Sync(CountDownLatch done) {}

    private final BlockingQueue<Object> queue;
    private final int maxBatch;
    private final Sink<T> sink;
    private final AtomicLong dropped = new AtomicLong();
    private final Thread thread;
    private volatile boolean closed;

    /**
     * Starts the writer thread.
     *
     * @param capacity items waiting before new ones are dropped
     * @param maxBatch the most items one batch takes while running (closing writes the rest at once)
     */
    public BatchWriter(String threadName, int capacity, int maxBatch, Sink<T> sink) {
        this.queue = new ArrayBlockingQueue<>(capacity);
        this.maxBatch = maxBatch;
        this.sink = sink;
        this.thread = new Thread(this::run, threadName);
        thread.setDaemon(true);
        thread.start();
    }

    /** Queues an item; never blocks. False when it was dropped (closed, or the queue is full). */
    public boolean offer(T item) {
        if (closed || !queue.offer(item)) {
            dropped.incrementAndGet();
            return false;
        }
        return true;
    }

    /** Waits (at most about 5 s) until everything queued so far has been written. */
    public void sync() {
        Sync s = new Sync(new CountDownLatch(1));
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        try {
            // A full queue has room again as soon as the writer takes its next batch.
            if (!closed && queue.offer(s, 5, TimeUnit.SECONDS)) {
                s.done().await(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    public boolean isClosed() {
        return closed;
    }

    @SuppressWarnings("unchecked")
    private void run() {
        sink.started();
        List<Object> taken = new ArrayList<>();
        while (!closed || !queue.isEmpty()) {
            try {
                Object first = queue.poll(1, TimeUnit.SECONDS);
                if (first != null) {
                    taken.add(first);
                    queue.drainTo(taken, maxBatch - 1);
                }
            } catch (InterruptedException e) {
                if (!closed) {
                    continue;
                }
                queue.drainTo(taken);
            }
            List<T> batch = new ArrayList<>(taken.size());
            List<Sync> waiting = new ArrayList<>();
            for (Object o : taken) {
                if (o instanceof Sync s) {
                    waiting.add(s);
                } else {
                    batch.add((T) o);
                }
            }
            taken.clear();
            long lost = dropped.getAndSet(0);
            if (!batch.isEmpty() || lost > 0) {
                try {
                    sink.write(batch, lost);
                } catch (RuntimeException e) {
                    log.warn("{}: a batch of {} failed", thread.getName(),
                            batch.size(), e);
                }
            }
            waiting.forEach(s -> s.done().countDown());
            sink.afterRound();
        }
    }

    /** Writes what is queued, then stops (waiting at most 5 s for the thread). */
    @Override
    public void close() {
        closed = true;
        // Woken by a marker, not at once by an interrupt: an interrupt landing inside a write to a
        // file channel closes the channel (ClosedByInterruptException) and loses the batch being
        // written, e.g. a vehicle's state saved just before a shutdown. Only a sink still waiting
        // after a second (a store that does not answer) is interrupted.
        queue.offer(new Sync(new CountDownLatch(1)));
        try {
            thread.join(1000);
            if (thread.isAlive()) {
                thread.interrupt();
                thread.join(4000);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
