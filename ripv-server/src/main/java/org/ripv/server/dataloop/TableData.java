package org.ripv.server.dataloop;

import java.nio.charset.StandardCharsets;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.ripv.messages.TableResult;

/**
 * A query's table as the DataVisServer's data file (docs/datavis.md): {@code %} label lines, then
 * one row of numbers per table row. Numbers stay numbers — the database's own text, checked but
 * not converted, so 100,000 rows cost a scan rather than a parse and a format each — timestamps
 * become epoch seconds (UTC), SQL NULL and NaN become NaN (a gap), infinities Inf/-Inf; any other
 * text is refused with the column's name.
 */
final class TableData {
    private TableData() {}

    /** Whether a column of this SQL type is a time. */
    static boolean isTime(String type) {
        String t = type.toUpperCase(Locale.ROOT);
        return t.startsWith("TIMESTAMP") || t.equals("DATE");
    }

    /** A cell as a data-file number: the decimal as it is, epoch seconds for a time, NaN for null. */
    static String token(String cell, String type, String column) {
        if (cell == null) {
            return "NaN";
        }
        if (isTime(type)) {
            try {
                String c = cell.strip().replace(' ', 'T');
                LocalDateTime t = c.length() == 10 ? LocalDateTime.parse(c + "T00:00:00") : LocalDateTime.parse(c);
                return seconds(t.toEpochSecond(ZoneOffset.UTC), t.getNano());
            } catch (DateTimeParseException e) {
                throw new IllegalArgumentException("column " + column + ": '" + cell + "' is not a time");
            }
        }
        String c = cell.strip();
        if (isDecimal(c)) {
            return c;
        }
        switch (c) {
            case "NaN" -> {
                return "NaN";
            }
            case "Infinity" -> {
                return "Inf";
            }
            case "-Infinity" -> {
                return "-Inf";
            }
            default -> throw new IllegalArgumentException("column " + column + " (" + type + ") holds '" + abbreviate(cell)
                    + "', not a number: plot numeric or time columns only");
        }
    }

    /** A cell as a number: epoch seconds for a time, NaN for null. */
    static double number(String cell, String type, String column) {
        String t = token(cell, type, column);
        return switch (t) {
            case "Inf" -> Double.POSITIVE_INFINITY;
            case "-Inf" -> Double.NEGATIVE_INFINITY;
            default -> Double.parseDouble(t);
        };
    }

    /** Whole seconds and nanoseconds as an exact decimal: 1452705611.24094. */
    static String seconds(long seconds, int nanos) {
        if (nanos == 0) {
            return Long.toString(seconds);
        }
        // before 1970 the fraction counts up from a whole second below: -1.75 s is (-2, 250,000,000)
        boolean negative = seconds < 0;
        long whole = negative ? -(seconds + 1) : seconds;
        int fraction = negative ? 1_000_000_000 - nanos : nanos;
        String f = String.format(Locale.ROOT, "%09d", fraction).replaceFirst("0+$", "");
        return (negative ? "-" : "") + whole + "." + f;
    }

    /** [+-] digits [. digits] or [+-] . digits, then optionally [eE] [+-] digits: what Double.toString and SQL write. */
    static boolean isDecimal(String s) {
        int n = s.length();
        int i = 0;
        if (i < n && (s.charAt(i) == '-' || s.charAt(i) == '+')) {
            i++;
        }
        int digits = 0;
        while (i < n && s.charAt(i) >= '0' && s.charAt(i) <= '9') {
            i++;
            digits++;
        }
        if (i < n && s.charAt(i) == '.') {
            i++;
            while (i < n && s.charAt(i) >= '0' && s.charAt(i) <= '9') {
                i++;
                digits++;
            }
        }
        if (digits == 0) {
            return false;
        }
        if (i < n && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            i++;
            if (i < n && (s.charAt(i) == '-' || s.charAt(i) == '+')) {
                i++;
            }
            int exp = 0;
            while (i < n && s.charAt(i) >= '0' && s.charAt(i) <= '9') {
                i++;
                exp++;
            }
            return exp > 0 && i == n;
        }
        return i == n;
    }

    /** Label lines, then the given rows (each already data-file numbers). */
    static byte[] write(List<String> labels, List<String[]> rows) {
        StringBuilder b = new StringBuilder(rows.size() * 32 + 256);
        for (String l : labels) {
            b.append("% ").append(l.replaceAll("\\p{Cntrl}", " ")).append('\n');
        }
        for (String[] r : rows) {
            for (int i = 0; i < r.length; i++) {
                if (i > 0) {
                    b.append(' ');
                }
                b.append(r[i]);
            }
            b.append('\n');
        }
        return b.toString().getBytes(StandardCharsets.UTF_8);
    }

    /** Every column of a table as data-file numbers. */
    static List<String[]> tokens(TableResult t) {
        int n = t.columns().size();
        List<String[]> out = new ArrayList<>(t.rows().size());
        for (String[] row : t.rows()) {
            String[] r = new String[n];
            for (int i = 0; i < n; i++) {
                r[i] = token(row[i], t.types().get(i), t.columns().get(i));
            }
            out.add(r);
        }
        return out;
    }

    private static String abbreviate(String s) {
        return s.length() <= 40 ? s : s.substring(0, 37) + "...";
    }
}
