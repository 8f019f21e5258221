package org.ripv.surfacing;

import java.time.Duration;
import java.time.format.DateTimeParseException;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * How often a vehicle is expected to call: written as {@code 90s}, {@code 10m}, {@code 2h},
 * {@code 1d} (or ISO-8601, {@code PT2H}) in a link's {@code overdue=} and the server's alert rules,
 * and announced by the SerialPortServer in its SURFACED text ({@code … (calls expected every 7200 s)})
 * so the server, which raises OVERDUE, knows the link's setting. Both sides read it here.
 */
public final class CallInterval {
    private static final Pattern SHORT = Pattern.compile("(\\d{1,9})(ms|s|m|h|d)");
    private static final Pattern ANNOUNCED = Pattern.compile("\\(calls expected every (\\d{1,12}) s\\)");

    private CallInterval() {
    }

    /** A positive duration; throws with the text quoted when it is none. */
    public static Duration parse(String text) {
        String s = text.strip().toLowerCase(Locale.ROOT);
        Matcher m = SHORT.matcher(s);
        Duration d;
        if (m.matches()) {
            long n = Long.parseLong(m.group(1));
            d = switch (m.group(2)) {
                case "ms" -> Duration.ofMillis(n);
                case "s" -> Duration.ofSeconds(n);
                case "m" -> Duration.ofMinutes(n);
                case "h" -> Duration.ofHours(n);
                default -> Duration.ofDays(n);
            };
        } else {
            try {
                d = Duration.parse(text.strip());
            } catch (DateTimeParseException e) {
                throw new IllegalArgumentException("not a duration: '" + text + "' (e.g. 90s, 10m, 2h, 1d)");
            }
        }
        if (d.isNegative() || d.isZero()) {
            throw new IllegalArgumentException("a duration must be positive: '" + text + "'");
        }
        return d;
    }

    /** What SURFACED says of a link's interval. */
    public static String announce(Duration every) {
        return "(calls expected every " + Math.max(1, every.toSeconds()) + " s)";
    }

    /** The interval a SURFACED text announces, if it does. */
    public static Optional<Duration> announced(String surfacedText) {
        Matcher m = ANNOUNCED.matcher(surfacedText);
        return m.find() ? Optional.of(Duration.ofSeconds(Long.parseLong(m.group(1)))) : Optional.empty();
    }
}
