package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.ripv.it.ops.CommandProcesses.jar;
import static org.ripv.it.ops.CommandProcesses.java;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.probe.FreePorts;
import org.ripv.testing.Tools;

/**
 * Issue 32, item 2: GliderDOS commands that share the CLI's words reach the vehicle with
 * {@code send LINE}. The jars the README starts (server, serial service, a GliderDOS simulator
 * that calls in) as processes, and {@code ripv-client.jar cli} typed into a terminal (tmux):
 * {@code send put c_dive_target_depth 30} sets the glider's sensor (not an upload), {@code send get}
 * reads it back from the glider (not the download store), {@code send exit} takes the glider to
 * PicoDOS and the CLI stays; Tab lists the CLI's own words under a group of their own, help says
 * which words are the CLI's.
 */
class CliSendTmuxTest {
    static final String PASSWORD = "correct horse battery";

    @TempDir
    Path dir;
    CommandProcesses processes;

    @BeforeEach
    void setUp() {
        processes = new CommandProcesses(dir);
    }

    @AfterEach
    void stop() throws Exception {
        processes.close();
    }

    static final String MAILBOX = "<SerialPortServer>::<localhost>ru29";
    static final String PROMPT = "alice@localhost ru29>";

    /** The screen after a command typed on a cleared screen: its line, what it printed, the prompt again. */
    static boolean answered(String screen) {
        return screen.split(PROMPT, -1).length > 2 && Tmux.lastLine(screen).equals(PROMPT);
    }

    /** Whether the screen shows {@code text} within {@code max}. */
    static boolean shows(Tmux t, String text, Duration max) throws Exception {
        long end = System.nanoTime() + max.toNanos();
        while (!t.screen().contains(text)) {
            if (System.nanoTime() > end) {
                return false;
            }
            Thread.sleep(200);
        }
        return true;
    }

    /** Between two looks at the vehicle's status. */
    static boolean pause() throws InterruptedException {
        Thread.sleep(1000);
        return true;
    }

    @Test
    void sendPassesGliderDosLinesThatShareTheClisWordsVerbatim() throws Exception {
        Tools.require("tmux");
        for (String m : List.of("ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(Path.of(jar(m))), "needs the jars (mvn verify builds them before this module's tests)");
        }
        int port = FreePorts.one();
        int registry = FreePorts.one();
        int glider = FreePorts.one();
        Path data = dir.resolve("data");
        processes.launch("server.log", java(), "-jar", jar("ripv-server"), "server", "--data", data.toString(), "--port", "" + port,
                "--registry-port", "" + registry, "--http-port", "0", "--outbound-port", "-1", "--bind", "127.0.0.1");
        processes.awaitLog("server.log", "RIPVServer ready", Duration.ofSeconds(90));
        Process passwd = new ProcessBuilder(java(), "-jar", jar("ripv-server"), "passwd", "--permit", data.resolve("permit.txt").toString(),
                "alice", "--roles", "operators").redirectErrorStream(true).start();
        passwd.getOutputStream().write((PASSWORD + "\n").getBytes(StandardCharsets.UTF_8));
        passwd.getOutputStream().close();
        passwd.getInputStream().readAllBytes();
        assertThat(passwd.waitFor(60, TimeUnit.SECONDS)).isTrue();
        Path pw = Files.writeString(dir.resolve("pw"), PASSWORD + "\n");
        processes.launch("serial.log", java(), "-Dripv.host=localhost", "-jar", jar("ripv-services"), "serial", "--server", "127.0.0.1:" + registry,
                "--secret-file", data.resolve("service.secret").toString(), "--carrier", "ignore", "--no-enumerate",
                "--link", "listen://127.0.0.1:" + glider + ",name=ru29,prompt-regex=GliderDOS [A-Z] -?\\d+ >|C:\\\\>");
        processes.awaitLog("serial.log", "MailBoxes:", Duration.ofSeconds(90));
        processes.launch("simulator.log", java(), "-jar", jar("ripv-services"), "simulator", "--call", "127.0.0.1:" + glider, "--name", "ru29",
                "--dialog", "gliderdos", "--dive-seconds", "600", "--surface-seconds", "600", "--dir",
                Files.createDirectories(dir.resolve("glider")).toString());
        // The local file the CLI's own put would upload: it must stay where it is, not reach the server.
        Files.writeString(dir.resolve("c_dive_target_depth"), "not for the glider\n");

        Path script = dir.resolve("cli.sh");
        Files.writeString(script, String.join("\n", "#!/bin/bash", "cd '" + dir + "'",
                "'" + java() + "' -jar '" + jar("ripv-client") + "' cli --server localhost:" + port + " --user alice --password-file '"
                        + pw + "' --known-hosts '" + dir.resolve("known_hosts") + "' --history '" + dir.resolve("history") + "'",
                "echo \"CLI-EXIT=$?\"", "sleep 120", ""), StandardCharsets.UTF_8);
        try (Tmux t = new Tmux(200, 50, "bash", script.toString())) {
            t.await("the prompt", Duration.ofSeconds(60), s -> Tmux.lastLine(s).equals("alice@localhost>"));
            t.type("use ru29");
            t.keys("Enter");
            t.await("the prompt with the vehicle", Duration.ofSeconds(60), s -> Tmux.lastLine(s).equals("alice@localhost ru29>"));
            // Wait for the glider's call as the operator would, with ?status ("vehicle (on call, ..." once
            // the call's SURFACED reached the server): a key sent before the call has begun fails at the
            // service ("not on a call"). Then take control with Ctrl-C (again if the glider's answer is slow).
            long end = System.nanoTime() + Duration.ofSeconds(180).toNanos();
            String status;
            do {
                assertThat(System.nanoTime()).as("the glider's call:\n" + t.screen() + processes.log("simulator.log")).isLessThan(end);
                t.keys("C-l");
                t.type("?status " + MAILBOX);
                t.keys("Enter");
                status = t.await("the vehicle's status", Duration.ofSeconds(60), CliSendTmuxTest::answered);
            } while (!status.contains("; vehicle (on call") && pause());
            do {
                assertThat(System.nanoTime()).as("the glider took Ctrl-C:\n" + t.screen() + processes.log("simulator.log")).isLessThan(end);
                t.type("key ctrl-c");
                t.keys("Enter");
            } while (!shows(t, "Mission stopped by the operator", Duration.ofSeconds(20)));
            t.keys("C-l");

            // Tab: the CLI's own words are listed apart from the vehicle's and the server's
            t.type("se");
            t.keys("Tab");
            t.keys("Tab");
            t.await("the completions, the CLI's own word marked", Duration.ofSeconds(30), s -> s.contains("the CLI's own word"));
            assertThat(t.screen()).containsPattern("send\\s+\\(the CLI's own word\\)").contains("sequence")
                    .doesNotContainPattern("sequence\\s+\\(the CLI's own word\\)");
            t.keys("C-u");

            t.type("send put c_dive_target_depth 30");
            t.keys("Enter");
            t.await("the glider set its sensor", Duration.ofSeconds(60),
                    s -> s.contains("sensor:c_dive_target_depth=30") && Tmux.lastLine(s).equals("alice@localhost ru29>"));
            t.type("send get c_dive_target_depth");
            t.keys("Enter");
            t.await("the glider read it back", Duration.ofSeconds(60),
                    s -> s.contains("\nc_dive_target_depth=30") && Tmux.lastLine(s).equals("alice@localhost ru29>"));
            t.type("send exit");
            t.keys("Enter");
            t.await("the glider went to PicoDOS; the CLI is still here", Duration.ofSeconds(60),
                    s -> s.contains("Exiting GliderDOS to PicoDOS") && Tmux.lastLine(s).equals("alice@localhost ru29>"));
            assertThat(t.screen()).doesNotContain("CLI-EXIT");
            t.keys("C-l");
            t.type("help");
            t.keys("Enter");
            t.await("help names the CLI's own words and send", Duration.ofSeconds(30),
                    s -> s.contains("send LINE") && s.contains("are the CLI's") && Tmux.lastLine(s).equals("alice@localhost ru29>"));
            t.type("quit");
            t.keys("Enter");
            t.awaitText("CLI-EXIT=0");
        }
        // the glider has the value, the server never got an upload of the local file
        assertThat(processes.log("server.log")).doesNotContain("c_dive_target_depth (");
        try (var files = Files.walk(data)) {
            assertThat(files.filter(f -> f.getFileName().toString().equals("c_dive_target_depth")).toList()).isEmpty();
        }
        // the vehicle's transcript: the lines went to the glider as typed
        assertThat(processes.log("simulator.log") + processes.log("serial.log")).doesNotContain("Exception");
    }
}
