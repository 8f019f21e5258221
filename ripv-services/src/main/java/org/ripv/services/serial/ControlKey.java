package org.ripv.services.serial;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * One control key a pilot may press on a vehicle ({@code ?key MAILBOX ctrl-c}): its name as
 * operators write it and the byte it sends. Names are {@code ctrl-a} … {@code ctrl-z}.
 *
 * @param name the key's name, lower case ({@code ctrl-c})
 * @param code the byte written to the link (0x03)
 */
public record ControlKey(String name, byte code) {
    /** Every link allows these unless its {@code keys=} says otherwise: Slocum's surfacing dialog. */
    static final String DEFAULT_KEYS = "ctrl-c,ctrl-r,ctrl-e,ctrl-f";
    private static final Pattern NAME = Pattern.compile("ctrl-[a-z]");

    /** The key named {@code name} ({@code ctrl-c}, {@code Ctrl-C}). */
    static ControlKey parse(String name) {
        String n = name.trim().toLowerCase(Locale.ROOT);
        if (!NAME.matcher(n).matches()) {
            throw new IllegalArgumentException("'" + name + "' is not a control key; name one as ctrl-a … ctrl-z, e.g. ctrl-c");
        }
        return new ControlKey(n, (byte) (n.charAt(5) - 'a' + 1));
    }

    /** A {@code keys=} value: names separated by commas (or {@code |}, as a {@code --link} spec needs), or {@code none}. */
    static List<ControlKey> parseList(String spec) {
        List<ControlKey> keys = new ArrayList<>();
        if (spec.isBlank()) {
            throw new IllegalArgumentException("keys= is empty; give e.g. ctrl-c|ctrl-r, or none");
        }
        if (spec.trim().equalsIgnoreCase("none")) {
            return keys;
        }
        for (String s : spec.split("[,|]")) {
            try {
                ControlKey k = parse(s);
                if (!keys.contains(k)) {
                    keys.add(k);
                }
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("keys '" + spec + "': " + e.getMessage());
            }
        }
        return List.copyOf(keys);
    }

    static String describe(List<ControlKey> keys) {
        return keys.isEmpty() ? "none" : String.join(", ", keys.stream().map(ControlKey::name).toList());
    }
}
