package org.ripv.server.session;

import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.Locale;
import java.util.Map;
import org.ripv.json.Json;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ConsoleFields;
import org.ripv.messages.ConsoleLines;
import org.ripv.messages.VehicleEvent;

/**
 * Console entries as flat JSON fields — the same names the CLI's {@code --follow --json} prints
 * (time, mailbox, kind, user, text, event, lat, lon; only those that apply) — and back.
 */
public final class Entries {
    /** The longest text kept per entry in the transcript; longer text is cut and says so. */
    public static final int MAX_TEXT = 4096;

    private Entries() {}

    public static Map<String, Object> toMap(ConsoleEntry e) {
        String text = e.text();
        if (text.length() > MAX_TEXT) {
            text = text.substring(0, MAX_TEXT) + " [cut: " + (e.text().length() - MAX_TEXT) + " more characters]";
        }
        return ConsoleFields.of(e, text);
    }

    public static String toJson(ConsoleEntry e) {
        return Json.write(toMap(e));
    }

    /** Reads back a transcript line; throws IllegalArgumentException for anything malformed. */
    public static ConsoleEntry fromJson(String line) {
        Map<String, Object> m = Json.parse(line);
        long time;
        try {
            time = Instant.parse(string(m, "time")).toEpochMilli();
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("bad time");
        }
        ConsoleEntry.Kind kind = ConsoleEntry.Kind.valueOf(string(m, "kind").toUpperCase(Locale.ROOT));
        String event = m.get("event") instanceof String s ? s : null;
        return new ConsoleEntry(time, string(m, "mailbox"), kind, m.get("user") instanceof String u ? u : "",
                m.get("text") instanceof String t ? t : "", event == null ? null : VehicleEvent.valueOf(event),
                number(m.get("lat")), number(m.get("lon")));
    }

    private static String string(Map<String, Object> m, String key) {
        if (!(m.get(key) instanceof String s)) {
            throw new IllegalArgumentException("no " + key);
        }
        return s;
    }

    private static Double number(Object o) {
        return o instanceof Number n ? n.doubleValue() : null;
    }

    /** The entry for people: {@code 2026-11-23T14:02:03Z ru29 [alice] > GPS Location ...}. */
    public static String toText(ConsoleEntry e) {
        return ConsoleLines.withInstantNoEventUser(e);
    }
}
