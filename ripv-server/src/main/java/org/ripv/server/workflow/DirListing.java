package org.ripv.server.workflow;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** Reading a vehicle's {@code dir} listing, and the globs {@code ymodem:get} matches against it. */
final class DirListing {
    /** The vehicle command that lists its files for {@code ymodem:get} globs. */
    static final String LIST_COMMAND = "dir";
    /** A PicoDOS/Slocum {@code dir} line: name, size, then date and time. */
    private static final Pattern DIR_LINE = Pattern.compile("^\\s*([^\\s/\\\\]+)\\s+(\\d+)\\s+\\S+\\s+\\S+\\s*$");

    private DirListing() {}

    /** The files of a {@code dir} listing, name to size; lines that are not a file are skipped. */
    static Map<String, Long> listing(String text) {
        Map<String, Long> out = new LinkedHashMap<>();
        for (String line : text.split("\r?\n")) {
            Matcher m = DIR_LINE.matcher(line);
            if (m.matches() && m.group(2).length() <= 18) {
                out.put(m.group(1), Long.parseLong(m.group(2)));
            }
        }
        return out;
    }

    static boolean isGlob(String name) {
        return name.indexOf('*') >= 0 || name.indexOf('?') >= 0;
    }

    /** {@code *} any run, {@code ?} one character, case-insensitive (PicoDOS names are). */
    static Pattern glob(String g) {
        StringBuilder b = new StringBuilder();
        for (char c : g.toCharArray()) {
            if (c == '*') {
                b.append(".*");
            } else if (c == '?') {
                b.append('.');
            } else {
                b.append(Pattern.quote(String.valueOf(c)));
            }
        }
        return Pattern.compile(b.toString(), Pattern.CASE_INSENSITIVE);
    }
}
