package org.ripv.server.dataloop;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Status;

/**
 * The download's final reply once its automatic ingest has answered. It always starts its added
 * text with {@code fetched N, ingested M}, which workflows read ({@code {ingested}} in a
 * {@code notify}); it is an ERROR when any DBA file was not ingested, with the stored files still
 * in its result: the files did arrive, but a reply that says OK would claim what did not happen.
 */
public final class IngestVerdict {
    private static final Pattern SUMMARY = Pattern.compile("(?m)^fetched (\\d+), ingested (\\d+)\\b");

    /** A download's counts as its reply states them, and why files were not ingested (empty if all were). */
    public record Counts(int fetched, int ingested, String why) {}

    private IngestVerdict() {
    }

    static OutgoingServerMessage ingested(OutgoingServerMessage reply, int fetched, int ingested, String database, String text) {
        Footer f = reply.footer();
        String added = "fetched " + fetched + ", ingested " + ingested + " into " + database + ":\n" + text;
        return new OutgoingServerMessage(reply.header(), f.withText(join(f.replyText(), added)));
    }

    static OutgoingServerMessage failed(OutgoingServerMessage reply, int fetched, int ingested, String why) {
        Footer f = reply.footer();
        String added = "fetched " + fetched + ", ingested " + ingested + ": " + why;
        return new OutgoingServerMessage(reply.header(), new Footer(f.serviceId(), Status.ERROR, ErrorCode.DATABASE_ERROR,
                f.route(), join(f.replyText(), added), f.result()));
    }

    /** How many files an ingest reply refused (one line each, "NAME: ... nothing stored: ..."). */
    static int refused(String text) {
        int n = 0;
        for (String line : text.split("\n")) {
            if (line.contains("nothing stored")) {
                n++;
            }
        }
        return n;
    }

    /** The counts a download's reply states, if its files went to the automatic ingest. */
    public static Optional<Counts> counts(String replyText) {
        Matcher m = SUMMARY.matcher(replyText);
        Counts last = null;
        while (m.find()) { // the data loop's line comes last, after the service's own text
            String rest = replyText.substring(m.end());
            last = new Counts(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)),
                    rest.startsWith(": ") ? rest.substring(2).strip() : "");
        }
        return Optional.ofNullable(last);
    }

    private static String join(String before, String added) {
        return before.isEmpty() ? added : before + "\n" + added;
    }
}
