package org.ripv.server.store;

import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.nio.charset.MalformedInputException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.files.PrivateFiles;
import org.ripv.server.store.StateStore.TranscriptLine;
import org.ripv.server.store.StateStore.TranscriptPage;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Transcripts as files: {@code ROOT/<mailbox-dir>/YYYY-MM-DD[.N].jsonl}, one JSON line per entry
 * (UTC days; a file over the size limit continues in {@code .1}, {@code .2}, ...). Appends are
 * buffered per open file and flushed at the end of each batch; up to {@link #MAX_OPEN} files stay
 * open. Reads go to the files directly (what a batch wrote is flushed before it returns).
 */
final class FileTranscripts {
    private static final Logger log = LoggerFactory.getLogger(FileTranscripts.class);
    static final Pattern FILE = Pattern.compile("(\\d{4}-\\d{2}-\\d{2})(?:\\.(\\d{1,6}))?\\.jsonl");
    /** The entry's time in its JSON line (the first key the transcript writes). */
    private static final Pattern TIME = Pattern.compile("\"time\":\"([^\"]{1,40})\"");
    private static final int MAX_OPEN = 256;

    private final Path root;
    private final long maxFileBytes;
    private final Map<String, Open> open = new LinkedHashMap<>(16, 0.75f, true);

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

    FileTranscripts(Path root, long maxFileBytes) {
        this.root = root;
        this.maxFileBytes = Math.max(4096, maxFileBytes);
    }

    /** Why lines are not being written now (the disk is full), with since when and how many; null when they are. */
    private volatile String trouble;
    private long lostSince;
    private long lost;

    String trouble() {
        return trouble;
    }

    /**
     * Writes and flushes a batch; a line the disk refuses is skipped (retrying would repeat the
     * others). A refusing disk is a state, said once when it starts and once when it ends, and
     * shown by {@link #trouble} — not a warning per line (issue 23, item 14).
     */
    synchronized void append(List<TranscriptLine> lines) {
        for (TranscriptLine l : lines) {
            try {
                write(l);
                if (trouble != null) {
                    log.warn("transcripts are kept again; {} lines since {} were not", lost, Instant.ofEpochMilli(lostSince));
                    trouble = null;
                }
            } catch (IOException | RuntimeException x) {
                if (trouble == null) {
                    lostSince = System.currentTimeMillis();
                    lost = 0;
                    log.error("transcripts cannot be written ({}): console lines are not kept until there is room;"
                            + " the live console goes on", x.toString());
                }
                lost++;
                trouble = "transcripts are not being kept since " + Instant.ofEpochMilli(lostSince) + " (" + lost
                        + " lines lost): " + (x.getMessage() != null && x.getMessage().contains("No space left")
                        ? "the disk is full" : x.toString());
            }
        }
        for (Open o : open.values()) {
            try {
                o.out.flush();
            } catch (IOException e) {
                log.warn("transcript {}: {}", o.file, e.toString());
            }
        }
    }

    private void write(TranscriptLine l) throws IOException {
        String line = l.json() + "\n";
        byte[] bytes = line.getBytes(StandardCharsets.UTF_8);
        Open o = fileFor(l.mailbox(), LocalDate.ofInstant(Instant.ofEpochMilli(l.time()), ZoneOffset.UTC), bytes.length);
        o.out.write(line);
        o.size += bytes.length;
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
        Path dir = dirOf(root, mailbox);
        PrivateFiles.createDirectories(dir); // owner-only whatever the umask (issue 23, item 13)
        Path file = dir.resolve(day + ".jsonl");
        int n = 0;
        while (Files.exists(file) && Files.size(file) + need > maxFileBytes) {
            n++;
            file = dir.resolve(day + "." + n + ".jsonl");
        }
        long size = Files.exists(file) ? Files.size(file) : 0;
        BufferedWriter w = new BufferedWriter(new OutputStreamWriter(PrivateFiles.newOutputStream(file, StandardOpenOption.CREATE,
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

    /** Deletes files of days before {@code oldestKept}, except one open for writing. */
    synchronized void prune(LocalDate oldestKept) throws IOException {
        if (!Files.isDirectory(root)) {
            return;
        }
        try (DirectoryStream<Path> dirs = Files.newDirectoryStream(root)) {
            for (Path dir : dirs) {
                if (!Files.isDirectory(dir)) {
                    continue;
                }
                for (Path f : files(dir)) {
                    if (day(f).isBefore(oldestKept) && open.values().stream().noneMatch(x -> x.file.equals(f))) {
                        Files.deleteIfExists(f);
                        log.info("transcript {} is from before {}; deleted", f, oldestKept);
                    }
                }
            }
        }
    }

    TranscriptPage read(String mailbox, long sinceMillis, int limit, boolean newest) throws IOException {
        ArrayDeque<String> kept = new ArrayDeque<>();
        boolean more = false;
        int bad = 0;
        LocalDate sinceDay = sinceMillis <= 0 ? LocalDate.MIN : LocalDate.ofInstant(Instant.ofEpochMilli(sinceMillis), ZoneOffset.UTC);
        for (Path f : files(dirOf(root, mailbox))) {
            if (day(f).isBefore(sinceDay)) {
                continue;
            }
            try (BufferedReader r = Files.newBufferedReader(f, StandardCharsets.UTF_8)) {
                String line;
                while ((line = r.readLine()) != null) {
                    long time = timeOf(line);
                    if (time == Long.MIN_VALUE) {
                        bad++;
                        continue;
                    }
                    if (time < sinceMillis) {
                        continue;
                    }
                    if (kept.size() == limit) {
                        more = true;
                        if (!newest) {
                            return new TranscriptPage(List.copyOf(kept), true, bad);
                        }
                        kept.removeFirst();
                    }
                    kept.addLast(line);
                }
            } catch (MalformedInputException x) {
                bad++;
            }
        }
        return new TranscriptPage(List.copyOf(kept), more, bad);
    }

    /** The entry's time, or Long.MIN_VALUE for a line that is not one of ours. */
    private static long timeOf(String line) {
        if (!line.startsWith("{")) {
            return Long.MIN_VALUE;
        }
        Matcher m = TIME.matcher(line);
        if (!m.find()) {
            return Long.MIN_VALUE;
        }
        try {
            return Instant.parse(m.group(1)).toEpochMilli();
        } catch (DateTimeParseException e) {
            return Long.MIN_VALUE;
        }
    }

    synchronized void close() {
        open.values().forEach(FileTranscripts::closeQuietly);
        open.clear();
    }

    /** The directory of a MailBox's files: a readable part of its address and a hash of the whole. */
    static Path dirOf(Path root, String mailbox) {
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
    static List<Path> files(Path dir) throws IOException {
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
        out.sort(Comparator.comparing(FileTranscripts::day).thenComparing(FileTranscripts::index));
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
}
