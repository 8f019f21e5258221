package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code ./ripv bench console} refuses counts and times it cannot run with, naming the option, before starting anything. */
class ConsoleBenchOptionsTest {
    @Test
    void impossibleOptionsAreAUsageErrorThatNamesTheOption() {
        for (String[] args : List.of(new String[] {"--baseline-seconds", "-5"}, new String[] {"--watchers", "0"},
                new String[] {"--rate", "1000000"}, new String[] {"--seconds", "0"}, new String[] {"--warmup", "-1"},
                new String[] {"--full-clients", "-2"}, new String[] {"--raw-threads", "0"})) {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            StringWriter err = new StringWriter();
            CommandLine cl = new CommandLine(new ConsoleBench(new PrintStream(out, true, StandardCharsets.UTF_8)));
            cl.setErr(new PrintWriter(err, true));
            int exit = cl.execute(args);
            assertThat(exit).as(String.join(" ", args)).isEqualTo(2);
            assertThat(err.toString()).contains(args[0] + " must").contains("got " + args[1]);
            assertThat(out.toString(StandardCharsets.UTF_8)).as("nothing ran, nothing measured").isEmpty();
        }
    }
}
