package org.ripv.client;

import org.ripv.client.cli.CliCommand;
import org.ripv.client.gui.ClientCommand;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code java -jar ripv-client.jar [client|cli] ...}: the GUI by default, or the command-line client. */
@Command(name = "ripv-client", mixinStandardHelpOptions = true, version = "RIPV 1.0",
        description = "The RIPV operator clients.",
        subcommands = {ClientCommand.class, CliCommand.class})
public final class ClientMain implements Runnable {
    @Override
    public void run() {
        new CommandLine(this).usage(System.out);
    }

    public static int run(String... args) {
        if (args.length == 0) {
            args = new String[] {"client"}; // double-clicking the jar opens the GUI
        }
        CommandLine cl = new CommandLine(new ClientMain());
        cl.setExecutionExceptionHandler((e, line, parsed) -> {
            line.getErr().println("Error: " + (e.getMessage() == null ? e.toString() : e.getMessage()));
            return 1;
        });
        return cl.execute(args);
    }

    public static void main(String[] args) {
        System.exit(run(args));
    }
}
