package org.ripv.service;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.ripv.messages.ConsoleEntry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Carries a service's console entries to the server on a thread of its own, batched, so that a
 * vehicle printing fast never waits on RMI. The queue is bounded: when the server cannot keep up,
 * entries are skipped and one "N lines skipped" line says so, in place, once it can.
 */
final class ConsolePublisher {
    private static final Logger log = LoggerFactory.getLogger(ConsolePublisher.class);
    private static final int BATCH = 500;

    private final BlockingQueue<ConsoleEntry> queue;
    private final Supplier<ReplySink> sink;
    private final AtomicLong skipped = new AtomicLong();
    private volatile String skippedMailbox;
    private final Thread thread;

    ConsolePublisher(String name, int capacity, Supplier<ReplySink> sink) {
        this.queue = new ArrayBlockingQueue<>(capacity);
        this.sink = sink;
        this.thread = new Thread(this::run, "console-publisher-" + name);
        thread.setDaemon(true);
        thread.start();
    }

    void publish(ConsoleEntry entry) {
        if (!queue.offer(entry)) {
            skippedMailbox = entry.mailbox();
            skipped.incrementAndGet();
        }
    }

    void stop() {
        thread.interrupt();
    }

    private void run() {
        List<ConsoleEntry> batch = new ArrayList<>(BATCH);
        try {
            while (!Thread.currentThread().isInterrupted()) {
                ConsoleEntry first = queue.poll(1, TimeUnit.SECONDS);
                long lost = skipped.getAndSet(0);
                if (lost > 0) {
                    batch.add(ConsoleEntry.line(skippedMailbox, "[" + lost + " lines skipped: the server could not keep up]"));
                }
                if (first == null && batch.isEmpty()) {
                    continue;
                }
                if (first != null) {
                    batch.add(first);
                    queue.drainTo(batch, BATCH - batch.size());
                }
                try {
                    sink.get().console(List.copyOf(batch));
                } catch (Exception e) {
                    // Not registered, or the server is away: the console is live, not a queue.
                    log.debug("dropped {} console entries: {}", batch.size(), e.toString());
                }
                batch.clear();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
