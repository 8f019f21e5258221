package org.ripv.server.plans;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.Properties;

import org.ripv.files.PrivateFiles;
import org.ripv.server.files.FileStore;

/**
 * Every saved version of a vehicle's behaviour file, who saved it and when, and which of them were
 * sent: {@code DATA/plans/history/FOLDER/NAME/} holds {@code N.ma} (the bytes as saved) and
 * {@code index.properties} (written whole through a temporary file and an atomic move). FOLDER is
 * the MailBox's to-vehicle folder name, NAME the file's name in lower case. Bounded: the newest
 * {@value #KEEP} versions of a name, {@value #MAX_NAMES} names a vehicle, files of the reader's
 * size limit.
 */
final class PlanVersions {
    static final int KEEP = 100;
    static final int MAX_NAMES = 200;

    /** One saved version; {@code sent} says how it went to the vehicle ("" while it has not). */
    record Version(int n, String user, long time, String sha256, long bytes, String sent) {}

    private final Path dir;

    PlanVersions(Path dir) throws IOException {
        this.dir = PrivateFiles.createDirectories(dir);
    }

    private Path of(String mailbox, String name) {
        return dir.resolve(FileStore.folderFor(mailbox)).resolve(name.toLowerCase(Locale.ROOT));
    }

    /** Keeps {@code bytes} as the next version of {@code name}. */
    synchronized Version save(String mailbox, String name, String user, byte[] bytes, String sha256) throws IOException {
        Path d = of(mailbox, name);
        if (!Files.isDirectory(d)) {
            Path vehicle = PrivateFiles.createDirectories(d.getParent());
            try (DirectoryStream<Path> names = Files.newDirectoryStream(vehicle)) {
                int n = 0;
                for (Path ignored : names) {
                    n++;
                }
                if (n >= MAX_NAMES) {
                    throw new IllegalArgumentException(mailbox + " has saved versions of " + n + " files already, the most kept;"
                            + " save under a name used before");
                }
            }
            PrivateFiles.createDirectories(d);
        }
        List<Version> all = new ArrayList<>(list(mailbox, name));
        int n = all.isEmpty() ? 1 : all.get(all.size() - 1).n() + 1;
        Path tmp = PrivateFiles.createTempFile(d, "version-", ".tmp");
        try {
            Files.write(tmp, bytes);
            Files.move(tmp, d.resolve(n + ".ma"), StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
        Version v = new Version(n, user, System.currentTimeMillis(), sha256, bytes.length, "");
        all.add(v);
        while (all.size() > KEEP) {
            Files.deleteIfExists(d.resolve(all.remove(0).n() + ".ma"));
        }
        write(d, all);
        return v;
    }

    /** The versions of {@code name}, oldest first. */
    synchronized List<Version> list(String mailbox, String name) throws IOException {
        Path index = of(mailbox, name).resolve("index.properties");
        if (!Files.isRegularFile(index)) {
            return List.of();
        }
        Properties p = new Properties();
        try (Reader in = Files.newBufferedReader(index, StandardCharsets.UTF_8)) {
            p.load(in);
        }
        List<Version> out = new ArrayList<>();
        for (String v : p.getProperty("versions", "").split(",")) {
            if (v.isEmpty()) {
                continue;
            }
            String k = "v." + v + ".";
            out.add(new Version(Integer.parseInt(v), p.getProperty(k + "user", ""), Long.parseLong(p.getProperty(k + "time", "0")),
                    p.getProperty(k + "sha256", ""), Long.parseLong(p.getProperty(k + "bytes", "0")), p.getProperty(k + "sent", "")));
        }
        return out;
    }

    /** The bytes of version {@code n}. */
    synchronized byte[] bytes(String mailbox, String name, int n) throws IOException {
        return Files.readAllBytes(of(mailbox, name).resolve(n + ".ma"));
    }

    /** Every version of the vehicle's files with this content is marked as sent ({@code how}: as what, which change, when). */
    synchronized void sent(String mailbox, String sha256, String how) throws IOException {
        Path vehicle = dir.resolve(FileStore.folderFor(mailbox));
        if (!Files.isDirectory(vehicle)) {
            return;
        }
        try (DirectoryStream<Path> names = Files.newDirectoryStream(vehicle)) {
            for (Path d : names) {
                List<Version> all = list(mailbox, d.getFileName().toString());
                boolean changed = false;
                for (int i = 0; i < all.size(); i++) {
                    Version v = all.get(i);
                    if (v.sha256().equals(sha256)) {
                        all.set(i, new Version(v.n(), v.user(), v.time(), v.sha256(), v.bytes(), how));
                        changed = true;
                    }
                }
                if (changed) {
                    write(d, all);
                }
            }
        }
    }

    /** The newest version of {@code name} sent before version {@code n} (or {@code n} itself is excluded). */
    synchronized Optional<Version> lastSentBefore(String mailbox, String name, int n) throws IOException {
        Version found = null;
        for (Version v : list(mailbox, name)) {
            if (v.n() < n && !v.sent().isEmpty()) {
                found = v;
            }
        }
        return Optional.ofNullable(found);
    }

    private static void write(Path d, List<Version> all) throws IOException {
        Properties p = new Properties();
        StringBuilder ns = new StringBuilder();
        for (Version v : all) {
            ns.append(ns.length() == 0 ? "" : ",").append(v.n());
            String k = "v." + v.n() + ".";
            p.setProperty(k + "user", v.user());
            p.setProperty(k + "time", Long.toString(v.time()));
            p.setProperty(k + "sha256", v.sha256());
            p.setProperty(k + "bytes", Long.toString(v.bytes()));
            p.setProperty(k + "sent", v.sent());
        }
        p.setProperty("versions", ns.toString());
        Path tmp = PrivateFiles.createTempFile(d, "index-", ".tmp");
        try {
            try (Writer out = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
                p.store(out, "RIPV saved plan versions (docs/plans.md)");
            }
            Files.move(tmp, d.resolve("index.properties"), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }
}
