package org.ripv.it;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.ripv.client.cli.CliCommand;
import picocli.CommandLine;

/**
 * The CLI run inside the test's JVM as {@code ripv cli OPTIONS --exec LINE…} runs it (picocli,
 * no console input), for tests that drive a server the way an operator's script does.
 */
public final class InJvmCli {
    private InJvmCli() {}

    /** {@code --server SERVER --user USER --password} {@link TestSystem#PASSWORD}, then {@code more}. */
    public static List<String> as(String user, String server, String... more) {
        List<String> options = new ArrayList<>(List.of("--server", server, "--user", user, "--password", TestSystem.PASSWORD));
        options.addAll(List.of(more));
        return options;
    }

    /**
     * Runs the CLI with {@code options} and one {@code --exec} a line; returns its exit code. Both
     * streams are emptied first; {@code err} may be {@code out}, for one stream in the order written.
     */
    public static int exec(ByteArrayOutputStream out, ByteArrayOutputStream err, List<String> options, String... lines) {
        out.reset();
        err.reset();
        List<String> all = new ArrayList<>(options);
        for (String l : lines) {
            all.add("--exec");
            all.add(l);
        }
        PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
        PrintStream e = err == out ? o : new PrintStream(err, true, StandardCharsets.UTF_8);
        return new CommandLine(new CliCommand(new ByteArrayInputStream(new byte[0]), o, e)).execute(all.toArray(String[]::new));
    }
}
