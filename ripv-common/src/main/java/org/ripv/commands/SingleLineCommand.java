package org.ripv.commands;

/**
 * The rule that a command is one line of text (docs/security.md): no control character other
 * than tab — no CR, LF, NUL, ^C, ESC, DEL, nor a C1 control (U+0080–U+009F), nor the Unicode
 * line and paragraph separators — and no longer than a limit. A CR inside {@code dir\rGO} would
 * otherwise make a vehicle run a second command that no permit rule was asked about; a ^C or ESC
 * would interrupt whatever the vehicle is doing.
 *
 * <pre>{@code
 * SingleLineCommand.check(body, SingleLineCommand.SERVER_MAX);   // throws IllegalArgumentException
 * }</pre>
 */
public final class SingleLineCommand {
    /** The per-link default of the SerialPortServer ({@code maxcommand=}). */
    public static final int DEFAULT_MAX = 1024;
    /** The server's cap on any command it routes to a service, whatever a link allows. */
    public static final int SERVER_MAX = 16 * 1024;

    private SingleLineCommand() {}

    /**
     * Returns {@code command} if it is one line of at most {@code maxLength} characters.
     *
     * @throws IllegalArgumentException saying what is wrong, quoting at most the start of the command
     *                                  with its control characters made visible
     */
    public static String check(String command, int maxLength) {
        if (command == null) {
            throw new IllegalArgumentException("no command");
        }
        if (command.length() > maxLength) {
            throw new IllegalArgumentException("the command '" + shown(command) + "' is " + command.length()
                    + " characters long; at most " + maxLength + " are allowed");
        }
        int bad = firstControl(command);
        if (bad >= 0) {
            throw new IllegalArgumentException("the command '" + shown(command) + "' contains a control character ("
                    + name(command.charAt(bad)) + " at position " + (bad + 1) + "); a command is one line of text,"
                    + " and interrupting a vehicle is not done with bytes inside a command");
        }
        return command;
    }

    /** The index of the first character {@link #check} refuses, or -1. */
    public static int firstControl(CharSequence s) {
        for (int i = 0; i < s.length(); i++) {
            if (isRefused(s.charAt(i))) {
                return i;
            }
        }
        return -1;
    }

    /** True for every character a command may not hold: C0 but tab, DEL, C1, U+2028, U+2029. */
    public static boolean isRefused(char c) {
        return c < 0x20 && c != '\t' || c >= 0x7f && c <= 0x9f || c == '\u2028' || c == '\u2029';
    }

    /** The start of a text for a log or a message: at most 80 characters, controls shown as {@code \r}, {@code ^C}, {@code \x1b}. */
    public static String shown(String s) {
        if (s.length() <= 77 && firstControl(s) < 0 && s.indexOf('\t') < 0) {
            return s; // nothing to shorten or make visible: the common case, without a copy
        }
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            if (b.length() >= 77) {
                return b.append("...").toString();
            }
            char c = s.charAt(i);
            if (isRefused(c) || c == '\t') {
                b.append(visible(c));
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }

    private static String visible(char c) {
        return switch (c) {
            case '\r' -> "\\r";
            case '\n' -> "\\n";
            case '\t' -> "\\t";
            case 0 -> "\\0";
            default -> c < 0x20 ? "^" + (char) (c + 64) : String.format("\\u%04x", (int) c);
        };
    }

    private static String name(char c) {
        return switch (c) {
            case '\r' -> "CR";
            case '\n' -> "LF";
            case 0 -> "NUL";
            case 0x1b -> "ESC";
            case 0x7f -> "DEL";
            default -> c < 0x20 ? "^" + (char) (c + 64) : String.format("U+%04X", (int) c);
        };
    }
}
