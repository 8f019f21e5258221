package org.ripv.messages;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;

/**
 * A console entry as flat JSON fields (time, mailbox, kind, user, text, event, lat, lon; only
 * those that apply): one rule for the CLI's {@code --follow --json} lines and the server's
 * transcript, so that both read the same.
 */
public final class ConsoleFields {
    private ConsoleFields() {}

    /** The entry's fields, with {@code text} standing for its text (the transcript keeps a cut one). */
    public static Map<String, Object> of(ConsoleEntry e, String text) {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("time", Instant.ofEpochMilli(e.time()).toString());
        m.put("mailbox", e.mailbox());
        m.put("kind", e.kind().name().toLowerCase(Locale.ROOT));
        if (!e.user().isEmpty()) {
            m.put("user", e.user());
        }
        m.put("text", text);
        if (e.event() != null) {
            m.put("event", e.event().name());
        }
        if (e.lat() != null && e.lon() != null && Double.isFinite(e.lat()) && Double.isFinite(e.lon())) {
            m.put("lat", e.lat());
            m.put("lon", e.lon());
        }
        return m;
    }
}
