package org.ripv.messages;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Locale;

/**
 * How a console entry reads for people, the one rule for the GUI's console, the CLI's
 * {@code --follow} and the server's {@code ?history} and notification texts: its time, then the
 * vehicle's line, {@code > command} (with {@code [user]}), {@code ~ transfer} or
 * {@code * EVENT by user text (lat, lon)}.
 */
public final class ConsoleLines {
    private static final DateTimeFormatter CLOCK = DateTimeFormatter.ofPattern("HH:mm:ss", Locale.ROOT).withZone(ZoneOffset.UTC);

    private ConsoleLines() {}

    /** {@code 2026-11-23T14:02:03Z  > dir}: the whole time, for logs, transcripts and the CLI. */
    public static String withInstant(ConsoleEntry e) {
        return render(e, Instant.ofEpochMilli(e.time()).toString(), true);
    }

    /** {@code 14:02:03  > dir}: the time of day (UTC), for a console window. */
    public static String withClock(ConsoleEntry e) {
        return render(e, CLOCK.format(Instant.ofEpochMilli(e.time())), true);
    }

    /** As {@link #withInstant}, with an event's user left out (the server's {@code ?history} and notification texts). */
    public static String withInstantNoEventUser(ConsoleEntry e) {
        return render(e, Instant.ofEpochMilli(e.time()).toString(), false);
    }

    private static String render(ConsoleEntry e, String time, boolean eventUser) {
        return switch (e.kind()) {
            case LINE -> time + "  " + e.text();
            case COMMAND -> time + "  " + (e.user().isEmpty() ? "" : "[" + e.user() + "] ") + "> " + e.text();
            case TRANSFER -> time + "  ~ " + e.text();
            case EVENT -> time + "  * " + e.event() + (!eventUser || e.user().isEmpty() ? "" : " by " + e.user())
                    + (e.text().isEmpty() ? "" : " " + e.text())
                    + (e.lat() != null && e.lon() != null ? String.format(Locale.ROOT, " (%.5f, %.5f)", e.lat(), e.lon()) : "");
        };
    }
}
