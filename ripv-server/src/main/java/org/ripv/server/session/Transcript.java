package org.ripv.server.session;

import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.messages.ConsoleEntry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The per-vehicle transcript: every console entry, appended as one JSON line to
 * {@code DATA/transcripts/<mailbox-dir>/YYYY-MM-DD[.N].jsonl} (UTC days; a file over the size
 * limit continues in {@code .1}, {@code .2}, ...), by one writer thread so that disk never holds
 * up the console. Files older than the kept number of days are deleted. When the writer cannot
 * keep up, entries are dropped and a line in the transcript says how many.
 */
public final class Transcript implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Transcript.class);
    /** Entries waiting for the writer before new ones are dropped (and counted). */
    static final int QUEUE = 100_000;
    /** The most entries one {@code ?history} returns. */
    public static final int MAX_HISTORY = 2000;
    private static final Pattern FILE = Pattern.compile("(\\d{4}-\\d{2}-\\d{2})(?:\\.(\\d{1,6}))?\\.jsonl");
    private static final int MAX_OPEN = 256;

    private final Path root;
    private final long maxFileBytes;
    private final int keepDays;
    private final BlockingQueue<Object> queue = new ArrayBlockingQueue<>(QUEUE);
    private final AtomicLong dropped = new AtomicLong();
    private final Map<String, Open> open = new LinkedHashMap<>(16, 0.75f, true);
    private final Thread writer;
    private volatile String droppedMailbox;
    private volatile boolean closed;
    private long lastPrune;

    private static final class Open {
        final Path file;
        final BufferedWriter out;
        final LocalDate day;
        long size;

        Open(Path file, BufferedWriter out, LocalDate day, long size) {
            this.file = file;
            this.out = out;
            this.day = day;
            this.size = size;
        }
    }

    /**
     * @param root         the transcripts directory
     * @param maxFileBytes a file grows to about this size before the next one starts
     * @param keepDays     files of days older than this are deleted
     */
    public Transcript(Path root, long maxFileBytes, int keepDays) throws IOException {
        this.root = root;
        this.maxFileBytes = Math.max(4096, maxFileBytes);
        this.keepDays = Math.max(1, keepDays);
        Files.createDirectories(root);
        this.writer = new Thread(this::writeLoop, "ripv-transcript-writer");
        writer.setDaemon(true);
        writer.start();
    }

    /** Queues an entry; never blocks. */
    public void append(ConsoleEntry e) {
        if (closed || !queue.offer(e)) {
            droppedMailbox = e.mailbox();
            dropped.incrementAndGet();
        }
    }

    /** Waits (briefly) until everything queued so far is on disk, so a reader sees it. */
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
        // Prune once at start, before this run writes anything, then hourly: what a run writes is
        // never pruned under it by a first sweep that happens to land after its first batch.
        lastPrune = System.currentTimeMillis();
        prune(LocalDate.now(ZoneOffset.UTC));
        List<Object> batch = new ArrayList<>();
        while (!closed || !queue.isEmpty()) {
            try {
                Object first = queue.poll(1, TimeUnit.SECONDS);
                if (first != null) {
                    batch.add(first);
                    queue.drainTo(batch, 4096);
                }
            } catch (InterruptedException e) {
                if (closed) {
                    queue.drainTo(batch);
                } else {
                    continue;
                }
            }
            long lost = dropped.getAndSet(0);
            if (lost > 0) {
                write(ConsoleEntry.line(droppedMailbox, "[transcript: " + lost + " entries dropped, the disk could not keep up]"));
            }
            List<CountDownLatch> waiting = new ArrayList<>();
            for (Object o : batch) {
                if (o instanceof ConsoleEntry e) {
                    write(e);
                } else if (o instanceof CountDownLatch l) {
                    waiting.add(l);
                }
            }
            batch.clear();
            for (Open o : open.values()) {
                try {
                    o.out.flush();
                } catch (IOException e) {
                    log.warn("transcript {}: {}", o.file, e.toString());
                }
            }
            waiting.forEach(CountDownLatch::countDown);
            long now = System.currentTimeMillis();
            if (now - lastPrune > Duration.ofHours(1).toMillis()) {
                lastPrune = now;
                prune(LocalDate.now(ZoneOffset.UTC));
            }
        }
        open.values().forEach(o -> closeQuietly(o));
        open.clear();
    }

    private void write(ConsoleEntry e) {
        String line = Entries.toJson(e) + "\n";
        byte[] bytes = line.getBytes(StandardCharsets.UTF_8);
        try {
            Open o = fileFor(e.mailbox(), LocalDate.ofInstant(Instant.ofEpochMilli(e.time()), ZoneOffset.UTC), bytes.length);
            o.out.write(line);
            o.size += bytes.length;
        } catch (IOException | RuntimeException x) {
            log.warn("transcript of {}: could not write: {}", e.mailbox(), x.toString());
        }
    }

    /** The open file for the mailbox and day with room for {@code need} more bytes. */
    private Open fileFor(String mailbox, LocalDate day, int need) throws IOException {
        Open o = open.get(mailbox);
        if (o != null && o.day.equals(day) && o.size + need <= maxFileBytes) {
            return o;
        }
        if (o != null) {
            closeQuietly(o);
            open.remove(mailbox);
        }
        Path dir = dirOf(mailbox);
        Files.createDirectories(dir);
        Path file = dir.resolve(day + ".jsonl");
        int n = 0;
        while (Files.exists(file) && Files.size(file) + need > maxFileBytes) {
            n++;
            file = dir.resolve(day + "." + n + ".jsonl");
        }
        long size = Files.exists(file) ? Files.size(file) : 0;
        BufferedWriter w = new BufferedWriter(new OutputStreamWriter(Files.newOutputStream(file, StandardOpenOption.CREATE,
                StandardOpenOption.APPEND, StandardOpenOption.WRITE), StandardCharsets.UTF_8), 16 * 1024);
        Open fresh = new Open(file, w, day, size);
        open.put(mailbox, fresh);
        if (open.size() > MAX_OPEN) {
            var eldest = open.entrySet().iterator().next();
            closeQuietly(eldest.getValue());
            open.remove(eldest.getKey());
        }
        return fresh;
    }

    private static void closeQuietly(Open o) {
        try {
            o.out.close();
        } catch (IOException ignored) {
            // the next write reopens
        }
    }

    /** Deletes transcript files of days more than keepDays before {@code today}. */
    void prune(LocalDate today) {
        LocalDate oldest = today.minusDays(keepDays);
        try (DirectoryStream<Path> dirs = Files.newDirectoryStream(root)) {
            for (Path dir : dirs) {
                if (!Files.isDirectory(dir)) {
                    continue;
                }
                for (Path f : files(dir)) {
                    if (day(f).isBefore(oldest)) {
                        Open o = open.values().stream().filter(x -> x.file.equals(f)).findFirst().orElse(null);
                        if (o == null) {
                            Files.deleteIfExists(f);
                            log.info("transcript {} is older than {} days; deleted", f, keepDays);
                        }
                    }
                }
            }
        } catch (IOException e) {
            log.warn("transcript pruning failed: {}", e.toString());
        }
    }

    /** The directory of a MailBox's files: a readable part of its address and a hash of the whole. */
    public Path dirOf(String mailbox) {
        String readable = mailbox.replaceAll("[^A-Za-z0-9._-]+", "_");
        if (readable.length() > 60) {
            readable = readable.substring(readable.length() - 60);
        }
        try {
            byte[] h = MessageDigest.getInstance("SHA-256").digest(mailbox.getBytes(StandardCharsets.UTF_8));
            return root.resolve(readable + "-" + HexFormat.of().formatHex(h, 0, 4));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A MailBox's transcript files, oldest first. */
    List<Path> files(Path dir) throws IOException {
        List<Path> out = new ArrayList<>();
        if (!Files.isDirectory(dir)) {
            return out;
        }
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir, "*.jsonl")) {
            for (Path p : s) {
                if (FILE.matcher(p.getFileName().toString()).matches()) {
                    out.add(p);
                }
            }
        }
        out.sort(Comparator.comparing(Transcript::day).thenComparing(Transcript::index));
        return out;
    }

    private static LocalDate day(Path p) {
        Matcher m = FILE.matcher(p.getFileName().toString());
        return m.matches() ? LocalDate.parse(m.group(1)) : LocalDate.MIN;
    }

    private static int index(Path p) {
        Matcher m = FILE.matcher(p.getFileName().toString());
        return m.matches() && m.group(2) != null ? Integer.parseInt(m.group(2)) : 0;
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
        ArrayDeque<ConsoleEntry> kept = new ArrayDeque<>();
        boolean more = false;
        int bad = 0;
        LocalDate sinceDay = since == null ? LocalDate.MIN : LocalDate.ofInstant(since, ZoneOffset.UTC);
        for (Path f : files(dirOf(mailbox))) {
            if (day(f).isBefore(sinceDay)) {
                continue;
            }
            try (BufferedReader r = Files.newBufferedReader(f, StandardCharsets.UTF_8)) {
                String line;
                while ((line = r.readLine()) != null) {
                    ConsoleEntry e;
                    try {
                        e = Entries.fromJson(line);
                    } catch (IllegalArgumentException | NullPointerException x) {
                        bad++;
                        continue;
                    }
                    if (!e.mailbox().equals(mailbox) || since != null && e.time() < since.toEpochMilli()) {
                        continue;
                    }
                    if (kept.size() == limit) {
                        more = true;
                        if (last <= 0) {
                            return new Page(List.copyOf(kept), true, bad);
                        }
                        kept.removeFirst();
                    }
                    kept.addLast(e);
                }
            } catch (java.nio.charset.MalformedInputException x) {
                bad++;
            }
        }
        return new Page(List.copyOf(kept), more, bad);
    }

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
