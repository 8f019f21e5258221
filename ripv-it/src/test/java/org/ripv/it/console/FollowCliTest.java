package org.ripv.it.console;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.cli.CliCommand;
import org.ripv.it.TestSystem;
import org.ripv.messages.Priority;
import org.ripv.messages.VehicleEvent;
import picocli.CommandLine;

/** {@code ripv cli --follow MAILBOX} prints the console as it comes, as text or one JSON object per line. */
class FollowCliTest {
    @TempDir
    Path dir;
    TestSystem sys;
    VehicleConsoleService vehicle;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators").user("olga", "observers").user("eve");
        vehicle = new VehicleConsoleService("localhost", "ru29");
        sys.register(vehicle);
    }

    @AfterEach
    void stop() {
        sys.close();
    }

    /** Runs the CLI on a thread of its own; the output grows in {@code out}. */
    private CompletableFuture<Integer> follow(ByteArrayOutputStream out, ByteArrayOutputStream err, String user, String... more) {
        List<String> args = new java.util.ArrayList<>(List.of("--server", "localhost:" + sys.server().port(), "--user", user,
                "--password", TestSystem.PASSWORD, "--follow", vehicle.mailbox()));
        args.addAll(List.of(more));
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        return CompletableFuture.supplyAsync(() -> new CommandLine(cmd).execute(args.toArray(String[]::new)));
    }

    private static void waitFor(ByteArrayOutputStream out, String text) throws InterruptedException {
        long end = System.nanoTime() + Duration.ofSeconds(20).toNanos();
        while (!out.toString(StandardCharsets.UTF_8).contains(text) && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertThat(out.toString(StandardCharsets.UTF_8)).contains(text);
    }

    @Test
    void followPrintsJsonLinesUntilTheConnectionEnds() throws Exception {
        vehicle.line("said before anyone watched"); // replayed on ?watch
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        CompletableFuture<Integer> exit = follow(out, err, "olga", "--json");
        waitFor(out, "said before anyone watched");
        vehicle.event(VehicleEvent.SURFACED, "Glider ru29 at surface", 41.63323, -70.53647);
        sys.login("alice").call(vehicle.mailbox(), "say hi \"there\"", Priority.NORMAL, Duration.ofSeconds(20), null);
        waitFor(out, "\"kind\":\"line\",\"text\":\"hi \\\"there\\\"\"}"); // the reply line, not the command
        sys.server().stop(); // the connection ends: the CLI says so and exits 3
        assertThat(exit.get(20, TimeUnit.SECONDS)).isEqualTo(CliCommand.EXIT_NO_SESSION);
        List<String> lines = out.toString(StandardCharsets.UTF_8).lines().toList();
        String box = vehicle.mailbox();
        assertThat(lines.get(0)).matches("\\{\"time\":\"\\d{4}-\\d\\d-\\d\\dT[0-9:.]+Z\",\"mailbox\":\"" + java.util.regex.Pattern.quote(box)
                + "\",\"kind\":\"line\",\"text\":\"said before anyone watched\"}");
        assertThat(lines.get(1)).contains("\"kind\":\"event\"", "\"text\":\"Glider ru29 at surface\"", "\"event\":\"SURFACED\"",
                "\"lat\":41.63323", "\"lon\":-70.53647");
        assertThat(lines.get(2)).contains("\"kind\":\"command\"", "\"user\":\"alice\"", "\"text\":\"say hi \\\"there\\\"\"");
        assertThat(lines.get(3)).contains("\"kind\":\"line\"", "\"text\":\"hi \\\"there\\\"\"").doesNotContain("\"user\"");
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("Error:");
    }

    @Test
    void followPrintsTextAndRefusesWithoutTheReadRight() throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        CompletableFuture<Integer> exit = follow(out, err, "alice");
        waitFor(err, "watching " + vehicle.mailbox());
        vehicle.event(VehicleEvent.DIVED, "", null, null);
        vehicle.line("after the dive");
        waitFor(out, "after the dive");
        assertThat(out.toString(StandardCharsets.UTF_8)).containsPattern("Z  \\* DIVED\\R.*Z  after the dive");
        sys.server().stop();
        assertThat(exit.get(20, TimeUnit.SECONDS)).isEqualTo(CliCommand.EXIT_NO_SESSION);

        sys.close();
        sys = TestSystem.start(dir.resolve("again"));
        sys.user("eve");
        sys.register(vehicle = new VehicleConsoleService("localhost", "ru29"));
        ByteArrayOutputStream out2 = new ByteArrayOutputStream();
        ByteArrayOutputStream err2 = new ByteArrayOutputStream();
        assertThat(follow(out2, err2, "eve").get(20, TimeUnit.SECONDS)).isEqualTo(CliCommand.EXIT_ERROR_REPLY);
        assertThat(err2.toString(StandardCharsets.UTF_8)).contains("may not read", "FORBIDDEN");
    }
}
