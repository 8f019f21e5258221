package org.ripv.launch;

import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;

/**
 * What every RIPV launcher shares: picocli set up to report a failure as one {@code Error:} line,
 * to print the version and git commit for {@code --version}, and to name the program in usage
 * lines as users type it ({@code ripv cli}, not {@code ripv-client cli}).
 */
public final class Launchers {
    /** With this environment variable set to 1, a command line is checked and nothing is run. */
    public static final String PARSE_ONLY = "RIPV_PARSE_ONLY";

    private Launchers() {}

    /** A command line whose failures print {@code Error: MESSAGE} and exit 1, never a stack trace. */
    public static CommandLine commandLine(Object command) {
        CommandLine cl = new CommandLine(command);
        cl.setExecutionExceptionHandler((e, line, parsed) -> {
            line.getErr().println("Error: " + (e.getMessage() == null ? e.toString() : e.getMessage()));
            return 1;
        });
        versions(cl);
        if ("1".equals(System.getenv(PARSE_ONLY))) {
            // A dry run: bad options still fail (exit 2), help and version still print, nothing starts.
            cl.setExecutionStrategy(parsed -> {
                Integer help = CommandLine.executeHelpRequest(parsed);
                return help != null ? help : 0;
            });
        }
        return cl;
    }

    /**
     * As {@link #commandLine(Object)}, the command named {@code name} in usage lines, e.g.
     * {@code "ripv service serial"} (subcommands then read {@code ripv service serial SUB}).
     */
    public static CommandLine commandLine(Object command, String name) {
        CommandLine cl = commandLine(command);
        cl.setCommandName(name);
        return cl;
    }

    private static void versions(CommandLine cl) {
        CommandSpec spec = cl.getCommandSpec();
        spec.versionProvider(new Version.Provider());
        cl.getSubcommands().values().forEach(Launchers::versions);
    }
}
