package org.ripv.launch;

import picocli.CommandLine;

/** What every RIPV launcher shares: picocli set up to report a failure as one {@code Error:} line. */
public final class Launchers {
    private Launchers() {}

    /** A command line whose failures print {@code Error: MESSAGE} and exit 1, never a stack trace. */
    public static CommandLine commandLine(Object command) {
        CommandLine cl = new CommandLine(command);
        cl.setExecutionExceptionHandler((e, line, parsed) -> {
            line.getErr().println("Error: " + (e.getMessage() == null ? e.toString() : e.getMessage()));
            return 1;
        });
        return cl;
    }
}
