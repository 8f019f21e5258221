package org.ripv.services.serial.ymodem;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * The names an operator asked a vehicle to send ({@code ymodem:get MISSION1.LOG *.DBD}) and the
 * check that what the vehicle's block 0 named is one of them. A vehicle does not choose the name
 * a file is stored under: a file that was not asked for is refused, and one that matches an asked
 * name in a different case is stored under the operator's spelling.
 */
public final class AskedNames {
    /** A file received and the name it is to be stored under. */
    public record Accepted(FileHeader file, String storedName) {}

    /** What the check made of a batch: the files to keep and a warning for each one refused. */
    public record Verdict(List<Accepted> accepted, List<String> warnings) {}

    private final List<String> asked;

    public AskedNames(List<String> asked) {
        this.asked = List.copyOf(asked);
    }

    /** Sorts a received batch into the files asked for and warnings about the rest. */
    public Verdict check(List<FileHeader> received) {
        List<Accepted> accepted = new ArrayList<>();
        List<String> warnings = new ArrayList<>();
        List<String> taken = new ArrayList<>();
        for (FileHeader f : received) {
            String stored = storedName(f.name());
            if (stored == null) {
                warnings.add("the vehicle sent '" + f.name() + "', which was not asked for; refused (not stored)");
            } else if (taken.contains(stored.toLowerCase(Locale.ROOT))) {
                warnings.add("the vehicle sent '" + f.name() + "' more than once; one copy is kept");
            } else {
                taken.add(stored.toLowerCase(Locale.ROOT));
                accepted.add(new Accepted(f, stored));
            }
        }
        return new Verdict(accepted, warnings);
    }

    /** The name to store a sent file under, or null when nothing asked for it. */
    String storedName(String sent) {
        for (String a : asked) {
            if (isPattern(a)) {
                continue;
            }
            if (a.equalsIgnoreCase(sent)) {
                return a; // DOS file names ignore case; the operator's spelling wins
            }
        }
        for (String a : asked) {
            if (isPattern(a) && glob(a).matcher(sent).matches()) {
                return sent;
            }
        }
        return null;
    }

    private static boolean isPattern(String name) {
        return name.indexOf('*') >= 0 || name.indexOf('?') >= 0;
    }

    private static Pattern glob(String g) {
        StringBuilder re = new StringBuilder();
        for (char c : g.toCharArray()) {
            re.append(c == '*' ? "[^/\\\\]*" : c == '?' ? "[^/\\\\]" : Pattern.quote(String.valueOf(c)));
        }
        return Pattern.compile(re.toString(), Pattern.CASE_INSENSITIVE);
    }
}
