package org.ripv.server.store;

import java.io.IOException;
import java.time.Instant;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import java.util.List;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;

/**
 * {@code ?audit [--last N] [--since ISO-TIME]}: the admin's view of the audit trail, read from the
 * state store (files or PostgreSQL alike), oldest first. The caller has checked the user's right.
 */
public final class AuditCommand {
    /** Lines one reply carries at most. */
    public static final int MAX = 1000;
    static final int DEFAULT = 100;

    private AuditCommand() {}

    public static OutgoingServerMessage run(IncomingServerMessage request, String fid, String[] w, AuditTrail trail,
                                            StateStore store) throws IOException {
        int last = DEFAULT;
        long since = 0;
        for (int i = 1; i < w.length; i += 2) {
            if (i + 1 >= w.length) {
                throw new IllegalArgumentException(usage());
            }
            switch (w[i]) {
                case "--last" -> {
                    try {
                        last = Integer.parseInt(w[i + 1]);
                    } catch (NumberFormatException e) {
                        last = -1;
                    }
                    if (last < 1 || last > MAX) {
                        throw new IllegalArgumentException("--last takes 1-" + MAX + ", not '" + w[i + 1] + "'");
                    }
                }
                case "--since" -> since = time(w[i + 1]).toEpochMilli();
                default -> throw new IllegalArgumentException(usage());
            }
        }
        trail.sync(); // what happened just before (this admin's own log-in) is in it
        List<StateStore.AuditRecord> lines = store.readAudit(since, last);
        StringBuilder b = new StringBuilder(lines.isEmpty() ? "no audit lines" : lines.size() + " audit line(s), oldest first");
        for (StateStore.AuditRecord r : lines) {
            b.append('\n').append(Instant.ofEpochMilli(r.time())).append(r.warn() ? " WARN " : " INFO ").append(r.line());
        }
        return request.reply(Footer.ok(fid, b.toString(), null).via("RIPVServer"));
    }

    private static String usage() {
        return "usage: ?audit [--last N] [--since ISO-TIME]";
    }

    /** {@code 2026-11-23T14:00:00Z}, {@code 2026-11-23T14:00} (UTC) or {@code 2026-11-23}. */
    static Instant time(String s) {
        try {
            return Instant.parse(s);
        } catch (DateTimeParseException e) {
            // not an instant; try the shorter forms
        }
        try {
            return LocalDateTime.parse(s).toInstant(ZoneOffset.UTC);
        } catch (DateTimeParseException e) {
            // nor a local time
        }
        try {
            return LocalDate.parse(s).atStartOfDay(ZoneOffset.UTC).toInstant();
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException("--since takes 2026-11-23T14:00:00Z, 2026-11-23T14:00 or 2026-11-23, not '" + s + "'");
        }
    }
}
