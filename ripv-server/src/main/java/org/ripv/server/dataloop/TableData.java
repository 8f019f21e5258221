package org.ripv.server.dataloop;

import java.nio.charset.StandardCharsets;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import java.util.List;
import java.util.Locale;
import org.ripv.messages.TableResult;

/**
 * A query's table as the DataVisServer's data file (docs/datavis.md): {@code %} label lines, then
 * one row of numbers per table row. Numbers stay numbers, timestamps become epoch seconds (UTC),
 * SQL NULL becomes NaN (a gap); any other text is refused with the column's name.
 */
final class TableData {
    private TableData() {}

    /** Whether a column of this SQL type is a time. */
    static boolean isTime(String type) {
        String t = type.toUpperCase(Locale.ROOT);
        return t.startsWith("TIMESTAMP") || t.equals("DATE");
    }

    /** A cell as a number: epoch seconds for a time, NaN for null. */
    static double number(String cell, String type, String column) {
        if (cell == null) {
            return Double.NaN;
        }
        if (isTime(type)) {
            try {
                String c = cell.strip().replace(' ', 'T');
                LocalDateTime t = c.length() == 10 ? LocalDateTime.parse(c + "T00:00:00") : LocalDateTime.parse(c);
                return t.toEpochSecond(ZoneOffset.UTC) + t.getNano() / 1e9;
            } catch (DateTimeParseException e) {
                throw new IllegalArgumentException("column " + column + ": '" + cell + "' is not a time");
            }
        }
        try {
            return Double.parseDouble(cell.strip());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("column " + column + " (" + type + ") holds '" + abbreviate(cell)
                    + "', not a number: plot numeric or time columns only");
        }
    }

    /** Label lines, then the given rows (each already numbers). */
    static byte[] write(List<String> labels, List<double[]> rows) {
        StringBuilder b = new StringBuilder(rows.size() * 40 + 256);
        for (String l : labels) {
            b.append("% ").append(l.replaceAll("\\p{Cntrl}", " ")).append('\n');
        }
        for (double[] r : rows) {
            for (int i = 0; i < r.length; i++) {
                if (i > 0) {
                    b.append(' ');
                }
                double v = r[i];
                if (Double.isNaN(v)) {
                    b.append("NaN");
                } else if (v == Math.rint(v) && Math.abs(v) < 1e15) {
                    b.append((long) v);
                } else {
                    b.append(v);
                }
            }
            b.append('\n');
        }
        return b.toString().getBytes(StandardCharsets.UTF_8);
    }

    /** Every column of a table as numbers. */
    static List<double[]> numbers(TableResult t) {
        int n = t.columns().size();
        return t.rows().stream().map(row -> {
            double[] out = new double[n];
            for (int i = 0; i < n; i++) {
                out[i] = number(row[i], t.types().get(i), t.columns().get(i));
            }
            return out;
        }).toList();
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
