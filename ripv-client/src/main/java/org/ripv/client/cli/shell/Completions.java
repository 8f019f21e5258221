package org.ripv.client.cli.shell;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.ripv.client.cli.CliSession;

/**
 * Tab completion for the CLI's lines: the word being typed, given the words before it and the
 * current MailBox. The CLI's own words (listed under a group of their own, {@link #group}), the server's {@code ?} commands, MailBox names after
 * {@code use} and after every server command whose {@code ?help} line names a MAILBOX first (the
 * server writes those lines from its command table), the service's commands, files
 * of the download directory after {@code get}, of the upload directory after an attach prefix
 * ({@code vis:NAME}), a server command's options (as {@code ?help} lists them). Local files after
 * {@code put} are the terminal's business ({@link Shell}).
 */
final class Completions {
    static final List<String> LOCAL = CliSession.OWN_WORDS;
    /** The group Tab lists the CLI's own words under, apart from the server's and the MailBox's commands. */
    static final String OWN_GROUP = "the CLI's own words (send LINE sends a line starting with one to the vehicle)";
    /** What Tab shows beside each of the CLI's own words. */
    static final String OWN_MARK = "the CLI's own word";
    static final String SERVER_GROUP = "server commands";
    static final String MAILBOX_GROUP = "commands for the MailBox";
    static final List<String> PRIORITIES = List.of("normal", "priority", "urgent");
    private static final Set<String> TAKES_MAILBOX = Set.of("use", "?status", "?lock", "?unlock");

    private final Facts facts;

    Completions(Facts facts) {
        this.facts = facts;
    }

    /**
     * Candidates for the word at {@code index} (its prefix is filtered by the terminal), in a stable
     * order without duplicates.
     */
    List<String> candidates(List<String> words, int index, String mailbox) {
        Set<String> out = new LinkedHashSet<>();
        String first = words.isEmpty() ? "" : words.get(0).toLowerCase(Locale.ROOT);
        String current = index < words.size() ? words.get(index) : "";
        if (index == 0) {
            out.addAll(LOCAL);
            out.addAll(facts.serverCommands());
            if (!mailbox.isEmpty()) {
                out.addAll(facts.serviceCommands(mailbox));
                out.addAll(attached(current, mailbox));
            }
        } else if (index == 1 && (TAKES_MAILBOX.contains(first) || first.startsWith("?") && facts.serverTakesMailbox(first))) {
            out.addAll(facts.mailboxes());
        } else if (index == 1 && first.equals("send") && !mailbox.isEmpty()) {
            out.addAll(facts.serviceCommands(mailbox)); // what follows send is the MailBox's
        } else if (index == 1 && first.equals("priority")) {
            out.addAll(PRIORITIES);
        } else if (index == 1 && (first.equals("get") || first.equals("?download"))) {
            out.addAll(facts.downloads());
        } else if (index == 1 && first.equals("?delete")) {
            out.addAll(facts.uploads());
            out.addAll(facts.downloads());
        } else if (first.startsWith("?") && index >= 1 && current.startsWith("-")) {
            out.addAll(facts.serverOptions(first)); // from the server's command table, by way of ?help
        } else if (first.equals("put") && index >= 2) {
            out.addAll(List.of("--replace", "--keep"));
        } else if (!mailbox.isEmpty()) {
            out.addAll(attached(current, mailbox));
        }
        return new ArrayList<>(out);
    }

    /** Which group Tab shows a first word under: the CLI's own, the server's, or the MailBox's. */
    static String group(String word) {
        return LOCAL.contains(word) ? OWN_GROUP : word.startsWith("?") ? SERVER_GROUP : MAILBOX_GROUP;
    }

    /** {@code vis:NAME} for every upload NAME, when the word starts with one of the service's attach prefixes. */
    private List<String> attached(String current, String mailbox) {
        List<String> out = new ArrayList<>();
        for (String prefix : facts.attachPrefixes(mailbox)) {
            if (current.regionMatches(true, 0, prefix, 0, prefix.length())) {
                for (String f : facts.uploads()) {
                    out.add(current.substring(0, prefix.length()) + f);
                }
            }
        }
        return out;
    }

    /**
     * The options {@code ?help} shows on the line of {@code command} ({@code ?history MAILBOX
     * [--last N] [--since ISO-TIME]} gives {@code --last}, {@code --since}): the server writes
     * that line from the command's options, so what Tab offers is what the server parses.
     */
    static List<String> optionsIn(String help, String command) {
        Set<String> out = new LinkedHashSet<>();
        for (String line : help.split("\n")) {
            String[] w = line.strip().split("\\s+");
            if (!w[0].equalsIgnoreCase(command)) {
                continue;
            }
            for (String word : w) {
                String option = word.replaceAll("^[\\[(|]+|[\\])|,]+$", "");
                if (option.matches("--[a-z][a-z0-9-]*")) {
                    out.add(option);
                }
            }
        }
        return new ArrayList<>(out);
    }

    /** Whether {@code ?help}'s line of {@code command} names a MailBox as its first word ({@code MAILBOX} or {@code [MAILBOX]}). */
    static boolean takesMailboxIn(String help, String command) {
        for (String line : help.split("\n")) {
            String[] w = line.strip().split("\\s+");
            if (w[0].equalsIgnoreCase(command)) {
                return w.length > 1 && w[1].replaceAll("[\\[\\]]", "").equals("MAILBOX");
            }
        }
        return false;
    }

    /**
     * The commands a service's help text names: the first word of each clause (split at commas,
     * semicolons, bars and line ends), {@code vis:} for {@code vis:NAME}; placeholders in capitals,
     * options ({@code out=NAME}) and labels ({@code worker:}) are not commands.
     */
    static List<String> commandsIn(String help) {
        Set<String> out = new LinkedHashSet<>();
        for (String clause : help.split("[,;|\\n]")) {
            String w = clause.strip().split("\\s+", 2)[0];
            if (w.startsWith("[") || w.contains("=") || w.isEmpty()) {
                continue;
            }
            int colon = w.indexOf(':');
            if (colon > 0) {
                if (colon < w.length() - 1) {
                    out.add(w.substring(0, colon + 1));
                }
                continue;
            }
            w = w.replaceAll("[^A-Za-z0-9_.-].*$", "");
            if (!w.isEmpty() && !(w.length() > 1 && w.equals(w.toUpperCase(Locale.ROOT)) && !w.equals(w.toLowerCase(Locale.ROOT)))) {
                out.add(w);
            }
        }
        return new ArrayList<>(out);
    }
}
