package org.ripv.client.cli;

import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;

/**
 * Table cells for {@code --json}: the services send every value as text, with its SQL type's name;
 * numbers become JSON numbers, booleans booleans, SQL NULL null, the rest stays text. Derby's and
 * PostgreSQL's type names both count.
 */
final class Cells {
    private static final Set<String> INTEGERS = Set.of("INTEGER", "INT", "SMALLINT", "TINYINT", "BIGINT",
            "INT2", "INT4", "INT8", "SERIAL", "BIGSERIAL", "SMALLSERIAL", "OID");
    private static final Set<String> DECIMALS = Set.of("DECIMAL", "NUMERIC", "DEC");
    private static final Set<String> FLOATS = Set.of("REAL", "FLOAT", "DOUBLE", "DOUBLE PRECISION", "FLOAT4", "FLOAT8");
    private static final Set<String> BOOLEANS = Set.of("BOOLEAN", "BOOL", "BIT");

    private Cells() {}

    static List<Object> row(List<String> types, String[] cells) {
        List<Object> out = new ArrayList<>(cells.length);
        for (int i = 0; i < cells.length; i++) {
            out.add(value(i < types.size() ? types.get(i) : "", cells[i]));
        }
        return out;
    }

    /** The cell as a JSON value: Long/BigInteger, BigDecimal, Double, Boolean, null or the text. */
    static Object value(String sqlType, String text) {
        if (text == null) {
            return null;
        }
        String type = sqlType == null ? "" : sqlType.strip().toUpperCase(Locale.ROOT);
        int paren = type.indexOf('(');
        if (paren > 0) {
            type = type.substring(0, paren).strip(); // NUMERIC(10,2)
        }
        String t = text.strip();
        try {
            if (INTEGERS.contains(type)) {
                BigInteger b = new BigInteger(t);
                return b.bitLength() < 64 ? (Object) b.longValue() : b;
            }
            if (DECIMALS.contains(type)) {
                return new BigDecimal(t);
            }
            if (FLOATS.contains(type)) {
                double d = Double.parseDouble(t);
                return Double.isFinite(d) ? (Object) d : text; // JSON has no NaN or Infinity
            }
        } catch (NumberFormatException e) {
            return text;
        }
        if (BOOLEANS.contains(type)) {
            switch (t.toLowerCase(Locale.ROOT)) {
                case "true", "t", "1" -> {
                    return Boolean.TRUE;
                }
                case "false", "f", "0" -> {
                    return Boolean.FALSE;
                }
                default -> {
                    return text;
                }
            }
        }
        return text;
    }
}
