package org.ripv.dac;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Instant;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.List;
import java.util.Set;

/**
 * What was pushed where: one line a push attempt's outcome, appended ({@code TIME\tFILE\tSHA-256\tsent|failed\tDETAIL}).
 * A file is identified by its name and content: the same bytes are never sent twice to the same
 * destination; a file rewritten under the same name (a delayed-mode file replacing nothing, or a
 * fixed profile) is new content and is sent.
 */
public final class DacLedger {
    private final Path file;
    private final Set<String> sent = new HashSet<>();

    public DacLedger(Path file) throws IOException {
        this.file = file;
        if (Files.exists(file)) {
            for (String line : Files.readAllLines(file, StandardCharsets.UTF_8)) {
                String[] f = line.split("\t", 6);
                if (f.length >= 5 && f[4].equals("sent")) {
                    sent.add(f[1] + "\t" + f[2] + "\t" + f[3]);
                }
            }
        }
    }

    public Path file() {
        return file;
    }

    public synchronized boolean wasSent(String destination, Path f, String sha256) {
        return sent.contains(destination + "\t" + f.getFileName() + "\t" + sha256);
    }

    public synchronized void record(String destination, Path f, String sha256, boolean ok, String detail) throws IOException {
        String line = String.join("\t", Instant.now().toString(), destination, f.getFileName().toString(), sha256,
                ok ? "sent" : "failed", detail.replace('\t', ' ').replace('\n', ' ')) + "\n";
        Files.writeString(file, line, StandardCharsets.UTF_8, StandardOpenOption.CREATE, StandardOpenOption.APPEND);
        if (ok) {
            sent.add(destination + "\t" + f.getFileName() + "\t" + sha256);
        }
    }

    /** The lines recorded so far. */
    public List<String> lines() throws IOException {
        return Files.exists(file) ? Files.readAllLines(file, StandardCharsets.UTF_8) : List.of();
    }

    static String sha256(Path f) throws IOException {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(f)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
