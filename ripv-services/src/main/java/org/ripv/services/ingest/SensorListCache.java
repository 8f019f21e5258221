package org.ripv.services.ingest;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.CRC32;
import org.ripv.slocum.SlocumFiles;

/**
 * The shore's copy of the glider's sensor-list cache: one {@code CRC.cac} file a list, named by
 * the {@code sensor_list_crc} of the files that use it, in one directory (as the glider's
 * {@code state/cache} folder and a dockserver's {@code cac} folder hold them). Names are matched
 * whatever their case; files are written whole (a temporary file moved into place) and never
 * replaced, so readers on other threads see a list completely or not at all.
 *
 * <p>A list is kept, taken and used only when it has the CRC it is filed under, computed as the
 * glider's firmware does ({@link #crcOf}: every one of the real cache files in the shared test data
 * is named by it). Before (issue 33 item 7) one cache served every vehicle and the first writer
 * won: a file from vehicle A claiming B's {@code sensor_list_crc} with its own list was kept as
 * {@code CRC.cac}, and B's files then decoded with A's list (latitude and longitude swapped).
 */
public final class SensorListCache {
    private static final Pattern CRC = Pattern.compile("[0-9A-Fa-f]{8}");
    /** A list of {@link SensorList#MAX_SENSORS} lines of at most about 160 characters. */
    static final long MAX_FILE_BYTES = 12L << 20;

    private final Path dir;

    public SensorListCache(Path dir) {
        this.dir = dir;
    }

    public Path directory() {
        return dir;
    }

    /** True for a name such as {@code 6b016a2e.cac} or {@code 00CDA96E.CAC}. */
    public static boolean isCacheName(String name) {
        return SlocumFiles.isCacheName(name);
    }

    /** The name without a folder ({@code TTY1/6B016A2E.CAC} as the server stores fetched files). */
    static String baseName(String name) {
        return SlocumFiles.baseName(name);
    }

    /**
     * The CRC a Slocum glider gives a sensor list: CRC-32 (the IEEE polynomial, as {@link java.util.zip.CRC32})
     * of the list's text — each {@code s:} line ending in a line feed, as in a cache file — without
     * CRC-32's final inversion; eight lower-case hex digits.
     */
    public static String crcOf(byte[] listText) {
        CRC32 c = new CRC32();
        c.update(listText);
        return String.format("%08x", ~c.getValue() & 0xffffffffL);
    }

    /** {@link #crcOf(byte[])} of these lines, each ending in a line feed. */
    public static String crcOf(List<String> lines) {
        return crcOf((String.join("\n", lines) + "\n").getBytes(StandardCharsets.ISO_8859_1));
    }

    /**
     * The lines of the list with this CRC, if the cache holds it.
     *
     * @throws IOException when the cache file does not hold the list with that CRC (put there by hand
     *                     or by an older version): it is not used, and the message says what to do
     */
    public Optional<List<String>> lines(String crc) throws IOException {
        Optional<Path> file = find(crc);
        if (file.isEmpty()) {
            return Optional.empty();
        }
        if (Files.size(file.get()) > MAX_FILE_BYTES) {
            throw new IOException(file.get() + " is larger than a sensor list can be (" + MAX_FILE_BYTES + " bytes)");
        }
        byte[] data = Files.readAllBytes(file.get());
        String actual = crcOf(data);
        if (!actual.equalsIgnoreCase(crc)) {
            throw new IOException("the cache file " + file.get().getFileName() + " does not hold the sensor list with CRC " + crc
                    + " (its list's CRC is " + actual + "); it is not used: delete it and fetch the vehicle's own cache file");
        }
        return Optional.of(SensorList.lines(new String(data, StandardCharsets.ISO_8859_1)));
    }

    public boolean holds(String crc) throws IOException {
        return find(crc).isPresent();
    }

    private Optional<Path> find(String crc) throws IOException {
        if (!CRC.matcher(crc).matches() || !Files.isDirectory(dir)) {
            return Optional.empty();
        }
        String wanted = crc.toLowerCase(Locale.ROOT) + ".cac";
        Path exact = dir.resolve(wanted);
        if (Files.isRegularFile(exact)) {
            return Optional.of(exact);
        }
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(f -> f.getFileName().toString().toLowerCase(Locale.ROOT).equals(wanted)).findFirst();
        }
    }

    /**
     * Keeps a list read from a file that carries its own, unless the cache holds it already or the
     * list does not have the CRC the file claims (a file may decode with its own list, but never
     * files another list under someone else's CRC).
     *
     * @return false when the list was not kept because its CRC is not the one claimed
     */
    public boolean keep(String crc, List<String> lines) throws IOException {
        if (!CRC.matcher(crc).matches()) {
            return false;
        }
        if (!crcOf(lines).equalsIgnoreCase(crc)) {
            return false;
        }
        if (!holds(crc)) {
            write(crc.toLowerCase(Locale.ROOT) + ".cac", String.join("\n", lines) + "\n");
        }
        return true;
    }

    /**
     * Takes a cache file fetched from the glider or uploaded: its name must be {@code CRC.cac} and
     * every line a sensor-list line. Returns the CRC.
     *
     * @throws IllegalArgumentException quoting the bad name or line
     */
    public String accept(String path, byte[] data) throws IOException {
        String name = baseName(path);
        if (!isCacheName(name)) {
            throw new IllegalArgumentException("'" + name + "' is not a cache file name (8 hex digits of the CRC, then .cac)");
        }
        if (data.length > MAX_FILE_BYTES) {
            throw new IllegalArgumentException(name + " is larger than a sensor list can be (" + MAX_FILE_BYTES + " bytes)");
        }
        List<String> lines = SensorList.lines(new String(data, StandardCharsets.ISO_8859_1));
        if (lines.isEmpty()) {
            throw new IllegalArgumentException(name + " holds no sensor lines");
        }
        for (int i = 0; i < lines.size(); i++) {
            if (!SensorList.isSensorLine(lines.get(i))) {
                throw new IllegalArgumentException(name + " line " + (i + 1) + " is not a sensor-list line: '"
                        + SensorList.cut(lines.get(i)) + "'");
            }
        }
        String crc = name.substring(0, 8).toLowerCase(Locale.ROOT);
        String actual = crcOf((String.join("\n", lines) + "\n").getBytes(StandardCharsets.ISO_8859_1));
        if (!actual.equals(crc)) {
            throw new IllegalArgumentException(name + " does not hold the sensor list with CRC " + crc + " (its list's CRC is "
                    + actual + "): refused, not kept");
        }
        if (!holds(crc)) {
            write(crc + ".cac", String.join("\n", lines) + "\n");
        }
        return crc;
    }

    private void write(String name, String text) throws IOException {
        Files.createDirectories(dir);
        Path tmp = Files.createTempFile(dir, ".cache-", ".part");
        try {
            Files.writeString(tmp, text, StandardCharsets.ISO_8859_1);
            try {
                Files.move(tmp, dir.resolve(name), StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, dir.resolve(name));
            }
        } catch (FileAlreadyExistsException e) {
            // another thread kept the same list first
        } finally {
            Files.deleteIfExists(tmp);
        }
    }
}
