package org.ripv.services.datavis;

import java.io.BufferedReader;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The DataVisServer's data file format (docs/datavis.md): column-separated ASCII, one row per
 * line, {@code %} comment lines that may carry {@code title:}, {@code xlabel:}, {@code ylabel:},
 * {@code legend:} and {@code size:}; {@code NaN}, {@code Inf}, an empty comma-separated field
 * and a blank line are gaps. Parsing streams: one row is in memory at a time, so a file of any
 * length is read in bounded memory.
 *
 * <p>{@link #normalize} turns an operator's file into the canonical {@code data.dat} every worker
 * reads: all {@code %} label lines first, then rows of exactly N numbers separated by one space,
 * with {@code NaN} for every gap.
 */
public final class DataFile {
    /** At most this many columns (x plus 63 series): a wider file is almost surely not a plot. */
    public static final int MAX_COLUMNS = 64;
    private static final Pattern LABEL = Pattern.compile("%+\\s*([A-Za-z]+)\\s*:(.*)");
    private static final Pattern SIZE = Pattern.compile("\\s*(\\d{1,5})\\s*[xX*]\\s*(\\d{1,5})\\s*");

    private DataFile() {}

    /** Receives the rows of a data file in order; a gap row is all NaN. */
    @FunctionalInterface
    public interface RowSink {
        /**
         * @param values the row's numbers (the array is reused for the next row)
         * @param tokens the canonical text of each number ({@code NaN} for a gap)
         */
        void row(double[] values, String[] tokens) throws IOException;
    }

    /**
     * What a parse found.
     *
     * @param labels  the {@code %} label lines
     * @param columns numbers per row
     * @param rows    rows, gap rows included
     */
    public record Summary(PlotLabels labels, int columns, long rows) {}

    /**
     * Reads a data file, handing each row to {@code sink}.
     *
     * @throws DataFormatException naming the line, for text in a numeric column, a ragged row,
     *                             too many columns, a bad label line, or no data rows at all
     */
    public static Summary parse(BufferedReader in, RowSink sink) throws IOException, DataFormatException {
        return parse(in, sink, true);
    }

    /**
     * As {@link #parse(BufferedReader, RowSink)}, checking every number's syntax but handing
     * {@code sink} only the tokens (the values array holds NaN for gaps and nothing meaningful
     * otherwise): for the passes that count, check or copy a file, which then need not convert
     * every number to a double.
     */
    public static Summary check(BufferedReader in, RowSink sink) throws IOException, DataFormatException {
        return parse(in, sink, false);
    }

    private static Summary parse(BufferedReader in, RowSink sink, boolean convert) throws IOException, DataFormatException {
        PlotLabels labels = PlotLabels.NONE;
        int columns = -1;
        boolean comma = false;
        boolean pendingGap = false;
        long rows = 0;
        long lineNo = 0;
        double[] values = null;
        String[] tokens = null;
        String raw;
        while ((raw = in.readLine()) != null) {
            lineNo++;
            String line = raw.strip();
            if (lineNo == 1 && !line.isEmpty() && line.charAt(0) == '\uFEFF') {
                line = line.substring(1).strip(); // a byte-order mark from a Windows editor
            }
            if (line.isEmpty()) {
                pendingGap = columns > 0; // blank line: break every series here
                continue;
            }
            if (line.charAt(0) == '%') {
                Matcher m = LABEL.matcher(line);
                if (m.matches()) {
                    String value = m.group(2).trim();
                    String key = m.group(1).toLowerCase(Locale.ROOT);
                    switch (key) {
                        case "title", "xlabel", "ylabel", "legend", "mark" -> labels = labels.with(key, value);
                        case "plot" -> {
                            String style = value.toLowerCase(Locale.ROOT);
                            if (!PlotLabels.STYLES.contains(style)) {
                                throw new DataFormatException(lineNo, "'% plot: " + value + "' is not one of "
                                        + String.join(", ", PlotLabels.STYLES));
                            }
                            labels = labels.with(key, style);
                        }
                        case "size" -> {
                            Matcher s = SIZE.matcher(value);
                            int w = s.matches() ? Integer.parseInt(s.group(1)) : -1;
                            int h = s.matches() ? Integer.parseInt(s.group(2)) : -1;
                            if (w < PlotLabels.MIN_SIZE || w > PlotLabels.MAX_SIZE || h < PlotLabels.MIN_SIZE
                                    || h > PlotLabels.MAX_SIZE) {
                                throw new DataFormatException(lineNo, "'% size: " + value + "' is not WIDTHxHEIGHT with "
                                        + PlotLabels.MIN_SIZE + ".." + PlotLabels.MAX_SIZE + " pixels a side, e.g. 800x600");
                            }
                            labels = labels.withSize(w, h);
                        }
                        default -> { } // any other "% word: text" is an ordinary comment
                    }
                }
                continue;
            }
            int cut = line.indexOf('%');
            if (cut >= 0) {
                line = line.substring(0, cut).strip(); // a trailing comment, as in MATLAB
            }
            if (columns < 0) {
                comma = line.indexOf(',') >= 0; // the first data row decides the separator
            }
            List<String> fields = split(line, comma);
            if (columns < 0) {
                columns = fields.size();
                if (columns > MAX_COLUMNS) {
                    throw new DataFormatException(lineNo, columns + " columns; at most " + MAX_COLUMNS
                            + " (x and " + (MAX_COLUMNS - 1) + " series) can be plotted");
                }
                values = new double[columns];
                tokens = new String[columns];
            } else if (fields.size() != columns) {
                throw new DataFormatException(lineNo, "ragged row: " + fields.size() + " value"
                        + (fields.size() == 1 ? "" : "s") + " where the rows before have " + columns
                        + (comma ? " (comma-separated; leave a field empty for a gap)" : "")
                        + ": '" + shorten(raw) + "'");
            }
            if (pendingGap) {
                Arrays.fill(values, Double.NaN);
                Arrays.fill(tokens, "NaN");
                sink.row(values, tokens);
                rows++;
                pendingGap = false;
            }
            for (int c = 0; c < columns; c++) {
                String f = fields.get(c);
                double v;
                try {
                    v = number(f, convert);
                } catch (NumberFormatException e) {
                    throw new DataFormatException(lineNo, "column " + (c + 1) + ": '" + shorten(f)
                            + "' is not a number (use NaN, or leave the field empty, for a gap)");
                }
                values[c] = v;
                tokens[c] = Double.isNaN(v) ? "NaN" : Double.isInfinite(v) ? (v > 0 ? "Inf" : "-Inf") : f;
            }
            sink.row(values, tokens);
            rows++;
        }
        if (rows == 0) {
            throw new DataFormatException(0, lineNo == 0 ? "the data file is empty"
                    : "the data file has no data rows (only comments or blank lines in " + lineNo + " line"
                            + (lineNo == 1 ? "" : "s") + ")");
        }
        return new Summary(labels, columns, rows);
    }

    /**
     * Writes the canonical {@code data.dat}: the label lines (the file's, with {@code overrides}
     * winning), then every row as numbers separated by one space.
     */
    public static Summary normalize(byte[] data, PlotLabels overrides, Writer out) throws IOException, DataFormatException {
        // Pass 1 validates and collects the labels, so they can all go first, where workers look for them.
        Summary found = check(reader(data), (v, t) -> { });
        PlotLabels labels = overrides.or(found.labels());
        if (labels.legend() != null && labels.legend().size() > Math.max(1, found.columns() - 1)) {
            throw new DataFormatException(0, "the legend names " + labels.legend().size() + " series but the file has "
                    + Math.max(1, found.columns() - 1));
        }
        writeLabels(labels, out);
        StringBuilder sb = new StringBuilder(64);
        check(reader(data), (v, tokens) -> {
            sb.setLength(0);
            for (int i = 0; i < tokens.length; i++) {
                if (i > 0) {
                    sb.append(' ');
                }
                sb.append(tokens[i]);
            }
            sb.append('\n');
            out.append(sb);
        });
        out.flush();
        return new Summary(labels, found.columns(), found.rows());
    }

    /** Writes the label lines that are given, in the canonical form. */
    static void writeLabels(PlotLabels labels, Writer out) throws IOException {
        if (labels.title() != null) {
            out.write("% title: " + labels.title() + "\n");
        }
        if (labels.xLabel() != null) {
            out.write("% xlabel: " + labels.xLabel() + "\n");
        }
        if (labels.yLabel() != null) {
            out.write("% ylabel: " + labels.yLabel() + "\n");
        }
        if (labels.legend() != null) {
            out.write("% legend: " + String.join(" | ", labels.legend()) + "\n");
        }
        if (labels.width() != 0) {
            out.write("% size: " + labels.width() + "x" + labels.height() + "\n");
        }
        if (labels.style() != null) {
            out.write("% plot: " + labels.style() + "\n");
        }
        if (labels.mark() != null) {
            out.write("% mark: " + labels.mark() + "\n");
        }
    }

    static BufferedReader reader(byte[] data) {
        return new BufferedReader(new InputStreamReader(new ByteArrayInputStream(data), StandardCharsets.UTF_8));
    }

    /**
     * A number, or NaN for a gap. Stricter than Double.parseDouble: no "1d", "0x1p3", "Infinity".
     * Unless {@code convert}, a plain decimal (no exponent, so never infinite) is only checked and
     * 0 stands for its value.
     */
    static double number(String f, boolean convert) {
        if (f.isEmpty()) {
            return Double.NaN;
        }
        char first = f.charAt(0);
        if (first >= '0' && first <= '9' || first == '.' || (first == '-' || first == '+') && f.length() > 1
                && f.charAt(1) != 'i' && f.charAt(1) != 'I') {
            int kind = decimal(f);
            if (kind == NOT_A_NUMBER) {
                throw new NumberFormatException(f);
            }
            return convert || kind == EXPONENT ? Double.parseDouble(f) : 0;
        }
        if (f.equalsIgnoreCase("nan") || f.equalsIgnoreCase("na")) {
            return Double.NaN;
        }
        if (f.equalsIgnoreCase("inf") || f.equalsIgnoreCase("+inf")) {
            return Double.POSITIVE_INFINITY;
        }
        if (f.equalsIgnoreCase("-inf")) {
            return Double.NEGATIVE_INFINITY;
        }
        throw new NumberFormatException(f);
    }

    private static final int NOT_A_NUMBER = 0;
    private static final int PLAIN = 1;
    private static final int EXPONENT = 2;

    /** [+-] digits [. digits] or [+-] . digits, then optionally [eE] [+-] digits: what parseDouble takes of these characters. */
    static int decimal(String f) {
        int n = f.length();
        int i = 0;
        if (f.charAt(0) == '-' || f.charAt(0) == '+') {
            i++;
        }
        int digits = 0;
        while (i < n && f.charAt(i) >= '0' && f.charAt(i) <= '9') {
            i++;
            digits++;
        }
        if (i < n && f.charAt(i) == '.') {
            i++;
            while (i < n && f.charAt(i) >= '0' && f.charAt(i) <= '9') {
                i++;
                digits++;
            }
        }
        if (digits == 0) {
            return NOT_A_NUMBER;
        }
        if (i == n) {
            return PLAIN;
        }
        if (f.charAt(i) != 'e' && f.charAt(i) != 'E') {
            return NOT_A_NUMBER;
        }
        i++;
        if (i < n && (f.charAt(i) == '-' || f.charAt(i) == '+')) {
            i++;
        }
        int exp = 0;
        while (i < n && f.charAt(i) >= '0' && f.charAt(i) <= '9') {
            i++;
            exp++;
        }
        return exp > 0 && i == n ? EXPONENT : NOT_A_NUMBER;
    }

    private static List<String> split(String line, boolean comma) {
        List<String> out = new ArrayList<>();
        if (comma) {
            for (String f : line.split(",", -1)) {
                out.add(f.strip());
            }
            return out;
        }
        int n = line.length();
        int i = 0;
        while (i < n) {
            while (i < n && Character.isWhitespace(line.charAt(i))) {
                i++;
            }
            int start = i;
            while (i < n && !Character.isWhitespace(line.charAt(i))) {
                i++;
            }
            if (i > start) {
                out.add(line.substring(start, i));
            }
        }
        return out;
    }

    private static String shorten(String s) {
        String t = s.strip();
        return t.length() > 60 ? t.substring(0, 57) + "..." : t;
    }
}
