package org.ripv.server.commands;

import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * The server's {@code ?} commands by word, in the order {@code ?help} lists them. Routing looks
 * a command up here, {@code ?help} is written from it, and the clients complete from
 * {@code ?help}: a command added here is known to all three.
 */
public final class CommandTable {
    private final Map<String, ServerCommand> commands = new LinkedHashMap<>();

    /** Adds a command; a word may be named once. */
    public CommandTable add(ServerCommand c) {
        if (!c.word().equals(c.word().toLowerCase(Locale.ROOT)) || !c.word().startsWith("?")) {
            throw new IllegalArgumentException("a server command is '?' and a lower-case word, not '" + c.word() + "'");
        }
        if (commands.putIfAbsent(c.word(), c) != null) {
            throw new IllegalArgumentException("the server command " + c.word() + " is named twice");
        }
        return this;
    }

    /** The command a word names, in any case. */
    public Optional<ServerCommand> find(String word) {
        return Optional.ofNullable(commands.get(word.toLowerCase(Locale.ROOT)));
    }

    /** Whether a line is served to a connection before log-in: the bare word of such a command. */
    public boolean servedBeforeLogin(String line) {
        return find(line.trim()).map(ServerCommand::beforeLogin).orElse(false);
    }

    public Collection<ServerCommand> all() {
        return commands.values();
    }

    /** What {@code ?help} says: one line a command (usage, help, FID). */
    public String help() {
        StringBuilder b = new StringBuilder("Server commands:\n");
        for (ServerCommand c : commands.values()) {
            b.append(String.format("  %-32s %s  [FID %s]%n", c.usage(), c.help(), c.fid()));
        }
        b.append("Anything else goes to the chosen MailBox of a service.");
        return b.toString();
    }
}
