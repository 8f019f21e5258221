package org.ripv.server.dataloop;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.messages.Footer;
import org.ripv.messages.OutgoingServerMessage;

/**
 * The download's final reply once its automatic ingest has answered. The transfer's verdict and
 * the ingest's are separate: files that arrived make an OK download whatever the database made of
 * them. The reply's added text starts {@code fetched N, ingested M}, which workflows read
 * ({@code {ingested}} in a {@code notify}); each file the database refused or had stored already
 * is a {@code note:} line of its own (the DatabaseServer also raises INGEST_REFUSED or
 * INGEST_REPEATED for it), as is an ingest that could not run at all.
 */
public final class IngestVerdict {
    private static final Pattern SUMMARY = Pattern.compile("(?m)^fetched (\\d+), ingested (\\d+)\\b");
    /** The start of each line the reply adds for a file that was not ingested. */
    public static final String NOTE = "note: ";

    /** A download's counts as its reply states them, and why files were not ingested (empty if all were). */
    public record Counts(int fetched, int ingested, String why) {}

    private IngestVerdict() {
    }

    /**
     * The download's reply with the ingest's answer added: its per-file lines, those of files
     * refused or stored already marked as notes.
     *
     * @param files how many of the fetched files went to the ingest
     */
    static OutgoingServerMessage ingested(OutgoingServerMessage reply, int fetched, int files, String database, String text) {
        StringBuilder lines = new StringBuilder();
        int notIngested = 0;
        for (String line : text.split("\n")) {
            if (notIngested(line)) {
                notIngested++;
                lines.append(NOTE);
            }
            lines.append(line).append('\n');
        }
        String added = "fetched " + fetched + ", ingested " + Math.max(0, files - notIngested) + " into " + database
                + (notIngested == 0 ? "" : " (" + notIngested + " not ingested, see the notes; every file fetched is stored)")
                + ":\n" + lines.toString().strip();
        return withText(reply, added);
    }

    /** The download's reply when its ingest could not run at all: still OK, the files arrived. */
    static OutgoingServerMessage notIngested(OutgoingServerMessage reply, int fetched, String why) {
        return withText(reply, "fetched " + fetched + ", ingested 0: " + NOTE + why);
    }

    /** True for an ingest reply's line of a file refused ("nothing stored") or stored already ("nothing added"). */
    static boolean notIngested(String line) {
        return line.contains("nothing stored") || line.contains("nothing added");
    }

    private static OutgoingServerMessage withText(OutgoingServerMessage reply, String added) {
        Footer f = reply.footer();
        return new OutgoingServerMessage(reply.header(), f.withText(join(f.replyText(), added)));
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
