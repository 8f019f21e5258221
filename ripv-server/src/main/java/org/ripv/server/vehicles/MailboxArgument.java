package org.ripv.server.vehicles;

import java.util.Locale;
import java.util.Set;

/**
 * Which word of a server command is a MailBox: the one place that knows it, so that every
 * command taking a MailBox takes a vehicle name too ({@code ?status sim01}, {@code ?queue add
 * sim01 dive.wf}). Words are the command line split on white space; word 0 is the command.
 */
public final class MailboxArgument {
    private static final Set<String> FIRST = Set.of("?status", "?lock", "?unlock", "?watch", "?unwatch", "?history", "?receipts", "?plan",
            "?changes", "?surfacings");
    private static final Set<String> QUEUE_VERBS = Set.of("add", "remove", "clear");

    private MailboxArgument() {
    }

    /** The index of the MailBox word in {@code words}, or -1 when the command has none (or it is missing). */
    public static int position(String[] words) {
        String command = words[0].toLowerCase(Locale.ROOT);
        int at = -1;
        if (FIRST.contains(command)) {
            at = 1;
        } else if (command.equals("?queue") && words.length > 1) {
            at = QUEUE_VERBS.contains(words[1].toLowerCase(Locale.ROOT)) ? 2 : 1;
        }
        return at > 0 && at < words.length ? at : -1;
    }

    /** The command line with word {@code at} replaced by {@code address}. */
    public static String replaced(String[] words, int at, String address) {
        String[] copy = words.clone();
        copy[at] = address;
        return String.join(" ", copy);
    }
}
