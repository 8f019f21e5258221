package org.ripv.json;

import java.util.Arrays;
import java.util.Collection;
import java.util.Map;

/**
 * Just enough JSON writing for RIPV's one-object-per-line outputs, without a library: strings,
 * numbers, booleans, null, maps and collections. NaN and infinities become null (JSON has
 * neither), and every control character and U+2028/2029 is escaped, so one value is always one
 * line.
 */
public final class JsonWriter {
    private JsonWriter() {}

    /** The value as JSON text. */
    public static String write(Object value) {
        StringBuilder b = new StringBuilder(128);
        append(b, value);
        return b.toString();
    }

    private static void append(StringBuilder b, Object v) {
        if (v == null || v instanceof Double d && !Double.isFinite(d) || v instanceof Float f && !Float.isFinite(f)) {
            b.append("null");
        } else if (v instanceof String s) {
            quote(b, s);
        } else if (v instanceof Number || v instanceof Boolean) {
            b.append(v);
        } else if (v instanceof Map<?, ?> m) {
            b.append('{');
            boolean first = true;
            for (Map.Entry<?, ?> e : m.entrySet()) {
                if (!first) {
                    b.append(',');
                }
                first = false;
                quote(b, String.valueOf(e.getKey()));
                b.append(':');
                append(b, e.getValue());
            }
            b.append('}');
        } else if (v instanceof Collection<?> c) {
            b.append('[');
            boolean first = true;
            for (Object o : c) {
                if (!first) {
                    b.append(',');
                }
                first = false;
                append(b, o);
            }
            b.append(']');
        } else if (v instanceof Object[] a) {
            append(b, Arrays.asList(a));
        } else {
            quote(b, v.toString());
        }
    }

    /** Appends {@code s} as a JSON string. */
    public static void quote(StringBuilder b, String s) {
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20 || c >= 0x7f && c <= 0x9f || c == 0x2028 || c == 0x2029) { // DEL and C1 too: JSON lines reach terminals
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        b.append('"');
    }
}
