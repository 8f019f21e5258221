package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.ripv.it.ops.CommandProcesses.jar;
import static org.ripv.it.ops.CommandProcesses.java;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.probe.FreePorts;
import org.ripv.testing.Tools;

/**
 * Issue 25's first hour against the launched jars, each a process of its own as the {@code ripv}
 * launcher starts them: a server, a SerialPortServer whose glider {@code sim01} calls in from the
 * simulator, a DatabaseServer and a DataVisServer. The vehicle is called by its name in every
 * command that takes a MailBox; {@code --follow sim01} follows on a terminal (tmux); and each
 * misleading error of the issue now says what is wrong and what to do, within a bounded time.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class FirstHourEndToEndTest {
    static final Path ROOT = RipvScriptHelpTest.ROOT;
    static final String PASSWORD = "first-hour-pw-1";
    static final String SIM = "<SerialPortServer>::<localhost>sim01";

    @TempDir
    static Path dir;
    CommandProcesses processes;
    int port;
    int registry;
    int http;
    Path secret;
    Path pw;
    Path knownHosts;

    @BeforeAll
    void start() throws Exception {
        processes = new CommandProcesses(dir);
        for (String m : List.of("ripv-common", "ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(Path.of(jar(m))), "needs the jars (mvn verify builds them before this module's tests)");
        }
        port = FreePorts.one();
        registry = FreePorts.one();
        http = FreePorts.one();
        int glider = FreePorts.one();
        Path data = dir.resolve("data");
        processes.launch("server.log", java(), "-jar", jar("ripv-server"), "server", "--data", data.toString(), "--port", "" + port,
                "--registry-port", "" + registry, "--http-port", "" + http, "--outbound-port", "-1", "--bind", "127.0.0.1");
        processes.awaitLog("server.log", "RIPVServer ready", Duration.ofSeconds(90));
        Process passwd = new ProcessBuilder(java(), "-jar", jar("ripv-server"), "passwd", "--permit", data.resolve("permit.txt").toString(),
                "alice", "--roles", "operators").redirectErrorStream(true).start();
        passwd.getOutputStream().write((PASSWORD + "\n").getBytes(StandardCharsets.UTF_8));
        passwd.getOutputStream().close();
        passwd.getInputStream().readAllBytes();
        assertThat(passwd.waitFor(60, TimeUnit.SECONDS)).isTrue();
        pw = Files.writeString(dir.resolve("pw"), PASSWORD + "\n");
        knownHosts = dir.resolve("known_hosts");
        secret = data.resolve("service.secret");
        String server = "127.0.0.1:" + registry;
        processes.launch("serial.log", java(), "-Dripv.host=localhost", "-jar", jar("ripv-services"), "serial", "--server", server,
                "--secret-file", secret.toString(), "--link", "listen://127.0.0.1:" + glider + ",name=sim01", "--carrier", "ignore",
                "--no-enumerate");
        processes.launch("database.log", java(), "-Dripv.host=localhost", "-jar", jar("ripv-services"), "database", "--server", server,
                "--secret-file", secret.toString(), "--data", dir.resolve("database").toString());
        processes.launch("datavis.log", java(), "-Dripv.host=localhost", "-jar", jar("ripv-services"), "datavis", "--server", server,
                "--secret-file", secret.toString(), "--workdir", dir.resolve("vis").toString());
        processes.awaitLog("serial.log", "MailBoxes:", Duration.ofSeconds(90));
        processes.launch("simulator.log", java(), "-jar", jar("ripv-services"), "simulator", "--call", "127.0.0.1:" + glider,
                "--name", "sim01", "--dive-seconds", "600", "--surface-seconds", "600", "--dir", dir.resolve("glider").toString());
        // All three services registered and the glider on call.
        long end = System.nanoTime() + Duration.ofSeconds(120).toNanos();
        while (true) {
            Result r = cli("--exec", "?mailboxes");
            if (r.out().contains(SIM + ": available") && r.out().contains("<DatabaseServer>") && r.out().contains("<DataVisServer>")) {
                break;
            }
            assertThat(System.nanoTime()).as("the services and the glider:\n" + r.out() + r.err()).isLessThan(end);
            Thread.sleep(1000);
        }
    }

    @AfterAll
    void stop() throws Exception {
        processes.close();
    }

    record Result(int code, String out, String err, Duration took) {}

    /** The CLI jar, as {@code ripv cli} runs it, with standard input from /dev/null. */
    Result cliAt(String serverPort, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(java(), "-jar", jar("ripv-client"), "cli", "--server", serverPort,
                "--user", "alice", "--password-file", pw.toString(), "--known-hosts", knownHosts.toString()));
        cmd.addAll(List.of(args));
        Path out = Files.createTempFile(dir, "cli", ".out");
        Path err = Files.createTempFile(dir, "cli", ".err");
        long t0 = System.nanoTime();
        Process p = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))).start();
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("the CLI did not end within 120 s: " + cmd + "\n" + Files.readString(err));
        }
        return new Result(p.exitValue(), Files.readString(out), Files.readString(err), Duration.ofNanos(System.nanoTime() - t0));
    }

    Result cli(String... args) throws Exception {
        return cliAt("localhost:" + port, args);
    }

    @Test
    void theVehicleIsCalledByItsNameWhereverAMailBoxIsExpected() throws Exception {
        Result r = cli("--exec", "?status sim01", "--exec", "?history sim01 --last 5", "--exec", "?lock sim01 60",
                "--exec", "?unlock sim01", "--exec", "?queue sim01", "--exec", "?receipts sim01", "--exec", "?watch sim01",
                "--exec", "?unwatch sim01");
        assertThat(r.code()).as(r.out() + r.err()).isZero();
        assertThat(r.out()).contains(SIM + ": available", "entries of " + SIM, SIM + " locked by alice", SIM + " unlocked",
                "the queue of " + SIM + " is empty", "no workflow receipts for " + SIM, "stopped watching " + SIM);
    }

    @Test
    void anUnknownNameSaysWhichNamesExistAndAnAmbiguousOneListsTheCandidates() throws Exception {
        Result r = cli("--exec", "?history sim02");
        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("no vehicle or MailBox is called 'sim02'; the names are: TTY1, sim01");
        // The DatabaseServer and the DataVisServer both have a MailBox TTY1.
        r = cli("--exec", "?status TTY1");
        assertThat(r.err()).contains("'TTY1' names 2 MailBoxes: <DataVisServer>::<localhost>TTY1, <DatabaseServer>::<localhost>TTY1");
    }

    @Test
    void followingAMailBoxThatDoesNotExistSaysSoAtOnce() throws Exception {
        Result r = cli("--follow", "<SerialPortServer>::<localhost>ru29");
        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("no MailBox <SerialPortServer>::<localhost>ru29", "the names are: TTY1, sim01")
                .doesNotContain("nothing heard from it yet");
        r = cli("--follow", "ru29");
        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("no vehicle or MailBox is called 'ru29'");
    }

    @Test
    void followByNameOnATerminalFollowsInsteadOfOpeningThePrompt() throws Exception {
        Tools.require("tmux");
        Path script = dir.resolve("follow.sh");
        Files.writeString(script, String.join("\n", "#!/bin/bash",
                "'" + java() + "' -jar '" + jar("ripv-client") + "' cli --server localhost:" + port + " --user alice --password-file '"
                        + pw + "' --known-hosts '" + knownHosts + "' --history '" + dir.resolve("history") + "' --follow sim01",
                "echo \"CLI-EXIT=$?\"", "sleep 120", ""), StandardCharsets.UTF_8);
        try (Tmux t = new Tmux(200, 50, "bash", script.toString())) {
            // The history comes first: on a slow machine the call's SURFACED has scrolled off the screen by the time it is all there.
            t.awaitInScrollback("the watch, then the console's lines", Duration.ofSeconds(120),
                    s -> s.contains("watching " + SIM) && s.contains("Ctrl-C stops") && s.contains("SURFACED"));
            assertThat(t.screen()).as("no interactive prompt").doesNotContain("alice@localhost>");
            // A line the vehicle writes now arrives on the terminal as it happens.
            Result r = cli("--exec", "use sim01", "--exec", "report now");
            assertThat(r.code()).as(r.out() + r.err()).isZero();
            t.await("the command sent from elsewhere", Duration.ofSeconds(60), s -> s.contains("> report now"));
            t.keys("C-c");
            t.await("Ctrl-C ended it", Duration.ofSeconds(30), s -> s.contains("CLI-EXIT="));
        }
    }

    @Test
    void theCliAtTheWrongPortSaysWhichPortItReached() throws Exception {
        Result r = cliAt("localhost:" + registry, "--exec", "?ping");
        assertThat(r.code()).isEqualTo(3);
        assertThat(r.err()).contains("localhost:" + registry + " is the server's Java RMI registry", "not its client port")
                .doesNotContain("is the server started with --plain");
        assertThat(r.took()).isLessThan(Duration.ofSeconds(90));

        r = cliAt("localhost:" + http, "--exec", "?ping");
        assertThat(r.code()).isEqualTo(3);
        assertThat(r.err()).contains("localhost:" + http + " is the server's web/landing page port");
        assertThat(r.took()).as("bounded, not forever").isLessThan(Duration.ofSeconds(90));

        int nothing = FreePorts.one();
        r = cliAt("localhost:" + nothing, "--exec", "?ping");
        assertThat(r.code()).isEqualTo(3);
        assertThat(r.err()).contains("nothing listens on localhost:" + nothing);

        r = cliAt("localhost:" + port, "--plain", "--exec", "?ping");
        assertThat(r.code()).isEqualTo(3);
        assertThat(r.err()).contains("is a RIPV client port with TLS: leave out --plain");
    }

    @Test
    void aServiceAtTheClientPortOrWithTheWrongSecretGivesUpWithAnError() throws Exception {
        Process atClientPort = processes.launch("clock-client-port.log", java(), "-jar", jar("ripv-common"),
                "--server", "127.0.0.1:" + port, "--secret-file", secret.toString());
        Path wrong = Files.writeString(dir.resolve("wrong.secret"), "not-the-secret-at-all\n");
        Process wrongSecret = processes.launch("clock-wrong-secret.log", java(), "-jar", jar("ripv-common"),
                "--server", "127.0.0.1:" + registry, "--secret-file", wrong.toString());
        Process forever = processes.launch("clock-forever.log", java(), "-jar", jar("ripv-common"),
                "--server", "127.0.0.1:" + registry, "--secret-file", wrong.toString(), "--retry-forever");

        assertThat(atClientPort.waitFor(120, TimeUnit.SECONDS)).as(processes.log("clock-client-port.log")).isTrue();
        assertThat(atClientPort.exitValue()).isEqualTo(1);
        assertThat(processes.log("clock-client-port.log")).contains("Error: 127.0.0.1:" + port + " is RIPV's client port",
                "not the server's RMI registry", "(gave up after 5 tries; --retry-forever keeps trying)");

        assertThat(wrongSecret.waitFor(120, TimeUnit.SECONDS)).as(processes.log("clock-wrong-secret.log")).isTrue();
        assertThat(wrongSecret.exitValue()).isEqualTo(1);
        assertThat(processes.log("clock-wrong-secret.log")).contains("cannot prove it holds the service secret", "--secret-file",
                "(try 1 of 5)", "(gave up after 5 tries; --retry-forever keeps trying)");

        assertThat(processes.log("clock-forever.log")).contains("cannot prove it holds the service secret").doesNotContain("gave up");
        assertThat(forever.isAlive()).as("--retry-forever keeps trying").isTrue();
    }

    @Test
    void visTyposAndPlotsBeforeAnyIngestSayWhatToDo() throws Exception {
        Result r = cli("--exec", "use <DataVisServer>::<localhost>TTY1", "--exec", "vis:trak sim01");
        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("'vis:trak' is not a plot command (did you mean vis:track?)", "vis:track VEHICLE",
                "vis:depth VEHICLE", "vis:profile VEHICLE SENSOR", "vis:sql SELECT");
        r = cli("--exec", "use <DataVisServer>::<localhost>TTY1", "--exec", "vis:track sim01");
        assertThat(r.code()).isEqualTo(1);
        assertThat(r.err()).contains("no Slocum data for 'sim01' yet", "ymodem:get", "ingested automatically", "ingest NAME")
                .doesNotContain("SQLState");
    }
}
