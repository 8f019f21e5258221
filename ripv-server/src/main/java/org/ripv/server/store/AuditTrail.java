package org.ripv.server.store;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.ripv.server.store.StateStore.AuditRecord;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Takes audit lines from any thread without waiting and appends them to the store in batches on
 * a thread of its own ({@link BatchWriter}), so that a slow disk or database never holds up a
 * log-in. When the store cannot keep up, lines are dropped and the next batch says how many.
 */
public final class AuditTrail implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(AuditTrail.class);
    static final int QUEUE = 10_000;

    private final BatchWriter<AuditRecord> writer;

    public AuditTrail(StateStore store) {
        this.writer = new BatchWriter<>("ripv-audit-writer", QUEUE, 1000, (batch, dropped) -> {
            List<AuditRecord> records = new ArrayList<>(batch.size() + 1);
            if (dropped > 0) {
                records.add(new AuditRecord(System.currentTimeMillis(), true, "audit-dropped count=" + dropped));
            }
            records.addAll(batch);
            try {
                store.appendAudit(records);
            } catch (IOException | RuntimeException e) {
                log.warn("could not store {} audit lines (they are in the log): {}", records.size(), e.toString());
            }
        });
    }

    /** Queues one line ({@code event key=value ...}); never blocks. */
    public void record(boolean warn, String line) {
        writer.offer(new AuditRecord(System.currentTimeMillis(), warn, line));
    }

    /** Waits (briefly) until what was queued so far is stored. */
    public void sync() {
        writer.sync();
    }

    /** Stores what is queued, then stops. */
    @Override
    public void close() {
        writer.close();
    }
}
