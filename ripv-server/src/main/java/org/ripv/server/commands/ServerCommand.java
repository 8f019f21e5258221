package org.ripv.server.commands;

import java.io.IOException;
import java.util.Arrays;
import java.util.List;
import java.util.function.Supplier;
import org.ripv.commands.CommandWords;
import org.ripv.messages.OutgoingServerMessage;

/**
 * One of the server's own {@code ?} commands, named once: its word, FID, usage and help (what
 * {@code ?help} lists, and what the clients complete from it), its options, whether the permit
 * file must allow it first ({@code gated}: a rule for service RIPVServer whose command pattern
 * matches the line), where it runs, and what it does.
 *
 * <p>A command with {@code options} declares its words after the command word as a picocli class
 * ({@code @Parameters} and {@code @Option} fields): the line is parsed into a fresh instance before
 * the handler runs ({@link Call#options}), a bad line is refused with picocli's own words and the
 * usage, and the usage {@code ?help} shows is written from the same class.
 *
 * @param word    the command word, lower case ({@code ?lock})
 * @param fid     the FID its replies carry
 * @param usage   {@code ?lock MAILBOX [SECONDS]}
 * @param help    one line for {@code ?help}
 * @param gated   the permit file must allow the whole line for RIPVServer before it runs
 * @param runs    on the Post Office's thread, or on the file workers (disk work)
 * @param handler what it does
 * @param options makes a fresh picocli-annotated object for the words after the command word, or null
 * @param beforeLogin the bare word is served to a connection that has not logged in yet ({@code ?help}, {@code ?ping})
 */
public record ServerCommand(String word, String fid, String usage, String help, boolean gated, Runs runs, Handler handler,
                            Supplier<?> options, boolean beforeLogin) {
    /** Where a command runs. */
    public enum Runs {
        /** On the Post Office's thread: quick, or hands its work to a pool of its own. */
        AT_ONCE,
        /** On the file workers ({@code ripv-file-work}): it touches the disk. */
        FILE_WORK
    }

    /** What a command does. */
    @FunctionalInterface
    public interface Handler {
        /**
         * @return the reply, or null when the command answers later (or has answered already)
         * @throws IllegalArgumentException a bad line: answered BAD_REQUEST with its message
         * @throws IOException              answered INTERNAL, or as the file errors say
         */
        OutgoingServerMessage run(Call call) throws IOException;
    }

    /** A command that runs at once and needs no right but log-in. */
    public static ServerCommand open(String word, String fid, String usage, String help, Handler handler) {
        return new ServerCommand(word, fid, usage, help, false, Runs.AT_ONCE, handler, null, false);
    }

    /**
     * A command whose words after the command word are the picocli class {@code options} makes;
     * its usage is written from that class.
     */
    public static ServerCommand parsed(String word, String fid, Supplier<?> options, String help, Handler handler) {
        return new ServerCommand(word, fid, usage(word, options), help, false, Runs.AT_ONCE, handler, options, false);
    }

    /** The same command, gated by the permit file. */
    public ServerCommand needsRight() {
        return new ServerCommand(word, fid, usage, help, true, runs, handler, options, beforeLogin);
    }

    /** The same command, run on the file workers. */
    public ServerCommand onFileWork() {
        return new ServerCommand(word, fid, usage, help, gated, Runs.FILE_WORK, handler, options, beforeLogin);
    }

    /** The same command, its bare word served before log-in. */
    public ServerCommand servedBeforeLogin() {
        return new ServerCommand(word, fid, usage, help, gated, runs, handler, options, true);
    }

    /** The options (as {@code --last}) {@code ?help} shows for this command: what the clients complete. */
    public List<String> optionNames() {
        return options == null ? List.of() : CommandWords.optionNames(options.get());
    }

    /**
     * The words after the command word, parsed into a fresh options object ({@link CommandWords}'
     * rules for a hostile line); null for a command without options.
     *
     * @throws IllegalArgumentException picocli's reason and the usage
     */
    Object parse(String[] words) {
        if (options == null) {
            return null;
        }
        return CommandWords.parse(options.get(), usage, Arrays.copyOfRange(words, 1, words.length));
    }

    private static String usage(String word, Supplier<?> options) {
        return CommandWords.usage(word, options.get());
    }
}
