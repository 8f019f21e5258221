package org.ripv.server.dataloop;

import java.util.Locale;
import java.util.Optional;

/**
 * The plots the server draws from data, by the word after {@code vis:}: one table that decides
 * whether a DataVisServer command is the server's to take over ({@link DataLoop#plot}), how many
 * words it takes, and what the help and typo messages list.
 */
enum PlotKind {
    TRACK("track", "vis:track VEHICLE", 1),
    DEPTH("depth", "vis:depth VEHICLE", 1),
    PROFILE("profile", "vis:profile VEHICLE SENSOR", 2),
    SQL("sql", "vis:sql SELECT x, y FROM ...", 0);

    /** The word after {@code vis:}, lower case. */
    final String word;
    final String usage;
    /** The words before the {@code key=value} options (VEHICLE, SENSOR); 0 for {@code vis:sql}, whose rest is SQL. */
    final int words;

    PlotKind(String word, String usage, int words) {
        this.word = word;
        this.usage = usage;
        this.words = words;
    }

    /** The plot a command line names, in any case; empty for anything else ({@code vis:NAME}, {@code vis:file}). */
    static Optional<PlotKind> of(String body) {
        String w = visWord(body);
        if (w == null) {
            return Optional.empty();
        }
        for (PlotKind k : values()) {
            if (k.word.equals(w)) {
                return Optional.of(k);
            }
        }
        return Optional.empty();
    }

    /** The word after {@code vis:} (lower case, up to white space), or null when the line is no {@code vis:} command. */
    static String visWord(String body) {
        String b = body.strip();
        if (!b.regionMatches(true, 0, "vis:", 0, 4)) {
            return null;
        }
        return b.substring(4).split("\\s+", 2)[0].toLowerCase(Locale.ROOT);
    }
}
