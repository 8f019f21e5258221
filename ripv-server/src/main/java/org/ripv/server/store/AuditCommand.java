package org.ripv.server.store;

import java.io.IOException;
import java.time.Instant;
import java.util.List;
import org.ripv.commands.OptionValues;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import picocli.CommandLine.Option;

/**
 * {@code ?audit [--last N] [--since ISO-TIME]}: the admin's view of the audit trail, read from the
 * state store (files or PostgreSQL alike), oldest first. The caller has checked the user's right
 * and read the line ({@link Options}).
 */
public final class AuditCommand {
    /** Lines one reply carries at most. */
    public static final int MAX = OptionValues.MAX_LAST;
    static final int DEFAULT = 100;

    private AuditCommand() {}

    /** The words of {@code ?audit}, read by picocli through the server's command table. */
    public static final class Options {
        @Option(names = "--last", paramLabel = "N", converter = OptionValues.Last.class)
        int last = DEFAULT;
        @Option(names = "--since", paramLabel = "ISO-TIME", converter = OptionValues.IsoTime.class)
        Instant since;
    }

    public static OutgoingServerMessage run(IncomingServerMessage request, String fid, Options options, AuditTrail trail,
                                            StateStore store) throws IOException {
        long since = options.since == null ? 0 : options.since.toEpochMilli();
        trail.sync(); // what happened just before (this admin's own log-in) is in it
        List<StateStore.AuditRecord> lines = store.readAudit(since, options.last);
        StringBuilder b = new StringBuilder(lines.isEmpty() ? "no audit lines" : lines.size() + " audit line(s), oldest first");
        for (StateStore.AuditRecord r : lines) {
            b.append('\n').append(Instant.ofEpochMilli(r.time())).append(r.warn() ? " WARN " : " INFO ").append(r.line());
        }
        return request.reply(Footer.ok(fid, b.toString(), null).via("RIPVServer"));
    }
}
