package org.ripv.server.files;

/**
 * The rules for a file name a client or service may give (the thesis's CGI script, appendix D):
 * one path element, no slashes or backslashes, no leading dot, no control characters (C0, DEL, C1,
 * line separators) nor bidirectional controls, at most
 * 255 characters.
 */
public final class FileNames {
    public static final int MAX_LENGTH = 255;

    private FileNames() {}

    /** Returns the name, or throws with a message that quotes it and says what is wrong. */
    public static String check(String name) {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException("a file name is required");
        }
        String shown = printable(name);
        if (name.length() > MAX_LENGTH) {
            throw new IllegalArgumentException("file name '" + shown.substring(0, 40) + "...' is " + name.length()
                    + " characters long; at most " + MAX_LENGTH + " are allowed");
        }
        if (name.indexOf('/') >= 0 || name.indexOf('\\') >= 0) {
            throw new IllegalArgumentException("file name '" + shown + "' contains a slash; give a plain name, no directories");
        }
        if (name.startsWith(".")) {
            throw new IllegalArgumentException("file name '" + shown + "' starts with a dot; hidden files are not allowed");
        }
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            if (c < 0x20 || c >= 0x7f && c <= 0x9f || c == 0x2028 || c == 0x2029) {
                throw new IllegalArgumentException("file name '" + shown + "' contains a control character (code " + (int) c + ")");
            }
            if (isBidiControl(c)) {
                // U+202E shows 'evil\u202Efdp.exe' as 'evilexe.pdf' in listings (issue 33 item 10)
                throw new IllegalArgumentException("file name '" + shown + "' contains a bidirectional control character (U+"
                        + String.format("%04X", (int) c) + "), which makes a name look like another");
            }
        }
        if (name.equals("~") || name.isBlank() || name.contains(":")) {
            throw new IllegalArgumentException("file name '" + shown + "' is not allowed");
        }
        return name;
    }

    /** The embeddings, overrides and isolates (U+202A–202E, U+2066–2069) and the marks (U+200E, U+200F, U+061C). */
    static boolean isBidiControl(char c) {
        return c >= 0x202a && c <= 0x202e || c >= 0x2066 && c <= 0x2069 || c == 0x200e || c == 0x200f || c == 0x061c;
    }

    private static String printable(String s) {
        StringBuilder b = new StringBuilder();
        for (char c : s.toCharArray()) {
            b.append(c < 0x20 || c >= 0x7f && c <= 0x9f || c == 0x2028 || c == 0x2029 || isBidiControl(c) ? '?' : c);
        }
        return b.toString();
    }
}
