package org.ripv.client.cli.shell;

import java.util.List;

/** What completion needs to know about the server; {@link ServerFacts} asks it, tests give lists. */
interface Facts {
    /** The server's {@code ?} commands, e.g. {@code ?mailboxes}. */
    List<String> serverCommands();

    /** The options ({@code --last}) a server command's line in {@code ?help} names: the server's command table. */
    default List<String> serverOptions(String command) {
        return List.of();
    }

    /** Whether a server command's first word is a MailBox, as its line in {@code ?help} says ({@code ?history MAILBOX ...}). */
    default boolean serverTakesMailbox(String command) {
        return false;
    }

    /** Every MailBox's full address. */
    List<String> mailboxes();

    /** File names in the download directory (what {@code get} fetches). */
    List<String> downloads();

    /** File names in the upload directory (what {@code vis:NAME} and the like read). */
    List<String> uploads();

    /** The commands the MailBox's service lists in its help, and its attach prefixes (e.g. {@code vis:}). */
    List<String> serviceCommands(String mailbox);

    /** The attach prefixes of the MailBox's service, e.g. {@code vis:} (their argument is an upload). */
    List<String> attachPrefixes(String mailbox);
}
