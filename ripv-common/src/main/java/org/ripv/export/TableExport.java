package org.ripv.export;

import java.math.BigDecimal;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.ripv.json.Json;
import org.ripv.messages.TableResult;

/**
 * A query's table as CSV (RFC 4180: a header line, fields quoted when they need it, SQL NULL as
 * an empty field) or JSON ({@code {"query", "columns", "types", "truncated", "rows": [{COLUMN: value}]}},
 * numbers of numeric SQL types as JSON numbers, NULL as null). The CLI's {@code export} writes the
 * last table it received with it, the GUI's DAB panel the table in its tab.
 */
public final class TableExport {
    private static final Set<String> NUMERIC = Set.of("SMALLINT", "INTEGER", "INT", "BIGINT", "DECIMAL", "NUMERIC",
            "REAL", "FLOAT", "DOUBLE", "DOUBLE PRECISION", "INT2", "INT4", "INT8", "FLOAT4", "FLOAT8", "SERIAL",
            "BIGSERIAL", "TINYINT");

    private TableExport() {}

    /** The whole table, header first, CRLF line ends, SQL NULL as an empty field. */
    public static String csv(TableResult t) {
        StringBuilder b = new StringBuilder();
        line(b, t.columns());
        for (String[] row : t.rows()) {
            line(b, Arrays.asList(row));
        }
        return b.toString();
    }

    /** One CSV line of fields and CRLF. */
    static void line(StringBuilder b, List<String> fields) {
        for (int i = 0; i < fields.size(); i++) {
            if (i > 0) {
                b.append(',');
            }
            b.append(field(fields.get(i)));
        }
        b.append("\r\n");
    }

    /**
     * One CSV field: null (SQL NULL) is empty; an empty text, and one with a comma, quote, line
     * break or leading or trailing blank, is quoted (so "" and NULL stay apart, and spaces survive).
     */
    public static String field(String f) {
        if (f == null) {
            return "";
        }
        if (f.isEmpty() || f.indexOf(',') >= 0 || f.indexOf('"') >= 0 || f.indexOf('\n') >= 0 || f.indexOf('\r') >= 0
                || Character.isWhitespace(f.charAt(0)) || Character.isWhitespace(f.charAt(f.length() - 1))) {
            return '"' + f.replace("\"", "\"\"") + '"';
        }
        return f;
    }

    /** The whole table as one JSON object, numbers of numeric columns as numbers, NULL as null, a newline at the end. */
    public static String json(TableResult t) {
        List<Map<String, Object>> rows = new ArrayList<>(t.rows().size());
        for (String[] row : t.rows()) {
            Map<String, Object> o = new LinkedHashMap<>();
            for (int i = 0; i < row.length; i++) {
                o.put(t.columns().get(i), value(row[i], t.types().get(i)));
            }
            rows.add(o);
        }
        Map<String, Object> doc = new LinkedHashMap<>();
        doc.put("query", t.query());
        doc.put("columns", t.columns());
        doc.put("types", t.types());
        doc.put("truncated", t.truncated());
        doc.put("rows", rows);
        return Json.write(doc) + "\n";
    }

    /** A number for a numeric column (as the database wrote it, exactly), else the text; null stays null. */
    public static Object value(String cell, String type) {
        if (cell == null) {
            return null;
        }
        if (NUMERIC.contains(type.toUpperCase(Locale.ROOT))) {
            try {
                return new BigDecimal(cell.strip());
            } catch (NumberFormatException e) {
                return cell; // NaN or Infinity from a database that allows them: JSON has no number for those
            }
        }
        return cell;
    }
}
