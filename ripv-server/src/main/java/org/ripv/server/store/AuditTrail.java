package org.ripv.server.store;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.server.store.StateStore.AuditRecord;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Takes audit lines from any thread without waiting and appends them to the store in batches on
 * a thread of its own, so that a slow disk or database never holds up a log-in. When the store
 * cannot keep up, lines are dropped and the next batch says how many.
 */
public final class AuditTrail implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(AuditTrail.class);
    static final int QUEUE = 10_000;

    private final StateStore store;
    private final BlockingQueue<Object> queue = new ArrayBlockingQueue<>(QUEUE);
    private final AtomicLong dropped = new AtomicLong();
    private final Thread writer;
    private volatile boolean closed;

    public AuditTrail(StateStore store) {
        this.store = store;
        this.writer = new Thread(this::writeLoop, "ripv-audit-writer");
        writer.setDaemon(true);
        writer.start();
    }

    /** Queues one line ({@code event key=value ...}); never blocks. */
    public void record(boolean warn, String line) {
        if (closed || !queue.offer(new AuditRecord(System.currentTimeMillis(), warn, line))) {
            dropped.incrementAndGet();
        }
    }

    /** Waits (briefly) until what was queued so far is stored. */
    public void sync() {
        CountDownLatch done = new CountDownLatch(1);
        if (!closed && queue.offer(done)) {
            try {
                done.await(5, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private void writeLoop() {
        List<Object> batch = new ArrayList<>();
        while (!closed || !queue.isEmpty()) {
            try {
                Object first = queue.poll(1, TimeUnit.SECONDS);
                if (first != null) {
                    batch.add(first);
                    queue.drainTo(batch, 1000);
                }
            } catch (InterruptedException e) {
                queue.drainTo(batch);
            }
            List<AuditRecord> records = new ArrayList<>();
            long lost = dropped.getAndSet(0);
            if (lost > 0) {
                records.add(new AuditRecord(System.currentTimeMillis(), true, "audit-dropped count=" + lost));
            }
            List<CountDownLatch> waiting = new ArrayList<>();
            for (Object o : batch) {
                if (o instanceof AuditRecord r) {
                    records.add(r);
                } else if (o instanceof CountDownLatch l) {
                    waiting.add(l);
                }
            }
            batch.clear();
            try {
                store.appendAudit(records);
            } catch (IOException | RuntimeException e) {
                log.warn("could not store {} audit lines (they are in the log): {}", records.size(), e.toString());
            }
            waiting.forEach(CountDownLatch::countDown);
        }
    }

    /** Stores what is queued, then stops. */
    @Override
    public void close() {
        closed = true;
        writer.interrupt();
        try {
            writer.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
