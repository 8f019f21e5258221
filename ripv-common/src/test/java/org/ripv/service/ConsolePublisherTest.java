package org.ripv.service;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.OutgoingServiceMessage;

/** The service side of the live console: bounded, batched, never blocking, skips marked. */
class ConsolePublisherTest {
    private ConsolePublisher publisher;

    @AfterEach
    void stop() {
        if (publisher != null) {
            publisher.stop();
        }
    }

    /** A sink that records batches and can be held, like a server that is slow to answer. */
    static final class HeldSink implements ReplySink {
        final List<List<ConsoleEntry>> batches = new CopyOnWriteArrayList<>();
        final CountDownLatch release = new CountDownLatch(1);
        final CountDownLatch firstCall = new CountDownLatch(1);
        final boolean hold;

        HeldSink(boolean hold) {
            this.hold = hold;
        }

        @Override
        public void reply(OutgoingServiceMessage reply) {
        }

        @Override
        public void console(List<ConsoleEntry> entries) throws Exception {
            firstCall.countDown();
            if (hold) {
                release.await();
            }
            batches.add(entries);
        }

        List<String> texts() {
            List<String> all = new ArrayList<>();
            batches.forEach(b -> b.forEach(e -> all.add(e.text())));
            return all;
        }

        int entries() {
            return batches.stream().mapToInt(List::size).sum();
        }
    }

    private static ConsoleEntry line(int i) {
        return ConsoleEntry.line("<S>::<h>ru29", "line " + i);
    }

    private static void await(String what, java.util.function.BooleanSupplier done) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!done.getAsBoolean()) {
            assertTrue(System.nanoTime() < deadline, "not within 10 s: " + what);
            Thread.sleep(10); // the publisher's thread delivers on its own schedule
        }
    }

    @Test
    void entriesArriveInOrderInBatches() throws Exception {
        HeldSink sink = new HeldSink(false);
        publisher = new ConsolePublisher("t", 10_000, () -> sink);
        for (int i = 0; i < 2_000; i++) {
            publisher.publish(line(i));
        }
        await("all entries", () -> sink.entries() == 2_000);
        List<String> texts = sink.texts();
        for (int i = 0; i < 2_000; i++) {
            assertEquals("line " + i, texts.get(i));
        }
        assertTrue(sink.batches.size() < 2_000, "batched: " + sink.batches.size() + " calls for 2000 entries");
        assertTrue(sink.batches.stream().allMatch(b -> b.size() <= 500), "batches of at most 500");
    }

    @Test
    void aServerThatCannotKeepUpNeverBlocksThePublisherAndTheSkippedAreCounted() throws Exception {
        HeldSink sink = new HeldSink(true);
        publisher = new ConsolePublisher("t", 100, () -> sink);
        publisher.publish(line(-1));
        assertTrue(sink.firstCall.await(10, TimeUnit.SECONDS), "the first batch is on its way and held");
        long start = System.nanoTime();
        for (int i = 0; i < 10_000; i++) {
            publisher.publish(line(i)); // the queue holds 100; the rest must be skipped, not waited for
        }
        // Waiting on the held server would never end (it is released below): 20 s is only a loaded machine's margin.
        assertTrue(System.nanoTime() - start < TimeUnit.SECONDS.toNanos(20), "publish never waits on the server");
        sink.release.countDown();
        await("the queue drained", () -> sink.texts().contains("line 99"));
        await("the skip marker", () -> sink.texts().stream().anyMatch(t -> t.contains("lines skipped")));
        List<String> texts = sink.texts();
        assertEquals("line -1", texts.get(0));
        String marker = texts.stream().filter(t -> t.contains("lines skipped")).findFirst().orElseThrow();
        assertEquals("[9900 lines skipped: the server could not keep up]", marker);
        assertEquals(1 + 100 + 1, texts.size(), "the held one, the queue's 100, one marker: " + texts.size());
        for (int i = 0; i < 100; i++) {
            assertEquals("line " + i, texts.get(1 + i), "the queue keeps the first ones, in order");
        }
        assertEquals("<S>::<h>ru29", sink.batches.get(sink.batches.size() - 1).get(0).mailbox());
    }

    @Test
    void whatIsSaidWhileTheServerIsAwayArrivesInOrderWhenItIsBack() throws Exception {
        List<ConsoleEntry> got = new CopyOnWriteArrayList<>();
        java.util.concurrent.atomic.AtomicBoolean away = new java.util.concurrent.atomic.AtomicBoolean(true);
        java.util.concurrent.atomic.AtomicInteger refused = new java.util.concurrent.atomic.AtomicInteger();
        publisher = new ConsolePublisher("t", 1000, () -> new ReplySink() {
            @Override
            public void reply(OutgoingServiceMessage reply) {
            }

            @Override
            public void console(List<ConsoleEntry> entries) throws Exception {
                if (away.get()) {
                    refused.incrementAndGet();
                    throw new java.rmi.RemoteException("not registered with a server"); // restarting, or a takeover
                }
                got.addAll(entries);
            }
        });
        for (int i = 1; i <= 300; i++) {
            publisher.publish(line(i));
        }
        await("tried while away", () -> refused.get() >= 3);
        for (int i = 301; i <= 600; i++) {
            publisher.publish(line(i));
        }
        assertTrue(got.isEmpty());
        away.set(false);
        await("all 600", () -> got.size() >= 600);
        assertEquals(600, got.size(), "each once");
        for (int i = 0; i < 600; i++) {
            assertEquals("line " + (i + 1), got.get(i).text(), "in order");
        }
    }
}
