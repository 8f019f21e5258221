package org.ripv.server.store;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.ripv.files.PrivateFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The default store: owner-only files in the data directory, in the layout earlier versions
 * wrote, so an existing data directory keeps working.
 * <pre>
 * DATA/transcripts/MAILBOX-DIR/YYYY-MM-DD[.N].jsonl   transcripts (one JSON line per entry)
 * DATA/workflows/queues/KEY.properties                 a MailBox's workflow queue
 * DATA/workflows/fetched/KEY.properties                files its workflows fetched
 * DATA/workflows/receipts/KEY/NAME.txt                 receipts, the newest kept
 * DATA/notify/subscriptions.jsonl                      notification subscriptions
 * DATA/audit/YYYY-MM-DD.log                            the audit trail: TIME LEVEL event key=value ...
 * DATA/surfacings/KEY.jsonl                            call records, one JSON line per surfacing
 * DATA/surfacings/KEY.mailbox                          the MailBox address those records are of (records kept
 *                                                      before it was written: found from the transcripts, then written)
 * </pre>
 * Documents are written whole through a temporary file and an atomic move. Directories are made
 * when first written.
 *
 * <p>Longer than 400 lines for one job: it is {@link StateStore} on files, one short method per kind of
 * record, all written the one way described above.
 */
public final class EmbeddedStateStore implements StateStore {
    private static final Logger log = LoggerFactory.getLogger(EmbeddedStateStore.class);

    /**
     * Where each kind of state lives; {@link #in} gives the standard layout of a data directory.
     */
    public record Layout(Path transcripts, Path queues, Path fetched, Path receipts, Path subscriptions, Path audit) {
        public static Layout in(Path dataDir) {
            Path wf = dataDir.resolve("workflows");
            return new Layout(dataDir.resolve("transcripts"), wf.resolve("queues"), wf.resolve("fetched"),
                    wf.resolve("receipts"), dataDir.resolve("notify").resolve("subscriptions.jsonl"), dataDir.resolve("audit"));
        }

        public Layout withTranscripts(Path dir) {
            return new Layout(dir, queues, fetched, receipts, subscriptions, audit);
        }

        public Layout withQueues(Path dir) {
            return new Layout(transcripts, dir, fetched, receipts, subscriptions, audit);
        }

        public Layout withReceipts(Path dir) {
            return new Layout(transcripts, queues, fetched, dir, subscriptions, audit);
        }
    }

    private final Layout layout;
    private final FileTranscripts transcripts;
    private final Object auditLock = new Object();
    private final Object surfacingLock = new Object();

    /**
     * @param layout              where each kind of state lives
     * @param transcriptFileBytes a transcript file grows to about this size before the next one starts
     */
    public EmbeddedStateStore(Layout layout, long transcriptFileBytes) {
        this.layout = layout;
        this.transcripts = new FileTranscripts(layout.transcripts(), transcriptFileBytes);
        // What an older version left readable by others: owner-only from this start on.
        // Only folders this layout owns: a queue or receipt folder given alone (WorkflowQueues(dir)) has a
        // parent that is not RIPV's, and tightening it walked a whole temp folder owner-only.
        for (Path p : new Path[] {layout.transcripts(), ownParent(layout.queues(), "workflows"), layout.queues(),
                layout.fetched(), layout.receipts(), ownParent(layout.subscriptions(), "notify"), layout.audit()}) {
            try {
                DataFiles.tighten(p);
            } catch (IOException | RuntimeException e) {
                log.warn("could not make {} owner-only: {}", p, e.toString());
            }
        }
    }

    /** {@code p}'s parent when it is the data directory's own folder of that name, else {@code p} itself. */
    private static Path ownParent(Path p, String name) {
        Path parent = p.toAbsolutePath().getParent();
        return parent != null && parent.getFileName() != null && parent.getFileName().toString().equals(name) ? parent : p;
    }

    /** The standard layout of a data directory. */
    public EmbeddedStateStore(Path dataDir, long transcriptFileBytes) {
        this(Layout.in(dataDir), transcriptFileBytes);
    }

    public Layout layout() {
        return layout;
    }

    /** The directory of a MailBox's transcript files under a transcripts root. */
    public static Path transcriptDir(Path root, String mailbox) {
        return FileTranscripts.dirOf(root, mailbox);
    }

    /** A MailBox's transcript files in {@code dir}, oldest first. */
    public static List<Path> transcriptFiles(Path dir) throws IOException {
        return FileTranscripts.files(dir);
    }

    // ---- call records ----

    /** Beside the transcripts: {@code DATA/surfacings}. */
    private Path surfacings() {
        return layout.transcripts().toAbsolutePath().resolveSibling("surfacings");
    }

    @Override
    public void appendSurfacing(String mailbox, long time, String json, int keep) throws IOException {
        if (json.indexOf('\n') >= 0 || json.indexOf('\r') >= 0) {
            throw new IllegalArgumentException("a call record is one line");
        }
        synchronized (surfacingLock) {
            Path f = DataFiles.directory(surfacings()).resolve(DataFiles.key(mailbox) + ".jsonl");
            if (!Files.exists(f)) {
                DataFiles.create(f, "");
            }
            Path name = f.resolveSibling(DataFiles.key(mailbox) + ".mailbox");
            if (!Files.exists(name)) { // the file's key cannot be read back into the address
                DataFiles.write(name, mailbox);
            }
            try (BufferedWriter w = Files.newBufferedWriter(f, StandardCharsets.UTF_8, StandardOpenOption.APPEND)) {
                w.write(json);
                w.write('\n');
            }
            // Append-only until twice the records kept, then the newest are written anew: a vehicle
            // calling for years costs at most 2 x keep lines.
            List<String> all = readLast(f, 2 * keep + 1);
            if (all.size() > 2 * keep) {
                DataFiles.write(f, String.join("\n", all.subList(all.size() - keep, all.size())) + "\n");
            }
        }
    }

    @Override
    public List<String> lastSurfacings(String mailbox, int n) throws IOException {
        synchronized (surfacingLock) {
            Path f = surfacings().resolve(DataFiles.key(mailbox) + ".jsonl");
            return Files.exists(f) ? readLast(f, n) : List.of();
        }
    }

    @Override
    public List<String> surfacingMailboxes() throws IOException {
        synchronized (surfacingLock) {
            List<String> out = new ArrayList<>();
            if (!Files.isDirectory(surfacings())) {
                return out;
            }
            Set<String> unnamed = new TreeSet<>(); // records kept before KEY.mailbox was written beside them
            try (Stream<Path> files = Files.list(surfacings())) {
                for (Path p : (Iterable<Path>) files::iterator) {
                    String file = p.getFileName().toString();
                    if (file.endsWith(".mailbox") && Files.size(p) <= 1000) {
                        out.add(Files.readString(p, StandardCharsets.UTF_8).strip());
                    } else if (file.endsWith(".jsonl") && !Files.exists(p.resolveSibling(stem(file) + ".mailbox"))) {
                        unnamed.add(stem(file));
                    }
                }
            }
            if (!unnamed.isEmpty()) {
                Map<String, String> owners = OlderCallRecords.owners(layout.transcripts(), unnamed);
                for (Map.Entry<String, String> o : owners.entrySet()) {
                    out.add(o.getValue());
                    try { // named from now on: the next start need not look
                        DataFiles.write(surfacings().resolve(o.getKey() + ".mailbox"), o.getValue());
                    } catch (IOException e) {
                        log.warn("could not name the call records {}.jsonl: {}", o.getKey(), e.toString());
                    }
                }
                unnamed.removeAll(owners.keySet());
                if (!unnamed.isEmpty()) {
                    log.warn("no transcript names the MailBox of the call records {} in {}: each is read again from its vehicle's next call",
                            unnamed.stream().map(k -> k + ".jsonl").toList(), surfacings());
                }
            }
            return out;
        }
    }

    private static String stem(String file) {
        return file.substring(0, file.lastIndexOf('.'));
    }

    /** The last {@code n} non-empty lines of a file, holding no more than n in memory. */
    private static List<String> readLast(Path f, int n) throws IOException {
        ArrayDeque<String> last = new ArrayDeque<>();
        try (Stream<String> lines = Files.lines(f, StandardCharsets.UTF_8)) {
            lines.filter(l -> !l.isBlank()).forEach(l -> {
                if (n > 0) {
                    if (last.size() == n) {
                        last.removeFirst();
                    }
                    last.addLast(l);
                }
            });
        }
        return new ArrayList<>(last);
    }

    // ---- transcripts ----

    @Override
    public String transcriptTrouble() {
        return transcripts.trouble();
    }

    @Override
    public void appendTranscript(List<TranscriptLine> lines) throws IOException {
        transcripts.append(lines);
    }

    @Override
    public TranscriptPage readTranscript(String mailbox, long sinceMillis, int limit, boolean newest) throws IOException {
        return transcripts.read(mailbox, sinceMillis, Math.max(1, limit), newest);
    }

    @Override
    public void pruneTranscripts(LocalDate oldestKept) throws IOException {
        transcripts.prune(oldestKept);
    }

    // ---- workflows ----

    @Override
    public void saveQueue(String mailbox, String document) throws IOException {
        DataFiles.write(DataFiles.directory(layout.queues()).resolve(DataFiles.key(mailbox) + ".properties"), document);
    }

    @Override
    public List<Stored> loadQueues() throws IOException {
        List<Stored> out = new ArrayList<>();
        if (!Files.isDirectory(layout.queues())) {
            return out;
        }
        try (DirectoryStream<Path> files = Files.newDirectoryStream(layout.queues(), "*.properties")) {
            for (Path f : files) {
                if (f.getFileName().toString().startsWith(".")) {
                    continue;
                }
                try {
                    out.add(new Stored(f.toString(), Files.readString(f, StandardCharsets.UTF_8)));
                } catch (IOException e) {
                    // One damaged file must not cost the other vehicles their queues; it stays for a person to look at.
                    log.error("could not read the workflow queue {}: {}; it is left as it is", f, e.toString());
                }
            }
        }
        return out;
    }

    /** Beside the MailBox's transcript files, where earlier versions kept it. */
    private Path vehicleStateFile(String mailbox) {
        return transcriptDir(layout.transcripts(), mailbox).resolve("state.json");
    }

    @Override
    public void saveVehicleState(String mailbox, String json) throws IOException {
        Path f = vehicleStateFile(mailbox);
        DataFiles.directory(f.getParent()); // owner-only whatever the umask (issue 23, item 13), as the transcript writer makes it
        DataFiles.write(f, json);
    }

    @Override
    public Optional<String> loadVehicleState(String mailbox) throws IOException {
        Path f = vehicleStateFile(mailbox);
        return Files.isRegularFile(f) ? Optional.of(Files.readString(f, StandardCharsets.UTF_8)) : Optional.empty();
    }

    @Override
    public void saveFetched(String mailbox, String document) throws IOException {
        DataFiles.write(DataFiles.directory(layout.fetched()).resolve(DataFiles.key(mailbox) + ".properties"), document);
    }

    @Override
    public Optional<String> loadFetched(String mailbox) throws IOException {
        Path f = layout.fetched().resolve(DataFiles.key(mailbox) + ".properties");
        return Files.exists(f) ? Optional.of(Files.readString(f, StandardCharsets.UTF_8)) : Optional.empty();
    }

    @Override
    public void saveReceipt(String mailbox, String name, String text, int keep) throws IOException {
        checkName(name);
        Path d = DataFiles.directory(DataFiles.directory(layout.receipts()).resolve(DataFiles.key(mailbox)));
        Path f = d.resolve(name);
        boolean first = !Files.exists(f);
        DataFiles.write(f, text);
        if (first) {
            List<Path> files = receiptFiles(d);
            for (Path old : files.subList(0, Math.max(0, files.size() - keep))) {
                Files.deleteIfExists(old);
            }
        }
    }

    private static void checkName(String name) {
        if (!name.matches("[A-Za-z0-9._-]{1,200}") || name.startsWith(".") || !name.endsWith(".txt")) {
            throw new IllegalArgumentException("not a receipt file name: " + name);
        }
    }

    private static List<Path> receiptFiles(Path d) throws IOException {
        try (Stream<Path> s = Files.list(d)) {
            return s.filter(p -> p.getFileName().toString().endsWith(".txt") && !p.getFileName().toString().startsWith("."))
                    .sorted().toList();
        }
    }

    @Override
    public List<String> lastReceipts(String mailbox, int n) throws IOException {
        Path d = layout.receipts().resolve(DataFiles.key(mailbox));
        if (!Files.isDirectory(d)) {
            return List.of();
        }
        List<Path> files = receiptFiles(d);
        List<String> out = new ArrayList<>();
        for (Path p : files.subList(Math.max(0, files.size() - Math.max(0, n)), files.size())) {
            out.add(Files.readString(p, StandardCharsets.UTF_8));
        }
        return out;
    }

    // ---- subscriptions ----

    @Override
    public void saveSubscriptions(String document) throws IOException {
        DataFiles.directory(layout.subscriptions().getParent());
        DataFiles.write(layout.subscriptions(), document);
    }

    @Override
    public Optional<Stored> loadSubscriptions() throws IOException {
        Path f = layout.subscriptions();
        return Files.isRegularFile(f) ? Optional.of(new Stored(f.toString(), Files.readString(f, StandardCharsets.UTF_8)))
                : Optional.empty();
    }

    // ---- audit trail ----

    @Override
    public void appendAudit(List<AuditRecord> records) throws IOException {
        synchronized (auditLock) {
            Path dir = DataFiles.directory(layout.audit());
            BufferedWriter out = null;
            LocalDate day = null;
            try {
                for (AuditRecord r : records) {
                    LocalDate d = LocalDate.ofInstant(Instant.ofEpochMilli(r.time()), ZoneOffset.UTC);
                    if (!d.equals(day)) {
                        if (out != null) {
                            out.close();
                        }
                        day = d;
                        out = new BufferedWriter(new OutputStreamWriter(PrivateFiles.newOutputStream(
                                dir.resolve(d + ".log"), StandardOpenOption.CREATE, StandardOpenOption.APPEND, StandardOpenOption.WRITE),
                                StandardCharsets.UTF_8));
                    }
                    out.write(Instant.ofEpochMilli(r.time()) + (r.warn() ? " WARN " : " INFO ") + oneLine(r.line()) + "\n");
                }
            } finally {
                if (out != null) {
                    out.close();
                }
            }
        }
    }

    private static String oneLine(String s) {
        return s.replace('\n', '_').replace('\r', '_');
    }

    @Override
    public List<AuditRecord> readAudit(long sinceMillis, int last) throws IOException {
        ArrayDeque<AuditRecord> kept = new ArrayDeque<>();
        if (!Files.isDirectory(layout.audit()) || last <= 0) {
            return List.of();
        }
        List<Path> files;
        try (Stream<Path> s = Files.list(layout.audit())) {
            files = s.filter(p -> p.getFileName().toString().matches("\\d{4}-\\d{2}-\\d{2}\\.log")).sorted().toList();
        }
        LocalDate sinceDay = LocalDate.ofInstant(Instant.ofEpochMilli(Math.max(0, sinceMillis)), ZoneOffset.UTC);
        for (Path f : files) {
            if (LocalDate.parse(f.getFileName().toString().substring(0, 10)).isBefore(sinceDay)) {
                continue;
            }
            for (String line : Files.readAllLines(f, StandardCharsets.UTF_8)) {
                String[] parts = line.split(" ", 3);
                if (parts.length < 3) {
                    continue;
                }
                long time;
                try {
                    time = Instant.parse(parts[0]).toEpochMilli();
                } catch (DateTimeParseException e) {
                    continue;
                }
                if (time < sinceMillis) {
                    continue;
                }
                kept.addLast(new AuditRecord(time, parts[1].equals("WARN"), parts[2]));
                if (kept.size() > last) {
                    kept.removeFirst();
                }
            }
        }
        return List.copyOf(kept);
    }

    @Override
    public String describe() {
        return "files in " + layout.transcripts().getParent().toAbsolutePath();
    }

    @Override
    public void close() {
        transcripts.close();
    }
}
