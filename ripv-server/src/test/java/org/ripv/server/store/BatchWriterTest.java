package org.ripv.server.store;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** The writer thread behind the transcript and the audit trail: batches, drops counted, sync, close, a failing sink. */
class BatchWriterTest {
    @Test
    void itemsArriveInOrderAndSyncWaitsForThem() {
        List<Integer> seen = new CopyOnWriteArrayList<>();
        try (BatchWriter<Integer> w = new BatchWriter<>("test-writer", 1000, 10, (batch, dropped) -> seen.addAll(batch))) {
            for (int i = 0; i < 500; i++) {
                assertThat(w.offer(i)).isTrue();
            }
            w.sync();
            assertThat(seen).hasSize(500);
            assertThat(seen).isSorted();
        }
    }

    @Test
    void aFullQueueDropsAndTheNextBatchIsToldHowMany() throws Exception {
        CountDownLatch stuck = new CountDownLatch(1);
        CountDownLatch inside = new CountDownLatch(1);
        AtomicLong told = new AtomicLong();
        List<Integer> seen = new CopyOnWriteArrayList<>();
        try (BatchWriter<Integer> w = new BatchWriter<>("test-writer", 5, 100, (batch, dropped) -> {
            inside.countDown();
            try {
                stuck.await(); // a store that hangs: the queue fills behind it
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            told.addAndGet(dropped);
            seen.addAll(batch);
        })) {
            w.offer(-1);
            assertThat(inside.await(5, TimeUnit.SECONDS)).isTrue();
            int refused = 0;
            for (int i = 0; i < 20; i++) {
                if (!w.offer(i)) {
                    refused++;
                }
            }
            assertThat(refused).isEqualTo(15); // never blocked: 5 waited, the rest were counted
            stuck.countDown();
            w.sync();
            assertThat(told.get()).isEqualTo(15);
            assertThat(seen).containsExactly(-1, 0, 1, 2, 3, 4);
        }
    }

    /**
     * Closing while a batch is being written lets the write finish uninterrupted: an interrupt
     * inside a file channel's write loses the batch (ServerAwayTest's vehicle state, in CI).
     */
    @Test
    void closeDoesNotInterruptAWriteInProgress() throws Exception {
        CountDownLatch inside = new CountDownLatch(1);
        java.util.concurrent.atomic.AtomicBoolean interrupted = new java.util.concurrent.atomic.AtomicBoolean();
        List<Integer> seen = new CopyOnWriteArrayList<>();
        BatchWriter<Integer> w = new BatchWriter<>("test-writer", 100, 10, (batch, dropped) -> {
            inside.countDown();
            try {
                Thread.sleep(300); // a write under way, as a file channel's would be
            } catch (InterruptedException e) {
                interrupted.set(true);
            }
            seen.addAll(batch);
        });
        w.offer(1);
        assertThat(inside.await(5, TimeUnit.SECONDS)).isTrue();
        w.offer(2);
        w.close();
        assertThat(interrupted).isFalse();
        assertThat(seen).containsExactly(1, 2);
    }

    @Test
    void aSinkThatThrowsLosesOnlyItsBatch() {
        List<Integer> seen = new CopyOnWriteArrayList<>();
        try (BatchWriter<Integer> w = new BatchWriter<>("test-writer", 1000, 1, (batch, dropped) -> {
            if (batch.contains(13)) {
                throw new IllegalStateException("disk on fire");
            }
            seen.addAll(batch);
        })) {
            for (int i = 10; i < 16; i++) {
                w.offer(i);
                w.sync();
            }
            assertThat(seen).containsExactly(10, 11, 12, 14, 15);
        }
    }

    @Test
    void closeWritesWhatWaitsThenRefuses() {
        List<Integer> seen = new CopyOnWriteArrayList<>();
        BatchWriter<Integer> w = new BatchWriter<>("test-writer", 1000, 1, (batch, dropped) -> {
            try {
                Thread.sleep(20); // a slow store: items are still queued when close comes
            } catch (InterruptedException e) {
                // closing: this batch is written anyway
            }
            seen.addAll(batch);
        });
        for (int i = 0; i < 10; i++) {
            w.offer(i);
        }
        w.close();
        assertThat(seen).containsExactly(0, 1, 2, 3, 4, 5, 6, 7, 8, 9);
        assertThat(w.offer(99)).as("closed: refused").isFalse();
    }
}
