package org.ripv.server.workflow;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/** The receipts of every run, one owner-only text file each in {@code DATA/workflows/receipts/MAILBOX-KEY/}. */
final class Receipts {
    private final Path dir;

    Receipts(Path dir) throws IOException {
        this.dir = AtomicFiles.directory(dir);
    }

    /** The most receipts kept per MailBox; older ones are deleted as new runs start. */
    static final int KEEP = 1000;

    void write(Receipt r) throws IOException {
        Path d = AtomicFiles.directory(dir.resolve(AtomicFiles.key(r.mailbox)));
        Path f = d.resolve(r.fileName());
        boolean first = !Files.exists(f);
        AtomicFiles.write(f, r.render());
        if (first) {
            prune(d);
        }
    }

    /** Keeps the newest {@link #KEEP} receipts (an every-call workflow leaves one per call). */
    private static void prune(Path d) throws IOException {
        List<Path> files;
        try (Stream<Path> s = Files.list(d)) {
            files = s.filter(p -> p.getFileName().toString().endsWith(".txt") && !p.getFileName().toString().startsWith("."))
                    .sorted().toList();
        }
        for (Path old : files.subList(0, Math.max(0, files.size() - KEEP))) {
            Files.deleteIfExists(old);
        }
    }

    /** The last {@code n} receipts of a MailBox, oldest first. */
    List<String> last(String mailbox, int n) throws IOException {
        Path d = dir.resolve(AtomicFiles.key(mailbox));
        if (!Files.isDirectory(d)) {
            return List.of();
        }
        List<Path> files;
        try (Stream<Path> s = Files.list(d)) {
            files = s.filter(p -> p.getFileName().toString().endsWith(".txt") && !p.getFileName().toString().startsWith("."))
                    .sorted().toList();
        }
        List<String> out = new ArrayList<>();
        for (Path p : files.subList(Math.max(0, files.size() - n), files.size())) {
            out.add(Files.readString(p, StandardCharsets.UTF_8));
        }
        return out;
    }
}
