package org.ripv.text;

/**
 * Makes text safe to print to a terminal or a log: every control character but line feed and tab
 * — C0 (ESC, BEL, CR, backspace…), DEL, the C1 controls U+0080–U+009F (CSI, OSC…), the Unicode
 * line and paragraph separators and the bidirectional overrides — is shown as a visible escape.
 * Printable text is returned as it is (the same instance).
 */
public final class Printable {
    private Printable() {}

    /** The text with its non-printing characters shown ({@code ^[}, {@code \u009b}); line feeds and tabs kept. */
    public static String escape(String s) {
        if (s == null || clean(s, true)) {
            return s;
        }
        return escape(s, true);
    }

    /** As {@link #escape}, with line feeds shown as {@code \n} too: for one line of a log or a table. */
    public static String oneLine(String s) {
        if (s == null || clean(s, false)) {
            return s;
        }
        return escape(s, false);
    }

    /** True for a character {@link #escape} shows as an escape (line feed and tab aside). */
    public static boolean isHidden(char c) {
        return c < 0x20 && c != '\n' && c != '\t' || c >= 0x7f && c <= 0x9f || c == '\u2028' || c == '\u2029'
                || c >= '\u202a' && c <= '\u202e' || c >= '\u2066' && c <= '\u2069';
    }

    private static boolean clean(String s, boolean keepLines) {
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (isHidden(c) || !keepLines && c == '\n') {
                return false;
            }
        }
        return true;
    }

    private static String escape(String s, boolean keepLines) {
        StringBuilder b = new StringBuilder(s.length() + 16);
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\n' && !keepLines) {
                b.append("\\n");
            } else if (!isHidden(c)) {
                b.append(c);
            } else if (c == '\r') {
                b.append("\\r");
            } else if (c < 0x20) {
                b.append('^').append((char) (c + 64));
            } else {
                b.append(String.format("\\u%04x", (int) c));
            }
        }
        return b.toString();
    }
}
