package org.ripv.server.notify;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.ripv.json.Json;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.session.Entries;

/** What a notification says: the webhook's JSON body, the e-mail's subject and text. */
final class NoticeTexts {
    private NoticeTexts() {}

    /** The e-mail's subject: {@code [RIPV] ru29 SURFACED}. */
    static String subject(ConsoleHub.Notice n) {
        return "[RIPV] " + vehicle(n.event().mailbox()) + " " + n.event().event();
    }

    static String vehicle(String mailbox) {
        int at = mailbox.lastIndexOf('>');
        return at >= 0 && at < mailbox.length() - 1 ? mailbox.substring(at + 1) : mailbox;
    }

    static String webhookBody(Subscription s, ConsoleHub.Notice n) {
        ConsoleEntry e = n.event();
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("subscription", s.id);
        m.put("time", Instant.ofEpochMilli(e.time()).toString());
        m.put("mailbox", e.mailbox());
        m.put("vehicle", vehicle(e.mailbox()));
        m.put("event", e.event().name());
        m.put("text", e.text());
        if (!e.user().isEmpty()) {
            m.put("user", e.user());
        }
        SessionState st = n.state();
        Double lat = e.lat() != null ? e.lat() : st == null ? null : st.lat();
        Double lon = e.lon() != null ? e.lon() : st == null ? null : st.lon();
        if (lat != null && lon != null) {
            m.put("lat", lat);
            m.put("lon", lon);
        }
        if (st != null) {
            m.put("state", st.state().name().toLowerCase(Locale.ROOT));
            m.put("calls", st.calls());
            if (st.lastContact() > 0) {
                m.put("lastContact", Instant.ofEpochMilli(st.lastContact()).toString());
            }
        }
        return Json.write(m);
    }

    static String mailBody(ConsoleHub.Notice n) {
        ConsoleEntry e = n.event();
        SessionState st = n.state();
        StringBuilder b = new StringBuilder();
        b.append("Vehicle:  ").append(vehicle(e.mailbox())).append('\n');
        b.append("MailBox:  ").append(e.mailbox()).append('\n');
        b.append("Event:    ").append(e.event()).append(e.text().isEmpty() ? "" : " (" + e.text() + ")").append('\n');
        b.append("Time:     ").append(Instant.ofEpochMilli(e.time())).append('\n');
        Double lat = e.lat() != null ? e.lat() : st == null ? null : st.lat();
        Double lon = e.lon() != null ? e.lon() : st == null ? null : st.lon();
        b.append("Position: ").append(lat != null && lon != null
                ? String.format(Locale.ROOT, "%.5f, %.5f", lat, lon) : "unknown").append('\n');
        if (st != null) {
            b.append("State:    ").append(st.state().words()).append(", ").append(st.calls()).append(" call(s)");
            if (st.lastContact() > 0) {
                b.append(", last contact ").append(Instant.ofEpochMilli(st.lastContact()));
            }
            b.append('\n');
        }
        List<ConsoleEntry> lines = new ArrayList<>(n.lastLines());
        if (!lines.isEmpty()) {
            b.append("\nLast lines:\n");
            lines.forEach(l -> b.append("  ").append(Entries.toText(l)).append('\n'));
        }
        b.append("\n-- RIPV (?notify list shows your subscriptions; ?notify remove ID ends one)\n");
        return b.toString();
    }
}
