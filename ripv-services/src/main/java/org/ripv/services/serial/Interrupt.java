package org.ripv.services.serial;

import java.util.Locale;

/**
 * A link's interrupt ({@code interrupt=} in a {@code --link} spec): the keys {@code ?cancel}
 * writes to stop a running plain command. Written as caret notation ({@code ^C}, {@code ^X^C}),
 * {@code \xNN} escapes, plain characters, or a mix; {@code none} for a vehicle with no
 * interrupt (its plain commands cannot be cancelled). Kept as ISO-8859-1 text: one char a byte.
 */
final class Interrupt {
    /** Ctrl-C, what PicoDOS, Slocum's GliderDOS and most shells stop a command with. */
    static final String CTRL_C = "\u0003";

    private Interrupt() {}

    /** The keys an {@code interrupt=} value stands for; empty for {@code none}. */
    static String parse(String spec) {
        if (spec.isEmpty()) {
            throw new IllegalArgumentException("interrupt= is empty; give e.g. ^C, \\x03, or none");
        }
        if (spec.equalsIgnoreCase("none")) {
            return "";
        }
        StringBuilder keys = new StringBuilder();
        for (int i = 0; i < spec.length(); i++) {
            char c = spec.charAt(i);
            if (c == '^' && i + 1 < spec.length()) {
                char k = Character.toUpperCase(spec.charAt(++i));
                if (k < '@' || k > '_') {
                    throw new IllegalArgumentException("interrupt '" + spec + "': ^" + spec.charAt(i)
                            + " is not a control key (^@ to ^_, e.g. ^C)");
                }
                keys.append((char) (k - '@'));
            } else if (c == '\\' && i + 3 < spec.length() && spec.charAt(i + 1) == 'x') {
                try {
                    keys.append((char) Integer.parseInt(spec.substring(i + 2, i + 4), 16));
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException("interrupt '" + spec + "': " + spec.substring(i, i + 4)
                            + " is not a \\xNN escape");
                }
                i += 3;
            } else if (c < 0x20 || c > 0xff) {
                throw new IllegalArgumentException("interrupt '" + spec + "': write control keys as ^C or \\x03");
            } else {
                keys.append(c);
            }
        }
        if (keys.length() > 16) {
            throw new IllegalArgumentException("interrupt '" + spec + "' is longer than 16 keys");
        }
        return keys.toString();
    }

    /** The keys as an operator reads them: {@code ^C}, {@code none}. */
    static String describe(String keys) {
        if (keys.isEmpty()) {
            return "none";
        }
        StringBuilder b = new StringBuilder();
        for (char c : keys.toCharArray()) {
            if (c < 0x20) {
                b.append('^').append((char) (c + '@'));
            } else if (c == 0x7f || c > 0x7e) {
                b.append(String.format(Locale.ROOT, "\\x%02x", (int) c));
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }
}
