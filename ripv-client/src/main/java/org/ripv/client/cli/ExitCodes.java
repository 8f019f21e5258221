package org.ripv.client.cli;

/**
 * What {@code ripv cli} exits with, for scripts (docs/client.md): kept apart from
 * {@link CliCommand} so that the shell and the follower, which the command starts, can name them
 * without depending back on it.
 */
public final class ExitCodes {
    /** Every reply was OK (or the interactive session ended normally). */
    public static final int OK = 0;
    /** Some reply was an ERROR. */
    public static final int ERROR_REPLY = 1;
    /** A bad command line (picocli's usage error). */
    public static final int USAGE = 2;
    /** Could not connect or log in, or lost the connection. */
    public static final int NO_SESSION = 3;

    private ExitCodes() {}
}
