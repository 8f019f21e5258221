package org.ripv.client;

import org.ripv.client.cli.CliCommand;
import org.ripv.client.gui.ClientCommand;
import org.ripv.launch.Launchers;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code java -jar ripv-client.jar [client|cli] ...}: the GUI by default, or the command-line client. */
@Command(name = "ripv", mixinStandardHelpOptions = true,
        description = "The RIPV operator clients.",
        subcommands = {ClientCommand.class, CliCommand.class})
public final class ClientMain implements Runnable {
    @Override
    public void run() {
        Launchers.commandLine(this, "ripv").usage(System.out);
    }

    public static int run(String... args) {
        if (args.length == 0) {
            args = new String[] {"client"}; // double-clicking the jar opens the GUI
        }
        CommandLine cl = Launchers.commandLine(new ClientMain(), "ripv");
        return cl.execute(args);
    }

    public static void main(String[] args) {
        System.exit(run(args));
    }
}
