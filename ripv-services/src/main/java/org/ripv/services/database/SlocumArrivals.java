package org.ripv.services.database;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.ripv.messages.Attachment;
import org.ripv.services.ingest.Cycles;
import org.ripv.services.ingest.IngestLimits;
import org.ripv.services.ingest.MissingSensorListException;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.services.ingest.SlocumBinaryFiles;
import org.ripv.services.ingest.SlocumFormatException;

/**
 * The binary side of {@code ingest}: the DatabaseServer's sensor-list cache ({@code sensor-cache/},
 * filled by files that carry their list and by {@code .cac} files fetched or uploaded) and the
 * files that wait for a cache file ({@code awaiting-cache/CRC/NAME}), kept until it arrives and
 * then ingested by themselves. Both live beside the embedded database, or for another database
 * in {@code ~/.ripv/services/database/HANDLE/}.
 */
final class SlocumArrivals {
    private final SensorListCache cache;
    private final Path waiting;
    private volatile long maxPlainBytes = IngestLimits.DEFAULT_MAX_PLAIN_BYTES;

    SlocumArrivals(Path base) {
        this.cache = new SensorListCache(base.resolve("sensor-cache"));
        this.waiting = base.resolve("awaiting-cache");
    }

    static SlocumArrivals of(DatabaseTarget target) {
        String url = target.url();
        if (url.startsWith("jdbc:derby:") && !url.startsWith("jdbc:derby:memory:") && !url.startsWith("jdbc:derby://")) {
            String path = url.substring("jdbc:derby:".length());
            int semi = path.indexOf(';');
            Path db = Path.of(semi < 0 ? path : path.substring(0, semi)).toAbsolutePath();
            if (db.getParent() != null) {
                return new SlocumArrivals(db.getParent());
            }
        }
        return new SlocumArrivals(Path.of(System.getProperty("user.home"), ".ripv", "services", "database",
                target.handle().replaceAll("[^A-Za-z0-9._-]", "_")));
    }

    /** Decompress at most this many bytes of one file. */
    void limit(long maxPlainBytes) {
        this.maxPlainBytes = maxPlainBytes;
    }

    SensorListCache cache() {
        return cache;
    }

    static boolean isCache(String name) {
        return SensorListCache.isCacheName(name);
    }

    /** Keeps a cache file; returns its CRC. */
    String acceptCache(Attachment f) throws IOException {
        return cache.accept(f.name(), f.data());
    }

    /** A binary file's cycles; a file whose cache is missing is kept to wait for it, and the exception thrown. */
    Cycles open(Attachment f) throws IOException, SlocumFormatException {
        try {
            return SlocumBinaryFiles.cycles(f.name(), f.data(), cache, maxPlainBytes);
        } catch (MissingSensorListException e) {
            Path dir = waiting.resolve(e.crc());
            Files.createDirectories(dir);
            Path tmp = Files.createTempFile(dir, ".arriving-", ".part");
            Files.write(tmp, f.data());
            Files.move(tmp, dir.resolve(safe(f.name())), StandardCopyOption.REPLACE_EXISTING);
            throw e;
        }
    }

    /** The files that waited for this cache, taken off the waiting list. */
    List<Attachment> released(String crc) throws IOException {
        Path dir = waiting.resolve(crc.toLowerCase(Locale.ROOT));
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        List<Attachment> out = new ArrayList<>();
        try (Stream<Path> s = Files.list(dir)) {
            for (Path p : s.filter(p -> !p.getFileName().toString().startsWith(".")).sorted().toList()) {
                out.add(new Attachment(p.getFileName().toString(), Files.readAllBytes(p)));
                Files.delete(p);
            }
        }
        Files.deleteIfExists(dir);
        return out;
    }

    /** The CRCs files wait for, with their names ("6b016a2e.cac: a.sbd b.sbd"), for the reply and {@code ?status}. */
    List<String> waitingFor() throws IOException {
        if (!Files.isDirectory(waiting)) {
            return List.of();
        }
        List<String> out = new ArrayList<>();
        try (Stream<Path> crcs = Files.list(waiting)) {
            for (Path c : crcs.sorted().toList()) {
                try (Stream<Path> files = Files.list(c)) {
                    out.add(c.getFileName() + ".cac: " + String.join(" ", files.map(p -> p.getFileName().toString())
                            .filter(n -> !n.startsWith(".")).sorted().toList()));
                }
            }
        }
        return out;
    }

    static boolean isBinary(Attachment f) {
        return SlocumBinaryFiles.isBinary(f.name(), f.data());
    }

    private static String safe(String name) {
        String n = Path.of(name).getFileName().toString().replaceAll("[^A-Za-z0-9._-]", "_");
        return n.startsWith(".") ? "_" + n : n;
    }
}
