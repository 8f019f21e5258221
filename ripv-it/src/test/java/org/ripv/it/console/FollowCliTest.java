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
        CompletableFuture<Integer> exit = follow(out, err, "olga", "--json", "--no-reconnect");
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
        CompletableFuture<Integer> exit = follow(out, err, "alice", "--no-reconnect");
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

    @Test
    void followLogsInAgainAfterAServerRestartAndPrintsNothingTwice() throws Exception {
        // The server must come back where it was: the same ports and data directory (its certificate).
        int[] ports = new int[2];
        for (int i = 0; i < 2; i++) {
            try (java.net.ServerSocket s = new java.net.ServerSocket(0)) {
                ports[i] = s.getLocalPort();
            }
        }
        org.ripv.server.ServerConfig config = org.ripv.server.ServerConfig.forTests(dir.resolve("fixed"))
                .withPorts(ports[0], ports[1], -1);
        sys.close();
        sys = TestSystem.start(config);
        sys.user("olga", "observers");
        sys.register(vehicle = new VehicleConsoleService("localhost", "ru29"));
        vehicle.line("before the restart");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        java.util.concurrent.atomic.AtomicInteger exit = new java.util.concurrent.atomic.AtomicInteger(-1);
        Thread cli = new Thread(() -> exit.set(new CommandLine(cmd).execute("--server", "localhost:" + ports[0], "--user", "olga",
                "--password", TestSystem.PASSWORD, "--known-hosts", TestSystem.knownHosts().toString(),
                "--follow", vehicle.mailbox())));
        cli.start();
        try {
            waitFor(out, "before the restart");
            sys.close(); // the server goes away, and comes back a moment later
            Thread.sleep(1500);
            sys = TestSystem.start(config);
            sys.register(vehicle = new VehicleConsoleService("localhost", "ru29"));
            waitFor(err, "Reconnected to localhost:" + ports[0]);
            vehicle.line("after the restart");
            waitFor(out, "after the restart");
            String text = out.toString(StandardCharsets.UTF_8);
            // The new server replays its transcript on ?watch: what was printed is not printed again.
            assertThat(text.split("before the restart", -1)).hasSize(2);
            assertThat(err.toString(StandardCharsets.UTF_8)).contains("Connection lost").contains("logging in again");
            assertThat(cli.isAlive()).isTrue();
        } finally {
            cli.interrupt();
            cli.join(10_000);
        }
        assertThat(exit.get()).isZero();
    }
}
