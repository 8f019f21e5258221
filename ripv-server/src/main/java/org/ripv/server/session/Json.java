package org.ripv.server.session;

import java.util.LinkedHashMap;
import java.util.Map;
import org.ripv.json.JsonWriter;

/**
 * Flat JSON objects (strings, numbers, booleans, null) for the transcript and subscription
 * files: one object per line, written by {@link JsonWriter} and read back without a library. Parsing is strict and
 * treats the line as hostile: anything else is an {@link IllegalArgumentException}.
 */
public final class Json {
    private Json() {}

    /** Writes a flat object; values are String, Number, Boolean or null. */
    public static String write(Map<String, ?> fields) {
        return JsonWriter.write(fields);
    }

    public static void quote(StringBuilder b, String s) {
        JsonWriter.quote(b, s);
    }

    /** Reads a flat object: values come back as String, Double/Long, Boolean or null. */
    public static Map<String, Object> parse(String line) {
        Parser p = new Parser(line);
        Map<String, Object> out = p.object();
        p.skipSpace();
        if (p.i != line.length()) {
            throw new IllegalArgumentException("trailing characters at " + p.i);
        }
        return out;
    }

    private static final class Parser {
        private final String s;
        private int i;

        Parser(String s) {
            this.s = s;
        }

        void skipSpace() {
            while (i < s.length() && Character.isWhitespace(s.charAt(i))) {
                i++;
            }
        }

        char next() {
            if (i >= s.length()) {
                throw new IllegalArgumentException("unexpected end");
            }
            return s.charAt(i++);
        }

        void expect(char c) {
            skipSpace();
            if (next() != c) {
                throw new IllegalArgumentException("expected '" + c + "' at " + (i - 1));
            }
        }

        Map<String, Object> object() {
            Map<String, Object> m = new LinkedHashMap<>();
            expect('{');
            skipSpace();
            if (i < s.length() && s.charAt(i) == '}') {
                i++;
                return m;
            }
            while (true) {
                skipSpace();
                String key = string();
                expect(':');
                skipSpace();
                m.put(key, value());
                skipSpace();
                char c = next();
                if (c == '}') {
                    return m;
                }
                if (c != ',') {
                    throw new IllegalArgumentException("expected ',' or '}' at " + (i - 1));
                }
            }
        }

        Object value() {
            if (i >= s.length()) {
                throw new IllegalArgumentException("unexpected end");
            }
            char c = s.charAt(i);
            if (c == '"') {
                return string();
            }
            if (s.startsWith("null", i)) {
                i += 4;
                return null;
            }
            if (s.startsWith("true", i)) {
                i += 4;
                return Boolean.TRUE;
            }
            if (s.startsWith("false", i)) {
                i += 5;
                return Boolean.FALSE;
            }
            int start = i;
            while (i < s.length() && "+-0123456789.eE".indexOf(s.charAt(i)) >= 0) {
                i++;
            }
            String n = s.substring(start, i);
            if (n.isEmpty() || n.length() > 40) {
                throw new IllegalArgumentException("bad value at " + start);
            }
            try {
                if (n.matches("-?\\d{1,19}")) {
                    try {
                        return Long.parseLong(n);
                    } catch (NumberFormatException tooBig) {
                        return Double.parseDouble(n);
                    }
                }
                return Double.parseDouble(n);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("bad number '" + n + "'");
            }
        }

        String string() {
            if (next() != '"') {
                throw new IllegalArgumentException("expected a string at " + (i - 1));
            }
            StringBuilder b = new StringBuilder();
            while (true) {
                char c = next();
                if (c == '"') {
                    return b.toString();
                }
                if (c != '\\') {
                    b.append(c);
                    continue;
                }
                char e = next();
                switch (e) {
                    case '"', '\\', '/' -> b.append(e);
                    case 'n' -> b.append('\n');
                    case 'r' -> b.append('\r');
                    case 't' -> b.append('\t');
                    case 'b' -> b.append('\b');
                    case 'f' -> b.append('\f');
                    case 'u' -> {
                        if (i + 4 > s.length()) {
                            throw new IllegalArgumentException("short \\u escape");
                        }
                        try {
                            b.append((char) Integer.parseInt(s.substring(i, i + 4), 16));
                        } catch (NumberFormatException x) {
                            throw new IllegalArgumentException("bad \\u escape");
                        }
                        i += 4;
                    }
                    default -> throw new IllegalArgumentException("bad escape \\" + e);
                }
            }
        }
    }
}
