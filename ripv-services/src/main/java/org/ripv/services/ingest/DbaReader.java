package org.ripv.services.ingest;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.slocum.SlocumFiles;

/**
 * A strict, streaming reader of Slocum DBA files ({@code dbd2asc} output, merged {@code .mrg}):
 * {@code num_ascii_tags} header lines {@code key: value} (the first is {@value #LABEL}), then
 * {@code num_label_lines} (3) label lines — sensor names, units, bytes per value — then one row
 * per cycle, space separated, {@code NaN} where a sensor had no new value.
 *
 * <p>Only one line is in memory at a time. Positions come out in decimal degrees
 * ({@link Degrees}); a "no fix" ({@value Degrees#NO_FIX}) or impossible position comes out as
 * NaN, and is counted. Anything else that is not as the header promises — a header that stops
 * early, a row with fewer or more values than sensors, a value that is not a number, a file
 * cut in the middle of a line — throws a {@link DbaFormatException} naming the line.
 *
 * <pre>{@code
 * try (DbaReader r = new DbaReader(in)) {
 *     double[] row = new double[r.header().sensors().size()];
 *     while (r.next(row)) {
 *         double t = r.time(row);   // m_present_time, else sci_m_present_time
 *     }
 * }
 * }</pre>
 */
public final class DbaReader extends ColumnCycles {
    /** The first line of every DBA file. */
    public static final String LABEL = SlocumFiles.DBA_LABEL;
    static final int MAX_HEADER_LINE = 4096;
    static final int MAX_TAGS = 1000;
    static final int MAX_SENSORS = 100_000;
    private static final Pattern TAG = Pattern.compile("([A-Za-z0-9_]+):\\s?(.*)");
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9_]+");

    private final InputStream stream;
    private final LineReader lines;
    private final int width;
    private final int maxRowLength;
    private long blankLine;

    /**
     * Reads the header and label lines.
     *
     * @throws DbaFormatException when they are not a DBA header
     */
    public DbaReader(InputStream in) throws IOException, DbaFormatException {
        this(in, new LineReader(in));
    }

    private DbaReader(InputStream in, LineReader lines) throws IOException, DbaFormatException {
        super(readHeader(lines));
        this.stream = in;
        this.lines = lines;
        this.width = header().sensors().size();
        this.maxRowLength = 64 * width + 1024;
        if (!columns.timed()) {
            throw new DbaFormatException(lines.number() - 2,
                    "no m_present_time or sci_m_present_time sensor: the rows have no time");
        }
    }

    /** True when {@code start} (a file's first bytes) begins with the DBA label line. */
    public static boolean looksLikeDba(byte[] start) {
        return SlocumFiles.isDba(start);
    }

    private static DbaHeader readHeader(LineReader lines) throws IOException, DbaFormatException {
        Map<String, String> tags = readTags(lines);
        return new DbaHeader(tags, readLabels(lines, tags));
    }

    private static Map<String, String> readTags(LineReader lines) throws IOException, DbaFormatException {
        Map<String, String> tags = new LinkedHashMap<>();
        int expected = -1;
        while (expected < 0 || lines.number() < expected) {
            boolean more;
            try {
                more = lines.next(MAX_HEADER_LINE);
            } catch (DbaFormatException e) {
                throw new DbaFormatException(e.line(), (e.line() == 1 ? "not a DBA file: " : "") + "the header line is longer than "
                        + MAX_HEADER_LINE + " bytes");
            }
            if (!more) {
                long at = lines.number() + 1;
                throw new DbaFormatException(at, lines.number() == 0 ? "the file is empty"
                        : "the file ends in the header" + (expected > 0 ? " after " + lines.number() + " of "
                                + expected + " tag lines" : ""));
            }
            String text = lines.text().strip();
            if (lines.number() == 1) {
                if (!text.equals(LABEL)) {
                    throw new DbaFormatException(1, "not a DBA file: the first line is '" + quote(text)
                            + "', not '" + LABEL + "'");
                }
            }
            Matcher m = TAG.matcher(text);
            if (!m.matches()) {
                throw new DbaFormatException(lines.number(), "header line " + lines.number()
                        + (expected > 0 ? " of " + expected : "") + " is not 'key: value' but '" + quote(text)
                        + "' (the header stops early?)");
            }
            String key = m.group(1);
            if (tags.putIfAbsent(key, m.group(2).strip()) != null) {
                throw new DbaFormatException(lines.number(), "the header has '" + key + "' twice");
            }
            if (key.equals("num_ascii_tags")) {
                expected = integer(lines, tags, key, 3, MAX_TAGS);
                if (expected < lines.number()) {
                    throw new DbaFormatException(lines.number(), "num_ascii_tags is " + expected + " but this is tag line "
                            + lines.number());
                }
            } else if (expected < 0 && lines.number() >= 3) {
                throw new DbaFormatException(lines.number(), "no num_ascii_tags in the first 3 header lines");
            }
        }
        return tags;
    }

    private static int integer(LineReader lines, Map<String, String> tags, String key, int min, int max) throws DbaFormatException {
        String v = tags.get(key);
        if (v == null) {
            throw new DbaFormatException(lines.number(), "the header has no " + key);
        }
        try {
            int n = Integer.parseInt(v.strip());
            if (n < min || n > max) {
                throw new DbaFormatException(lines.number(), key + " is " + n + ", outside " + min + ".." + max);
            }
            return n;
        } catch (NumberFormatException e) {
            throw new DbaFormatException(lines.number(), key + " is '" + quote(v) + "', not a whole number");
        }
    }

    private static List<Sensor> readLabels(LineReader lines, Map<String, String> tags) throws IOException, DbaFormatException {
        int labelLines = integer(lines, tags, "num_label_lines", 0, 100);
        if (labelLines != 3) {
            throw new DbaFormatException(lines.number(), "num_label_lines is " + labelLines
                    + "; a DBA file has 3 (sensor names, units, bytes per value)");
        }
        int perCycle = integer(lines, tags, "sensors_per_cycle", 1, MAX_SENSORS);
        int maxLine = 64 * Math.max(perCycle, 1) + 1024;
        String[] names = labelLine(lines, maxLine, "sensor names");
        if (Math.abs(names.length - perCycle) > 1) {
            throw new DbaFormatException(lines.number(), "the label line names " + names.length
                    + " sensors but sensors_per_cycle is " + perCycle);
        }
        Set<String> seen = new HashSet<>();
        for (String n : names) {
            if (!NAME.matcher(n).matches() || n.length() > 64) {
                throw new DbaFormatException(lines.number(), "'" + quote(n) + "' is not a sensor name");
            }
            if (!seen.add(n)) {
                throw new DbaFormatException(lines.number(), "sensor '" + n + "' is named twice");
            }
        }
        String[] units = labelLine(lines, maxLine, "units");
        if (units.length != names.length) {
            throw new DbaFormatException(lines.number(), "the units line has " + units.length + " units for "
                    + names.length + " sensors");
        }
        String[] bytes = labelLine(lines, maxLine, "bytes per value");
        if (bytes.length != names.length) {
            throw new DbaFormatException(lines.number(), "the bytes line has " + bytes.length + " entries for "
                    + names.length + " sensors");
        }
        List<Sensor> out = new ArrayList<>(names.length);
        for (int i = 0; i < names.length; i++) {
            int b;
            if (units[i].length() > 32) {
                throw new DbaFormatException(lines.number() - 1, "unit '" + quote(units[i]) + "' of " + names[i]
                        + " is longer than 32 characters");
            }
            switch (bytes[i]) {
                case "1" -> b = 1;
                case "2" -> b = 2;
                case "4" -> b = 4;
                case "8" -> b = 8;
                default -> throw new DbaFormatException(lines.number(), "'" + quote(bytes[i]) + "' (for " + names[i]
                        + ") is not 1, 2, 4 or 8 bytes per value");
            }
            out.add(new Sensor(i, names[i], units[i], b, Sensor.kindOf(names[i], units[i])));
        }
        return out;
    }

    private static String[] labelLine(LineReader lines, int maxLine, String what) throws IOException, DbaFormatException {
        if (!lines.next(maxLine)) {
            throw new DbaFormatException(lines.number() + 1, "the file ends before the " + what + " line");
        }
        String t = lines.text().strip();
        if (t.isEmpty()) {
            throw new DbaFormatException(lines.number(), "the " + what + " line is empty");
        }
        return t.split("[ \t]+");
    }

    /**
     * Reads the next row into {@code values} (one per sensor; NaN where there is none, and for
     * no-fix or impossible positions). False at the end of the file.
     */
    @Override
    public boolean next(double[] values) throws IOException, DbaFormatException {
        if (values.length != width) {
            throw new IllegalArgumentException("a row of this file has " + width + " values, not " + values.length);
        }
        while (true) {
            if (!lines.next(maxRowLength)) {
                return false;
            }
            if (isBlank()) {
                if (blankLine == 0) {
                    blankLine = lines.number();
                }
                continue;
            }
            if (blankLine != 0) {
                throw new DbaFormatException(blankLine, "an empty line among the rows");
            }
            if (!lines.lastHadEnd()) {
                throw new DbaFormatException(lines.number(), "the last row has no line end: the file is cut short");
            }
            parse(values);
            counted();
            return true;
        }
    }

    private boolean isBlank() {
        byte[] b = lines.bytes();
        for (int i = 0; i < lines.length(); i++) {
            if (b[i] != ' ' && b[i] != '\t') {
                return false;
            }
        }
        return true;
    }

    private void parse(double[] values) throws DbaFormatException {
        byte[] b = lines.bytes();
        int n = lines.length();
        int col = 0;
        int i = 0;
        while (true) {
            while (i < n && (b[i] == ' ' || b[i] == '\t')) {
                i++;
            }
            if (i == n) {
                break;
            }
            int start = i;
            while (i < n && b[i] != ' ' && b[i] != '\t') {
                i++;
            }
            if (col == width) {
                throw new DbaFormatException(lines.number(), "the row has more values than the " + width + " sensors");
            }
            values[col] = value(b, start, i - start, col);
            col++;
        }
        if (col != width) {
            throw new DbaFormatException(lines.number(), "the row has " + col + " values for " + width
                    + " sensors" + (col < width ? " (the file is cut short?)" : ""));
        }
    }

    private double value(byte[] b, int off, int len, int col) throws DbaFormatException {
        if (len == 3 && b[off] == 'N' && b[off + 1] == 'a' && b[off + 2] == 'N') {
            return Double.NaN;
        }
        if (!isDecimal(b, off, len)) {
            throw new DbaFormatException(lines.number(), "value " + (col + 1) + " (" + header().sensors().get(col).name()
                    + ") is '" + quote(new String(b, off, Math.min(len, 40), StandardCharsets.ISO_8859_1))
                    + "', not a number");
        }
        double v = Double.parseDouble(new String(b, off, len, StandardCharsets.ISO_8859_1));
        if (Double.isInfinite(v)) {
            throw new DbaFormatException(lines.number(), "value " + (col + 1) + " (" + header().sensors().get(col).name()
                    + ") is too large");
        }
        return columns.isPosition(col) ? columns.degrees(col, v) : v;
    }

    /** [-+]digits[.digits][(e|E)[-+]digits], or [-+].digits...: what dbd2asc writes, nothing Java alone accepts. */
    static boolean isDecimal(byte[] b, int off, int len) {
        int i = off;
        int end = off + len;
        if (i < end && (b[i] == '-' || b[i] == '+')) {
            i++;
        }
        int digits = 0;
        while (i < end && b[i] >= '0' && b[i] <= '9') {
            i++;
            digits++;
        }
        if (i < end && b[i] == '.') {
            i++;
            while (i < end && b[i] >= '0' && b[i] <= '9') {
                i++;
                digits++;
            }
        }
        if (digits == 0) {
            return false;
        }
        if (i < end && (b[i] == 'e' || b[i] == 'E')) {
            i++;
            if (i < end && (b[i] == '-' || b[i] == '+')) {
                i++;
            }
            int exp = 0;
            while (i < end && b[i] >= '0' && b[i] <= '9') {
                i++;
                exp++;
            }
            if (exp == 0 || exp > 3) {
                return false;
            }
        }
        return i == end && len <= 40;
    }

    /** The line number of the row last read. */
    public long line() {
        return lines.number();
    }

    private static String quote(String s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length() && b.length() < 60; i++) {
            char c = s.charAt(i);
            b.append(c >= ' ' && c < 127 ? c : '?');
        }
        return s.length() > 60 ? b + "..." : b.toString();
    }

    @Override
    public void close() throws IOException {
        stream.close();
    }
}
