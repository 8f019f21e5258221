package org.ripv.service;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import org.ripv.messages.ConsoleEntry;
import org.ripv.retry.Backoff;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Carries a service's console entries to the server on a thread of its own, batched, so that a
 * vehicle printing fast never waits on RMI. A batch the server did not take (it is restarting, or
 * a standby is taking over) is offered again until it is, so nothing said in between is lost. The
 * queue is bounded in entries and in characters (a link may allow lines of a megabyte): when the
 * server cannot keep up, or stays away, entries are skipped and one "N lines skipped" line per
 * MailBox says so, in place (after the entries queued before the skip), once there is room. A batch
 * carries at most {@link #BATCH_CHARS} characters, so one RMI call never needs more than that.
 */
final class ConsolePublisher {
    private static final Logger log = LoggerFactory.getLogger(ConsolePublisher.class);
    private static final int BATCH = 500;
    /** What an entry costs besides its text (the record, its strings' headers, the MailBox is shared). */
    static final int ENTRY_OVERHEAD = 128;
    /** The most characters (with {@link #ENTRY_OVERHEAD} per entry) waiting at once. */
    static final long MAX_QUEUED_CHARS = 4L * 1024 * 1024;
    /** The most characters in one batch (a single bigger entry goes alone). */
    static final long BATCH_CHARS = 1024 * 1024;
    /** How long one batch is offered to a server that keeps failing before it is counted as skipped. */
    static final long GIVE_UP_MILLIS = 5 * 60_000;

    private final BlockingQueue<ConsoleEntry> queue;
    private final AtomicLong queuedChars = new AtomicLong();
    private final Supplier<ReplySink> sink;
    private final ConcurrentHashMap<String, AtomicLong> skipped =
            new ConcurrentHashMap<>();
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
        if (!offer(entry)) {
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
            if (n > 0 && !offer(ConsoleEntry.line(e.getKey(), "[" + n + " lines skipped: the server could not keep up]"))) {
                e.getValue().addAndGet(n);
                anySkipped = true;
            }
        }
    }

    private static long cost(ConsoleEntry e) {
        return e.text().length() + e.user().length() + ENTRY_OVERHEAD;
    }

    /** Queues the entry if both the count and the characters allow it. */
    private boolean offer(ConsoleEntry e) {
        long c = cost(e);
        if (queuedChars.addAndGet(c) > MAX_QUEUED_CHARS) {
            queuedChars.addAndGet(-c);
            return false;
        }
        if (!queue.offer(e)) {
            queuedChars.addAndGet(-c);
            return false;
        }
        return true;
    }

    /** Moves queued entries into the batch, up to {@link #BATCH} entries and {@link #BATCH_CHARS} characters. */
    private void drain(List<ConsoleEntry> batch) {
        long chars = 0;
        for (ConsoleEntry e : batch) {
            chars += cost(e);
        }
        while (batch.size() < BATCH) {
            ConsoleEntry next = queue.peek();
            if (next == null || !batch.isEmpty() && chars + cost(next) > BATCH_CHARS) {
                return;
            }
            queue.poll(); // only this thread takes from the queue
            queuedChars.addAndGet(-cost(next));
            chars += cost(next);
            batch.add(next);
        }
    }

    void stop() {
        thread.interrupt();
    }

    private void run() {
        List<ConsoleEntry> batch = new ArrayList<>(BATCH);
        long failingSince = 0;
        Backoff backoff = new Backoff(Duration.ofMillis(100), Duration.ofMillis(2000));
        try {
            while (!Thread.currentThread().isInterrupted()) {
                if (batch.isEmpty()) {
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
                    queuedChars.addAndGet(-cost(first));
                    batch.add(first);
                }
                drain(batch);
                if (anySkipped && queue.isEmpty()) {
                    queueSkipMarkers(); // everything queued before the skip is in this batch
                    drain(batch);
                }
                try {
                    sink.get().console(List.copyOf(batch));
                    batch.clear();
                    failingSince = 0;
                    backoff.reset();
                } catch (Exception e) {
                    // The server restarted, or a standby is taking over: keep the batch and try again,
                    // so what the vehicle said meanwhile reaches the transcript (the queue behind it
                    // stays bounded and skips, with a marker, if this lasts). Give up on a batch only
                    // after GIVE_UP_MILLIS, so that one the server keeps refusing cannot stop the console.
                    long now = System.nanoTime();
                    if (failingSince == 0) {
                        failingSince = now;
                    } else if (now - failingSince > GIVE_UP_MILLIS * 1_000_000L) {
                        log.warn("dropped {} console entries after {} s of failures: {}", batch.size(), GIVE_UP_MILLIS / 1000,
                                e.toString());
                        skipped.computeIfAbsent(batch.get(0).mailbox(), m -> new AtomicLong()).addAndGet(batch.size());
                        anySkipped = true;
                        batch.clear();
                        failingSince = 0;
                        backoff.reset();
                        continue;
                    }
                    long wait = backoff.nextMillis();
                    log.debug("console entries not delivered ({}); trying again in {} ms", e.toString(), wait);
                    Thread.sleep(wait);
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
