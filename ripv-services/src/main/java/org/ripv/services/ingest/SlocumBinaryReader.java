package org.ripv.services.ingest;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;
import org.ripv.slocum.SlocumFiles;
import org.slf4j.LoggerFactory;

/**
 * A strict, streaming decoder of Slocum binary data files ({@code .sbd}, {@code .tbd},
 * {@code .dbd}, {@code .ebd}, … and, through {@link Lz4BlockInputStream}, their LZ4-compressed
 * forms {@code .scd}, {@code .tcd}, {@code .dcd}, {@code .ecd}, …), as docs/slocum.md describes:
 *
 * <ol>
 * <li>an ASCII header of {@code num_ascii_tags} lines {@code key: value};
 * <li>the sensor list, {@code total_num_sensors} lines {@code s: T|F INDEX CYCLE_INDEX BYTES NAME
 * UNITS} — or, with {@code sensor_list_factored: 1}, none: the list is in the cache file
 * {@code CRC.cac} named by {@code sensor_list_crc} ({@link SensorListCache});
 * <li>the known-bytes cycle: {@code 's' 'a'}, the 2-byte integer 0x1234 (which gives the byte
 * order), the float 123.456 and the double 123456789.12345;
 * <li>data cycles: {@code 'd'}, {@code state_bytes_per_cycle} bytes of 2-bit states, four
 * sensors a byte from the high bits down (0 not updated, 1 same value as before, 2 a new value
 * follows), then the new values, 1-byte and 2-byte signed integers, 4-byte floats and 8-byte
 * doubles in cycle order;
 * <li>the end tag {@code 'X'}.
 * </ol>
 *
 * <p>As Teledyne's {@code dbd2asc} does, the first data cycle (the values the file starts from)
 * gives no row but the values later "same as before" states repeat. One cycle is in memory at a
 * time; anything that is not as the header promises throws a {@link SlocumFormatException} with
 * the byte offset. A file whose data cycles stop short of the end tag (a call cut over Iridium)
 * is read, as {@code dbd2asc} reads it, up to its last whole cycle; {@link #leftOut()} says what
 * was left. A file cut in its header or known-bytes cycle has no cycle to give and is refused.
 *
 * <p>Longer than 400 lines for one job: the header, the sensor list, the known-bytes cycle and
 * the data cycles are read through one buffer at one byte offset, which every error names.
 */
public final class SlocumBinaryReader implements AutoCloseable {
    /** The label line's value in every binary file. */
    public static final String LABEL = SlocumFiles.BINARY_LABEL;
    /** The only encoding the files in the field use (every glider firmware since the 2000s writes 5). */
    public static final int ENCODING = 5;
    static final int MAX_LINE = 512;
    static final int MAX_TAGS = 100;
    private static final Pattern TAG = Pattern.compile("([A-Za-z0-9_]+):\\s*(.*?)\\s*");
    private static final Pattern CRC = Pattern.compile("[0-9A-Fa-f]{8}");

    private final InputStream in;
    private final String file;
    private final byte[] buf = new byte[1 << 16];
    private int pos;
    private int lim;
    private long base;
    private final Map<String, String> tags;
    private final List<SlocumSensor> sensors;
    private final String crc;
    private final byte[] sizes;
    private final double[] last;
    private final byte[] states;
    private boolean bigEndian;
    private boolean first = true;
    private boolean ended;
    private long cycles;
    /** Why the data ended before the end tag, or empty (see {@link #leftOut()}). */
    private String leftOut = "";
    /** True while a data cycle is read: running out of bytes then cuts the file, it does not break it. */
    private boolean inCycle;

    /**
     * Reads the header, the sensor list and the known-bytes cycle.
     *
     * @param in    the file's bytes (plain: a compressed file comes through {@link #open})
     * @param file  its name, for messages
     * @param cache where factored lists are found, and where lists carried by a file are kept; may be null
     * @throws MissingSensorListException when the list is in a cache file the cache does not hold
     * @throws SlocumFormatException      when the file is not what its header promises
     */
    public SlocumBinaryReader(InputStream in, String file, SensorListCache cache) throws IOException, SlocumFormatException {
        this.in = in;
        this.file = file;
        try {
            this.tags = Collections.unmodifiableMap(readTags());
            int total = intTag("total_num_sensors", 1, SensorList.MAX_SENSORS);
            int perCycle = intTag("sensors_per_cycle", 0, total);
            int stateBytes = intTag("state_bytes_per_cycle", 0, SensorList.MAX_SENSORS);
            if (stateBytes != (perCycle + 3) / 4) {
                throw format("state_bytes_per_cycle is " + stateBytes + " but " + perCycle + " sensors need " + (perCycle + 3) / 4);
            }
            String crcTag = tags.getOrDefault("sensor_list_crc", "");
            if (!CRC.matcher(crcTag).matches()) {
                throw format("sensor_list_crc '" + crcTag + "' is not 8 hex digits");
            }
            this.crc = crcTag.toLowerCase(Locale.ROOT);
            String factored = tags.getOrDefault("sensor_list_factored", "0");
            List<String> lines;
            long listAt = offset();
            if (factored.equals("1")) {
                Optional<List<String>> cached = cache == null ? Optional.empty() : cache.lines(crc);
                if (cached.isEmpty()) {
                    throw new MissingSensorListException(file, listAt, crc);
                }
                lines = cached.get();
            } else if (factored.equals("0")) {
                lines = new ArrayList<>(total);
                for (int i = 0; i < total; i++) {
                    lines.add(line("sensor line " + (i + 1) + " of " + total));
                }
            } else {
                throw format("sensor_list_factored is '" + factored + "', not 0 or 1");
            }
            try {
                this.sensors = SensorList.cycle(lines, total, perCycle);
            } catch (IllegalArgumentException e) {
                throw new SlocumFormatException(file, listAt, (factored.equals("1") ? "the cache file " + crc + ".cac does not fit"
                        + " the header (a cache of another list under this CRC?): " : "") + e.getMessage());
            }
            if (factored.equals("0") && cache != null && !cache.keep(crc, lines)) {
                // the file decodes with its own list, but that list is not filed under a CRC it does not have
                LoggerFactory.getLogger(SlocumBinaryReader.class).warn("{}: its sensor list's CRC is {}, not the {} its"
                        + " header claims; the list is not kept in the sensor-list cache", file, SensorListCache.crcOf(lines), crc);
            }
            this.sizes = new byte[perCycle];
            for (int i = 0; i < perCycle; i++) {
                sizes[i] = (byte) sensors.get(i).bytes();
            }
            this.last = new double[perCycle];
            Arrays.fill(last, Double.NaN);
            this.states = new byte[stateBytes];
            knownBytes();
        } catch (Lz4BlockInputStream.CompressedFormatException e) {
            throw e.format();
        }
    }

    /** A reader for a file by its name: compressed names ({@code .?cd}) are decompressed on the way. */
    public static SlocumBinaryReader open(InputStream in, String file, SensorListCache cache) throws IOException, SlocumFormatException {
        return open(in, file, cache, IngestLimits.DEFAULT_MAX_PLAIN_BYTES);
    }

    /** As above, decompressing at most {@code maxPlainBytes}. */
    public static SlocumBinaryReader open(InputStream in, String file, SensorListCache cache, long maxPlainBytes)
            throws IOException, SlocumFormatException {
        return new SlocumBinaryReader(Lz4BlockInputStream.isCompressedName(file) ? new Lz4BlockInputStream(in, file, maxPlainBytes)
                : in, file, cache);
    }

    /** True for the names of Slocum binary data files, plain or compressed ({@code .sbd}, {@code .tcd}, …). */
    public static boolean isBinaryName(String name) {
        return SlocumFiles.isBinaryName(name);
    }

    /** The header's tags in file order. */
    public Map<String, String> tags() {
        return tags;
    }

    /** The cycle's sensors in cycle order. */
    public List<SlocumSensor> sensors() {
        return sensors;
    }

    /** The sensor list's CRC (lower case). */
    public String crc() {
        return crc;
    }

    /** Data cycles read so far, the first (which gives no row) included. */
    public long cycles() {
        return cycles;
    }

    /**
     * What a file cut short of its end tag left out, once {@link #next} has returned false: empty
     * for a whole file, else e.g. "the file ends after 376 cycles without its end tag 'X' (17 bytes
     * of a cut cycle left out): read up to its last whole cycle, as dbd2asc does".
     */
    public String leftOut() {
        return leftOut;
    }

    /** How many bytes of the (decompressed) file have been read. */
    public long offset() {
        return base + pos;
    }

    /**
     * The next row: each sensor's value, the last one for "same as before", NaN where it was not updated.
     *
     * @return false at the end tag
     */
    public boolean next(double[] row) throws IOException, SlocumFormatException {
        try {
            while (true) {
                if (ended) {
                    return false;
                }
                long at = offset();
                int tag = read();
                if (tag < 0) {
                    return cut(at, "");
                }
                if (tag == 'X') {
                    ended = true;
                    return false;
                }
                if (tag != 'd') {
                    throw new SlocumFormatException(file, at, "expected a data cycle ('d') or the end ('X'), found byte 0x"
                            + Integer.toHexString(tag) + " (cycle " + (cycles + 1) + ")");
                }
                inCycle = true;
                try {
                    cycle(row);
                } catch (Cut c) {
                    return cut(at, " (" + (c.offset() - at) + " bytes of a cut cycle left out)");
                } finally {
                    inCycle = false;
                }
                cycles++;
                if (!first) {
                    return true;
                }
                first = false;
            }
        } catch (Lz4BlockInputStream.CompressedFormatException e) {
            throw e.format();
        }
    }

    /** Ends the data at {@code at}, the start of the first cycle that is not whole. */
    private boolean cut(long at, String part) {
        ended = true;
        leftOut = "the file ends after " + cycles + " cycles without its end tag 'X'" + part
                + ": read up to its last whole cycle (byte " + at + "), as dbd2asc does";
        return false;
    }

    /** The bytes ran out inside a data cycle (its offset is the file's end): the file was cut there. */
    private static final class Cut extends SlocumFormatException {
        private static final long serialVersionUID = 1L;

        Cut(String file, long offset, String reason) {
            super(file, offset, reason);
        }
    }

    private SlocumFormatException truncated(String what) {
        String reason = "the file ends inside " + what + ": it is truncated";
        return inCycle ? new Cut(file, base + lim, reason) : new SlocumFormatException(file, offset(), reason);
    }

    private void cycle(double[] row) throws IOException, SlocumFormatException {
        fill(states, "the cycle's states");
        int n = sizes.length;
        for (int i = 0; i < n; i++) {
            int state = states[i >> 2] >> (6 - ((i & 3) << 1)) & 3;
            switch (state) {
                case 0 -> row[i] = Double.NaN;
                case 1 -> row[i] = last[i];
                case 2 -> {
                    double v = value(sizes[i]);
                    last[i] = v;
                    row[i] = v;
                }
                default -> throw new SlocumFormatException(file, offset(), "sensor " + sensors.get(i).name()
                        + " has the state 3, which no encoding uses (cycle " + (cycles + 1) + ")");
            }
        }
    }

    private double value(int size) throws IOException, SlocumFormatException {
        if (lim - pos < size && !ensure(size)) {
            throw truncated("a " + size + "-byte value");
        }
        int p = pos;
        pos += size;
        return switch (size) {
            case 1 -> buf[p];
            case 2 -> (short) (bigEndian ? (buf[p] & 0xff) << 8 | buf[p + 1] & 0xff : (buf[p + 1] & 0xff) << 8 | buf[p] & 0xff);
            case 4 -> Float.intBitsToFloat(int32(p));
            default -> Double.longBitsToDouble(bigEndian ? (long) int32(p) << 32 | int32(p + 4) & 0xffffffffL
                    : (long) int32(p + 4) << 32 | int32(p) & 0xffffffffL);
        };
    }

    private int int32(int p) {
        return bigEndian ? (buf[p] & 0xff) << 24 | (buf[p + 1] & 0xff) << 16 | (buf[p + 2] & 0xff) << 8 | buf[p + 3] & 0xff
                : (buf[p + 3] & 0xff) << 24 | (buf[p + 2] & 0xff) << 16 | (buf[p + 1] & 0xff) << 8 | buf[p] & 0xff;
    }

    private void knownBytes() throws IOException, SlocumFormatException {
        long at = offset();
        byte[] k = new byte[4];
        fill(k, "the known-bytes cycle");
        if (k[0] != 's' || k[1] != 'a') {
            throw new SlocumFormatException(file, at, "the known-bytes cycle does not start with 'sa' (found 0x"
                    + String.format("%02x%02x", k[0], k[1]) + ")");
        }
        if (k[2] == 0x12 && k[3] == 0x34) {
            bigEndian = true;
        } else if (k[2] == 0x34 && k[3] == 0x12) {
            bigEndian = false;
        } else {
            throw new SlocumFormatException(file, at + 2, "the known 2-byte integer is not 0x1234 in either byte order");
        }
        float f = (float) value(4);
        if (f != 123.456f) {
            throw new SlocumFormatException(file, at + 4, "the known float is " + f + ", not 123.456");
        }
        double d = value(8);
        if (d != 123456789.12345) {
            throw new SlocumFormatException(file, at + 8, "the known double is " + d + ", not 123456789.12345");
        }
    }

    private Map<String, String> readTags() throws IOException, SlocumFormatException {
        Map<String, String> t = new LinkedHashMap<>();
        String label = line("the header's first line");
        var m = TAG.matcher(label);
        if (!m.matches() || !m.group(1).equals("dbd_label") || !m.group(2).equals(LABEL)) {
            throw new SlocumFormatException(file, 0, "not a Slocum binary file: the first line is not 'dbd_label: " + LABEL
                    + "' but '" + SensorList.cut(printable(label)) + "'");
        }
        t.put("dbd_label", m.group(2));
        int count = -1;
        for (int i = 1; count < 0 ? i < 3 : i < count; i++) {
            long at = offset();
            String l = line("header line " + (i + 1));
            m = TAG.matcher(l);
            if (!m.matches()) {
                throw new SlocumFormatException(file, at, "header line " + (i + 1) + " is not 'key: value': '"
                        + SensorList.cut(printable(l)) + "'");
            }
            t.put(m.group(1), m.group(2));
            if (m.group(1).equals("encoding_ver") && !m.group(2).equals(Integer.toString(ENCODING))) {
                throw new SlocumFormatException(file, at, "encoding version '" + m.group(2) + "' is not one this decoder knows ("
                        + ENCODING + ")");
            }
            if (m.group(1).equals("num_ascii_tags")) {
                try {
                    count = Integer.parseInt(m.group(2));
                } catch (NumberFormatException e) {
                    count = -2;
                }
                if (count < 3 || count > MAX_TAGS) {
                    throw new SlocumFormatException(file, at, "num_ascii_tags '" + m.group(2) + "' is not between 3 and " + MAX_TAGS);
                }
            }
        }
        if (count < 0) {
            throw new SlocumFormatException(file, offset(), "no num_ascii_tags in the header's first three lines");
        }
        if (!t.containsKey("encoding_ver")) {
            throw new SlocumFormatException(file, offset(), "the header has no encoding_ver");
        }
        return t;
    }

    private int intTag(String key, int min, int max) throws SlocumFormatException {
        String v = tags.get(key);
        if (v == null) {
            throw format("the header has no " + key);
        }
        long n;
        try {
            n = Long.parseLong(v);
        } catch (NumberFormatException e) {
            throw format(key + " '" + SensorList.cut(printable(v)) + "' is not a number");
        }
        if (n < min || n > max) {
            throw format(key + " is " + n + ", not between " + min + " and " + max);
        }
        return (int) n;
    }

    private SlocumFormatException format(String reason) {
        return new SlocumFormatException(file, offset(), reason);
    }

    private String line(String what) throws IOException, SlocumFormatException {
        long at = offset();
        StringBuilder b = new StringBuilder();
        while (true) {
            int c = read();
            if (c < 0) {
                throw new SlocumFormatException(file, at, "the file ends in " + what + ": it is truncated");
            }
            if (c == '\n') {
                return b.toString();
            }
            if (b.length() >= MAX_LINE) {
                throw new SlocumFormatException(file, at, what + " is longer than " + MAX_LINE + " bytes: not a Slocum header");
            }
            b.append((char) c);
        }
    }

    static String printable(String s) {
        StringBuilder b = new StringBuilder();
        for (char c : s.toCharArray()) {
            b.append(c >= 0x20 && c < 0x7f ? String.valueOf(c) : String.format("\\x%02x", (int) c));
        }
        return b.toString();
    }

    private int read() throws IOException {
        if (pos == lim && !ensure(1)) {
            return -1;
        }
        return buf[pos++] & 0xff;
    }

    private void fill(byte[] into, String what) throws IOException, SlocumFormatException {
        if (lim - pos < into.length && !ensure(into.length)) {
            throw truncated(what);
        }
        System.arraycopy(buf, pos, into, 0, into.length);
        pos += into.length;
    }

    /** Makes {@code n} bytes available from {@code pos}; false at the end of the file. */
    private boolean ensure(int n) throws IOException {
        if (pos > 0) {
            System.arraycopy(buf, pos, buf, 0, lim - pos);
            base += pos;
            lim -= pos;
            pos = 0;
        }
        while (lim < n) {
            int got = in.read(buf, lim, buf.length - lim);
            if (got < 0) {
                return false;
            }
            lim += got;
        }
        return true;
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
