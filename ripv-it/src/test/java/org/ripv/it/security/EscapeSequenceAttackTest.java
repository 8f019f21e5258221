package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.cli.CliCommand;
import org.ripv.it.TestSystem;
import org.ripv.messages.VehicleEvent;
import picocli.CommandLine;

/**
 * Issue 23, item 8: text a vehicle or a user gives — console lines, event text — carried ESC, BEL
 * and C1 controls into other users' terminals through {@code ?history}: a vehicle (or whoever is on
 * its radio link) could retitle an operator's terminal, clear it, or fake output.
 */
class EscapeSequenceAttackTest {
    static final String HOSTILE = "GPS\u001b]0;owned\u0007\u001b[2J\u009b31m fake prompt\r> ";

    @TempDir
    Path dir;

    @Test
    void historyReachesTheTerminalEscaped() throws Exception {
        try (TestSystem sys = TestSystem.start(dir)) {
            sys.user("olga", "observers");
            VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
            sys.register(vehicle);
            vehicle.event(VehicleEvent.SURFACED, HOSTILE, 41.0, -70.0);
            vehicle.line(HOSTILE);
            String out = "";
            long end = System.nanoTime() + Duration.ofSeconds(30).toNanos();
            while (!out.contains("fake prompt")) {
                assertThat(System.nanoTime()).as("the lines are in the transcript: " + out).isLessThan(end);
                Thread.sleep(200);
                out = cli(sys, "?history " + vehicle.mailbox());
            }
            assertThat(out).as("no terminal control reaches the terminal")
                    .doesNotContainPattern("[\\x00-\\x08\\x0b-\\x1f\\x7f-\\x9f]")
                    .contains("GPS^[]0;owned^G^[[2J\\u009b31m fake prompt\\r> ");
        }
    }

    private static String cli(TestSystem sys, String command) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        new CommandLine(new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8)))
                .execute("--server", "localhost:" + sys.server().port(), "--user", "olga", "--password", TestSystem.PASSWORD,
                        "--exec", command);
        return out.toString(StandardCharsets.UTF_8) + err.toString(StandardCharsets.UTF_8);
    }
}
