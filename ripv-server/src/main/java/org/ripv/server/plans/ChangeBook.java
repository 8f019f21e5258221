package org.ripv.server.plans;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Properties;
import java.util.TreeMap;
import java.util.function.Predicate;

import org.ripv.files.PrivateFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Every change, kept in {@code DATA/plans/changes.properties}: written whole through a temporary
 * file and an atomic move after every change of state, so a restart loses none. Bounded: a
 * MailBox keeps its newest {@value #MAX_PER_MAILBOX} changes (settled ones go first), the server
 * {@value #MAX_TOTAL}.
 */
final class ChangeBook {
    private static final Logger log = LoggerFactory.getLogger(ChangeBook.class);
    static final int MAX_PER_MAILBOX = 200;
    static final int MAX_TOTAL = 10_000;

    private final Path file;
    private final TreeMap<Long, Change> changes = new TreeMap<>();
    private long nextId = 1;

    ChangeBook(Path dir) throws IOException {
        PrivateFiles.createDirectories(dir);
        this.file = dir.resolve("changes.properties");
        if (Files.isRegularFile(file)) {
            load();
        }
    }

    synchronized long nextId() {
        return nextId++;
    }

    synchronized void put(Change c) throws IOException {
        changes.put(c.id(), c);
        nextId = Math.max(nextId, c.id() + 1);
        trim(c.mailbox());
        save();
    }

    synchronized List<Change> list(Predicate<Change> which) {
        return changes.values().stream().filter(which).toList();
    }

    synchronized List<Change> of(String mailbox) {
        return list(c -> c.mailbox().equals(mailbox));
    }

    private void trim(String mailbox) {
        List<Change> mine = new ArrayList<>(of(mailbox));
        if (mine.size() > MAX_PER_MAILBOX) {
            mine.sort(Comparator.comparing((Change c) -> !c.state().settled()).thenComparingLong(Change::id));
            for (int i = 0; i < mine.size() - MAX_PER_MAILBOX; i++) {
                changes.remove(mine.get(i).id());
            }
        }
        while (changes.size() > MAX_TOTAL) {
            changes.pollFirstEntry();
        }
    }

    private void save() throws IOException {
        Properties p = new Properties();
        p.setProperty("next", Long.toString(nextId));
        for (Change c : changes.values()) {
            String k = "c." + c.id() + ".";
            p.setProperty(k + "mailbox", c.mailbox());
            p.setProperty(k + "kind", c.kind().name());
            p.setProperty(k + "target", c.target());
            p.setProperty(k + "value", c.value());
            p.setProperty(k + "source", c.source());
            p.setProperty(k + "sha256", c.sha256());
            p.setProperty(k + "bytes", Long.toString(c.bytes()));
            p.setProperty(k + "user", c.user());
            p.setProperty(k + "state", c.state().name());
            p.setProperty(k + "times", c.queuedAt() + "," + c.sentAt() + "," + c.receivedAt() + "," + c.settledAt());
            p.setProperty(k + "surfacings", Integer.toString(c.surfacings()));
            p.setProperty(k + "staged", c.staged());
            p.setProperty(k + "workflow", Long.toString(c.workflowId()));
            p.setProperty(k + "detail", c.detail());
            StringBuilder w = new StringBuilder();
            for (double[] ll : c.waypoints()) {
                w.append(w.length() == 0 ? "" : ";").append(ll[0]).append(',').append(ll[1]);
            }
            p.setProperty(k + "waypoints", w.toString());
        }
        Path tmp = PrivateFiles.createTempFile(file.getParent(), "changes-", ".tmp");
        try {
            try (Writer out = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
                p.store(out, "RIPV plan changes (docs/plans.md)");
            }
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    private void load() throws IOException {
        Properties p = new Properties();
        try (Reader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            p.load(in);
        }
        for (String key : p.stringPropertyNames()) {
            if (!key.startsWith("c.") || !key.endsWith(".mailbox")) {
                continue;
            }
            String k = key.substring(0, key.length() - "mailbox".length());
            try {
                long id = Long.parseLong(k.substring(2, k.length() - 1));
                String[] t = p.getProperty(k + "times", "0,0,0,0").split(",");
                List<double[]> wpts = new ArrayList<>();
                for (String ll : p.getProperty(k + "waypoints", "").split(";")) {
                    if (!ll.isEmpty()) {
                        String[] x = ll.split(",");
                        wpts.add(new double[] {Double.parseDouble(x[0]), Double.parseDouble(x[1])});
                    }
                }
                changes.put(id, new Change(id, p.getProperty(key), Change.Kind.valueOf(p.getProperty(k + "kind")),
                        p.getProperty(k + "target", ""), p.getProperty(k + "value", ""), p.getProperty(k + "source", ""),
                        p.getProperty(k + "sha256", ""), Long.parseLong(p.getProperty(k + "bytes", "0")), p.getProperty(k + "user", ""),
                        Change.State.valueOf(p.getProperty(k + "state").toUpperCase(Locale.ROOT)), Long.parseLong(t[0]),
                        Long.parseLong(t[1]), Long.parseLong(t[2]), Long.parseLong(t[3]),
                        Integer.parseInt(p.getProperty(k + "surfacings", "0")), p.getProperty(k + "staged", ""),
                        Long.parseLong(p.getProperty(k + "workflow", "0")), p.getProperty(k + "detail", ""), wpts));
                nextId = Math.max(nextId, id + 1);
            } catch (RuntimeException e) {
                log.warn("{}: change {} is damaged and left out: {}", file, k, e.toString());
            }
        }
        try {
            nextId = Math.max(nextId, Long.parseLong(p.getProperty("next", "1")));
        } catch (NumberFormatException e) {
            log.warn("{}: 'next' is damaged", file);
        }
    }
}
