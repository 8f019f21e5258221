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
 * entries are skipped and one "N lines skipped" line per MailBox says so, in place (after the
 * entries queued before the skip), once there is room.
 */
final class ConsolePublisher {
    private static final Logger log = LoggerFactory.getLogger(ConsolePublisher.class);
    private static final int BATCH = 500;

    private final BlockingQueue<ConsoleEntry> queue;
    private final Supplier<ReplySink> sink;
    private final java.util.concurrent.ConcurrentHashMap<String, AtomicLong> skipped =
            new java.util.concurrent.ConcurrentHashMap<>();
    private volatile boolean anySkipped;
    private final Thread thread;

    ConsolePublisher(String name, int capacity, Supplier<ReplySink> sink) {
        this.queue = new ArrayBlockingQueue<>(capacity);
        this.sink = sink;
        this.thread = new Thread(this::run, "console-publisher-" + name);
        thread.setDaemon(true);
        thread.start();
    }

    void publish(ConsoleEntry entry) {
        if (anySkipped) {
            queueSkipMarkers();
        }
        if (!queue.offer(entry)) {
            skipped.computeIfAbsent(entry.mailbox(), m -> new AtomicLong()).incrementAndGet();
            anySkipped = true;
        }
    }

    /** Queues one marker per MailBox with skipped entries, while there is room for them and more. */
    private void queueSkipMarkers() {
        anySkipped = false;
        for (var e : skipped.entrySet()) {
            if (queue.remainingCapacity() < 2) {
                anySkipped = true;
                return;
            }
            long n = e.getValue().getAndSet(0);
            if (n > 0 && !queue.offer(ConsoleEntry.line(e.getKey(), "[" + n + " lines skipped: the server could not keep up]"))) {
                e.getValue().addAndGet(n);
                anySkipped = true;
            }
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
                if (first == null) {
                    if (anySkipped) {
                        queueSkipMarkers();
                    }
                    first = queue.poll();
                    if (first == null) {
                        continue;
                    }
                }
                batch.add(first);
                queue.drainTo(batch, BATCH - batch.size());
                if (anySkipped && queue.isEmpty()) {
                    queueSkipMarkers(); // everything queued before the skip is in this batch
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
