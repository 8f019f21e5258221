package org.ripv.services.serial.zmodem;

import java.io.IOException;
import java.io.OutputStream;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import org.ripv.files.PrivateFiles;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.FileNames;

/**
 * Where files a ZMODEM get receives are assembled, one directory per link, kept between calls:
 * {@code NAME.partial} holds the bytes that arrived (each checked by its CRC), and
 * {@code NAME.partial.properties} what the vehicle's ZFILE header said (size, mtime) and the
 * calls that brought parts. A {@code .partial} file is never a result: only {@link #complete}
 * moves a whole file out, to where the caller collects it.
 *
 * <p>Resume rule: the next get of NAME continues from the part's length only when the vehicle
 * announces the same size and mtime and the part is shorter than that size; otherwise the part
 * is thrown away and the file is fetched whole, so two versions are never spliced.
 */
public final class ResumeStore {
    /** What {@link #offer} decided for one file. */
    public record Start(long offset, String note) {
    }

    private final Path dir;

    public ResumeStore(Path dir) throws IOException {
        this.dir = PrivateFiles.createDirectories(dir);
    }

    private Path part(String name) {
        return dir.resolve(FileNames.requirePlain(name) + ".partial");
    }

    private Path meta(String name) {
        return dir.resolve(FileNames.requirePlain(name) + ".partial.properties");
    }

    /** The length of the part kept for NAME, or -1. */
    public long partLength(String name) throws IOException {
        Path p = part(name);
        return Files.exists(p) ? Files.size(p) : -1;
    }

    /**
     * Decides where a file the vehicle announces starts: from an earlier part's length, or from
     * zero (with a note saying why an existing part was not used).
     */
    public Start offer(FileHeader file) throws IOException {
        Path p = part(file.name());
        if (!Files.exists(p)) {
            return new Start(0, "");
        }
        long have = Files.size(p);
        Properties m = load(file.name());
        long size = Long.parseLong(m.getProperty("size", "-2"));
        long mtime = Long.parseLong(m.getProperty("mtime", "-2"));
        String why;
        if (file.length() < 0 || file.mtimeSeconds() <= 0) {
            why = "the vehicle did not give its size and time, so the part cannot be matched";
        } else if (size != file.length() || mtime != file.mtimeSeconds()) {
            why = "it changed on the vehicle since (" + size + " bytes, mtime " + mtime + " then; " + file.length()
                    + " bytes, mtime " + file.mtimeSeconds() + " now)";
        } else if (have > file.length()) {
            why = "the part (" + have + " bytes) is longer than the file (" + file.length() + " bytes)";
        } else {
            return new Start(have, "resumed at byte " + have + " (" + m.getProperty("calls", "an earlier call") + ")");
        }
        discard(file.name());
        return new Start(0, "an earlier part of " + have + " bytes was not used: " + why + "; fetched whole");
    }

    /** Opens NAME's part for writing from {@code offset} (0 starts it afresh) and records the vehicle's header. */
    public OutputStream open(FileHeader file, long offset) throws IOException {
        Path p = part(file.name());
        Properties m = offset > 0 ? load(file.name()) : new Properties();
        m.setProperty("size", Long.toString(file.length()));
        m.setProperty("mtime", Long.toString(file.mtimeSeconds()));
        m.setProperty("started", m.getProperty("started", Instant.now().toString()));
        store(file.name(), m);
        if (offset == 0) {
            Files.deleteIfExists(p);
            return PrivateFiles.newOutputStream(p, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING);
        }
        // a part may hold more than the vehicle was told to resume from only if we asked wrongly: cut it there
        try (var ch = Files.newByteChannel(p, StandardOpenOption.WRITE)) {
            ch.truncate(offset);
        }
        return Files.newOutputStream(p, StandardOpenOption.WRITE, StandardOpenOption.APPEND);
    }

    /** Notes that a call ended with NAME cut short, for the receipt of the call that completes it. */
    public void interrupted(String name, long from, long to) throws IOException {
        Properties m = load(name);
        String call = "a call at " + Instant.now() + " got bytes " + from + "-" + to;
        String calls = m.getProperty("calls");
        m.setProperty("calls", calls == null ? call : calls + "; " + call);
        store(name, m);
    }

    /** Moves the whole file to {@code target} and forgets its part. */
    public void complete(String name, Path target) throws IOException {
        Files.move(part(name), target, StandardCopyOption.REPLACE_EXISTING);
        Files.deleteIfExists(meta(name));
    }

    /** Throws the part away (the peer broke the protocol, or the vehicle's file changed). */
    public void discard(String name) throws IOException {
        Files.deleteIfExists(part(name));
        Files.deleteIfExists(meta(name));
    }

    /** The names with a part kept, for the service's status and docs' examples. */
    public List<String> parts() throws IOException {
        List<String> names = new ArrayList<>();
        try (var s = Files.list(dir)) {
            s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".partial"))
                    .forEach(n -> names.add(n.substring(0, n.length() - ".partial".length())));
        }
        return names;
    }

    private Properties load(String name) throws IOException {
        Properties m = new Properties();
        Path p = meta(name);
        if (Files.exists(p)) {
            try (Reader r = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                m.load(r);
            }
        }
        return m;
    }

    private void store(String name, Properties m) throws IOException {
        Path tmp = dir.resolve(FileNames.requirePlain(name) + ".partial.properties.tmp");
        try (Writer w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
            m.store(w, "ZMODEM part of " + name + ": what the vehicle announced, and the calls that brought it");
        }
        Files.move(tmp, meta(name), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
