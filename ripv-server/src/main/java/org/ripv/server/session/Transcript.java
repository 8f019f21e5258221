package org.ripv.server.session;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.ConsoleEntry;
import org.ripv.retry.Backoff;
import org.ripv.server.store.BatchWriter;
import org.ripv.server.store.EmbeddedStateStore;
import org.ripv.server.store.StateStore;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The per-vehicle transcript: every console entry, as one JSON line, kept in the server's
 * {@link StateStore} (embedded: {@code DATA/transcripts/<mailbox-dir>/YYYY-MM-DD[.N].jsonl}, UTC
 * days, a file over the size limit continued in {@code .1}, {@code .2}, ...), by one writer thread
 * in batches ({@link BatchWriter}) so that neither disk nor database holds up the console. Entries older than the kept
 * number of days are deleted. When the writer cannot keep up, entries are dropped and a line in
 * the transcript says how many.
 */
public final class Transcript implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Transcript.class);
    /** Entries waiting for the writer before new ones are dropped (and counted). */
    static final int QUEUE = 100_000;
    /** The most entries one {@code ?history} returns. */
    public static final int MAX_HISTORY = 2000;

    private final Path root;
    private final StateStore store;
    private final boolean ownsStore;
    private final int keepDays;
    private final BatchWriter<ConsoleEntry> writer;
    private volatile String droppedMailbox;
    private long lastPrune;
    /** The most bytes one MailBox's transcript takes in one UTC day; 0: no cap. */
    private final long dayCap;
    /** What each MailBox wrote today, and what was cut: the writer thread's alone. */
    private final Map<String, DayUse> today = new HashMap<>();

    private static final class DayUse {
        LocalDate day;
        long bytes;
        long cutLines;
        long cutBytes;
    }

    /**
     * A transcript in files of its own under {@code root} (the embedded store's layout).
     *
     * @param root         the transcripts directory
     * @param maxFileBytes a file grows to about this size before the next one starts
     * @param keepDays     files of days older than this are deleted
     */
    public Transcript(Path root, long maxFileBytes, int keepDays) throws IOException {
        this(root, new EmbeddedStateStore(EmbeddedStateStore.Layout.in(root).withTranscripts(root), maxFileBytes), true, keepDays);
    }

    /**
     * A transcript kept in the server's store.
     *
     * @param root     the transcripts directory, which also holds each MailBox's {@code state.json}
     * @param store    where entries are kept (not closed by this transcript)
     * @param keepDays entries of days older than this are deleted
     */
    public Transcript(Path root, StateStore store, int keepDays) throws IOException {
        this(root, store, false, keepDays, 0);
    }

    /**
     * As {@link #Transcript(Path, StateStore, int)}, keeping at most {@code dayCap} bytes of one
     * MailBox's entries a day: a link printing at its rate limit for a day wrote ~5 GB (issue 23,
     * item 14). The first entry over the cap is replaced by a marker line saying so; the next day
     * starts with a line saying how much was cut.
     */
    public Transcript(Path root, StateStore store, int keepDays, long dayCap) throws IOException {
        this(root, store, false, keepDays, dayCap);
    }

    private Transcript(Path root, StateStore store, boolean ownsStore, int keepDays) throws IOException {
        this(root, store, ownsStore, keepDays, 0);
    }

    private Transcript(Path root, StateStore store, boolean ownsStore, int keepDays, long dayCap) throws IOException {
        this.root = root;
        this.dayCap = dayCap;
        this.store = store;
        this.ownsStore = ownsStore;
        this.keepDays = Math.max(1, keepDays);
        PrivateFiles.createDirectories(root); // owner-only whatever the umask (issue 23, item 13)
        this.writer = new BatchWriter<>("ripv-transcript-writer", QUEUE, 4096, new BatchWriter.Sink<>() {
            @Override
            public void started() {
                // Prune once at start, before this run writes anything, then hourly: what a run writes is
                // never pruned under it by a first sweep that happens to land after its first batch.
                lastPrune = System.currentTimeMillis();
                prune(LocalDate.now(ZoneOffset.UTC));
            }

            @Override
            public void write(List<ConsoleEntry> batch, long dropped) {
                store(lines(batch, dropped));
            }

            @Override
            public void afterRound() {
                long now = System.currentTimeMillis();
                if (now - lastPrune > Duration.ofHours(1).toMillis()) {
                    lastPrune = now;
                    prune(LocalDate.now(ZoneOffset.UTC));
                }
            }
        });
    }

    /** Queues an entry; never blocks. */
    public void append(ConsoleEntry e) {
        if (!writer.offer(e)) {
            droppedMailbox = e.mailbox();
        }
    }

    /** Waits (briefly) until everything queued so far is on disk, so a reader sees it. */
    public void sync() {
        writer.sync();
    }

    private List<StateStore.TranscriptLine> lines(List<ConsoleEntry> batch, long dropped) {
        List<StateStore.TranscriptLine> lines = new ArrayList<>(batch.size() + 1);
        if (dropped > 0) {
            String mailbox = droppedMailbox; // null only if the count was read between a drop and its naming
            if (mailbox != null) {
                lines.add(line(ConsoleEntry.line(mailbox, "[transcript: " + dropped + " entries dropped, the disk could not keep up]")));
            } else {
                log.warn("transcript: {} entries dropped, the disk could not keep up", dropped);
            }
        }
        for (ConsoleEntry e : batch) {
            try {
                StateStore.TranscriptLine l = line(e);
                if (withinCap(e, l, lines)) {
                    lines.add(l);
                }
            } catch (RuntimeException x) {
                log.warn("transcript of {}: could not write: {}", e.mailbox(), x.toString());
            }
        }
        return lines;
    }

    /** Counts an entry against its MailBox's day; false when it is over the cap (and a marker was added if it is the first). */
    private boolean withinCap(ConsoleEntry e, StateStore.TranscriptLine l, List<StateStore.TranscriptLine> lines) {
        if (dayCap <= 0) {
            return true;
        }
        LocalDate day = LocalDate.ofInstant(Instant.ofEpochMilli(e.time()), ZoneOffset.UTC);
        DayUse u = today.computeIfAbsent(e.mailbox(), k -> new DayUse());
        if (!day.equals(u.day)) {
            if (u.cutLines > 0) {
                lines.add(line(ConsoleEntry.line(e.mailbox(), "[transcript: " + u.cutLines + " entries (" + u.cutBytes
                        + " bytes) of " + u.day + " were not kept: over the cap of " + dayCap + " bytes a day]")));
            }
            if (today.size() > 10_000) {
                today.values().removeIf(x -> x.day != null && x.day.isBefore(day.minusDays(1)));
            }
            u.day = day;
            u.bytes = 0;
            u.cutLines = 0;
            u.cutBytes = 0;
        }
        long bytes = l.json().length() + 1L;
        if (u.bytes + bytes <= dayCap) {
            u.bytes += bytes;
            return true;
        }
        if (u.cutLines == 0) {
            lines.add(line(ConsoleEntry.line(e.mailbox(), "[transcript: " + e.mailbox() + " reached the cap of " + dayCap
                    + " bytes for " + day + "; its further entries of the day are not kept (the live console still shows them)]")));
        }
        u.cutLines++;
        u.cutBytes += bytes;
        return false;
    }

    /** Why entries are not being kept now (the disk is full), or null. */
    public String trouble() {
        return store.transcriptTrouble();
    }

    private static StateStore.TranscriptLine line(ConsoleEntry e) {
        return new StateStore.TranscriptLine(e.mailbox(), e.time(), Entries.toJson(e));
    }

    /** How long a failing store (a database restarting or failing over) is retried before a batch is given up. */
    static final Duration RETRY_FOR = Duration.ofSeconds(30);

    /**
     * Stores a batch. A store that fails is tried again, waiting 0.5 s, 1 s, 2 s ... up to
     * {@link #RETRY_FOR} in all, while new entries wait in the queue; only then (or when closing)
     * is the batch given up, and the log says how many entries were lost.
     */
    private void store(List<StateStore.TranscriptLine> lines) {
        if (lines.isEmpty()) {
            return;
        }
        long giveUp = System.nanoTime() + RETRY_FOR.toNanos();
        Backoff backoff = new Backoff(Duration.ofMillis(500), Duration.ofMillis(8000));
        for (int attempt = 1; ; attempt++) {
            try {
                store.appendTranscript(lines);
                if (attempt > 1) {
                    log.info("transcript: stored again after {} attempts", attempt);
                }
                return;
            } catch (IOException | RuntimeException x) {
                long wait = backoff.nextMillis();
                if (writer.isClosed() || System.nanoTime() + wait * 1_000_000 > giveUp) {
                    log.warn("transcript: could not store {} entries, they are lost: {}", lines.size(), x.toString());
                    return;
                }
                if (attempt == 1) {
                    log.warn("transcript: could not store {} entries ({}); trying again for up to {} s", lines.size(),
                            x.toString(), RETRY_FOR.toSeconds());
                }
                try {
                    Thread.sleep(wait);
                } catch (InterruptedException ie) {
                    // close(): one last try
                    try {
                        store.appendTranscript(lines);
                    } catch (IOException | RuntimeException last) {
                        log.warn("transcript: could not store {} entries, they are lost: {}", lines.size(), last.toString());
                    }
                    return;
                }
            }
        }
    }

    /** Deletes transcript entries of days more than keepDays before {@code today}. */
    void prune(LocalDate today) {
        try {
            store.pruneTranscripts(today.minusDays(keepDays));
        } catch (IOException | RuntimeException e) {
            log.warn("transcript pruning failed: {}", e.toString());
        }
    }

    /** The directory of a MailBox's files: a readable part of its address and a hash of the whole. */
    public Path dirOf(String mailbox) {
        return EmbeddedStateStore.transcriptDir(root, mailbox);
    }

    /** A MailBox's transcript files, oldest first (embedded store). */
    List<Path> files(Path dir) throws IOException {
        return EmbeddedStateStore.transcriptFiles(dir);
    }

    /** What {@link #history} found: the entries, oldest first, and whether some were left out. */
    public record Page(List<ConsoleEntry> entries, boolean more, int unreadable) {}

    /**
     * A MailBox's transcript: entries at or after {@code since} (null: from the start), the last
     * {@code last} of them (0: the first {@link #MAX_HISTORY}), never more than MAX_HISTORY.
     */
    public Page history(String mailbox, Instant since, int last) throws IOException {
        sync();
        int limit = last > 0 ? Math.min(last, MAX_HISTORY) : MAX_HISTORY;
        StateStore.TranscriptPage page = store.readTranscript(mailbox, since == null ? 0 : since.toEpochMilli(), limit, last > 0);
        List<ConsoleEntry> kept = new ArrayList<>(page.lines().size());
        int bad = page.unreadable();
        for (String line : page.lines()) {
            try {
                ConsoleEntry e = Entries.fromJson(line);
                if (e.mailbox().equals(mailbox)) {
                    kept.add(e);
                }
            } catch (IllegalArgumentException | NullPointerException x) {
                bad++;
            }
        }
        return new Page(List.copyOf(kept), page.more(), bad);
    }

    @Override
    public void close() {
        writer.close();
        if (ownsStore) {
            store.close();
        }
    }
}
