package org.ripv.server.commands;

import java.io.IOException;
import org.ripv.messages.OutgoingServerMessage;

/**
 * One of the server's own {@code ?} commands, named once: its word, FID, usage and help (what
 * {@code ?help} lists, and what the clients complete from it), whether the permit file must allow
 * it first ({@code gated}: a rule for service RIPVServer whose command pattern matches the line),
 * where it runs, and what it does.
 *
 * @param word    the command word, lower case ({@code ?lock})
 * @param fid     the FID its replies carry
 * @param usage   {@code ?lock MAILBOX [SECONDS]}
 * @param help    one line for {@code ?help}
 * @param gated   the permit file must allow the whole line for RIPVServer before it runs
 * @param runs    on the Post Office's thread, or on the file workers (disk work)
 * @param handler what it does
 */
public record ServerCommand(String word, String fid, String usage, String help, boolean gated, Runs runs, Handler handler) {
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
        return new ServerCommand(word, fid, usage, help, false, Runs.AT_ONCE, handler);
    }

    /** The same command, gated by the permit file. */
    public ServerCommand needsRight() {
        return new ServerCommand(word, fid, usage, help, true, runs, handler);
    }

    /** The same command, run on the file workers. */
    public ServerCommand onFileWork() {
        return new ServerCommand(word, fid, usage, help, gated, Runs.FILE_WORK, handler);
    }
}
