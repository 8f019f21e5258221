package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.messages.Priority;
import org.ripv.probe.FreePorts;
import org.ripv.testing.Tools;

/**
 * The interactive {@code ripv cli} as a person uses it, typed into a real terminal (tmux) and read
 * off the screen: the password prompt without echo, the prompt with the MailBox after {@code use},
 * Tab completion of {@code ?mai} and of a MailBox name, Up recalling the last command (also in the
 * next session, from the history file), Ctrl-C ending the wait for a running request with the CLI
 * still usable, Ctrl-D ending with status 0.
 */
class InteractiveCliTmuxTest {
    static final String BOX = "<ClockService>::<localhost>TTY1";

    @TempDir
    Path dir;
    TestSystem sys;
    org.ripv.server.ServerConfig config;
    Path launcher;
    Path history;

    @BeforeEach
    void start() throws Exception {
        Tools.require("tmux");
        int[] ports = FreePorts.several(2);
        // Fixed ports and data directory: a restarted server comes back where it was, with its certificate.
        config = org.ripv.server.ServerConfig.forTests(dir.resolve("sys")).withPorts(ports[0], ports[1], -1);
        sys = TestSystem.start(config);
        sys.user("alice", "operators");
        sys.register(new ClockService("localhost"));
        history = dir.resolve("home/.ripv/history");
        String java = org.ripv.it.TestJvms.java();
        launcher = dir.resolve("ripv-cli.sh");
        Files.writeString(launcher, String.join("\n",
                "#!/bin/bash",
                "unset RIPV_PASSWORD",
                "export RIPV_KNOWN_HOSTS='" + TestSystem.knownHosts() + "'", // test servers' certificates stay out of ~/.ripv
                "cd '" + dir + "'",
                "'" + java + "' -cp '" + System.getProperty("java.class.path") + "' org.ripv.client.ClientMain cli"
                        + " --server localhost:" + sys.server().port() + " --user alice --history '" + history + "'",
                "echo \"CLI-EXIT=$?\"",
                "sleep 120", ""), StandardCharsets.UTF_8);
    }

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    /** Waits until the MailBox runs a request (its key is held: "busy" in {@code ?status}). */
    void awaitRunning() throws Exception {
        try (ClientSocketHandler c = sys.login("alice")) {
            long end = System.nanoTime() + Duration.ofSeconds(60).toNanos();
            String status;
            while (!(status = c.call("", "?status " + BOX, Priority.NORMAL, Duration.ofSeconds(60), null).footer().replyText())
                    .contains("busy")) {
                assertThat(System.nanoTime()).as("the request reached the MailBox: " + status).isLessThan(end);
                Thread.sleep(100);
            }
        }
    }

    Tmux cli() throws Exception {
        Tmux t = new Tmux(220, 50, "bash", launcher.toString());
        // a JVM starting beside a loaded machine's other work: a first event, not a fixed time
        t.await("the password prompt", Duration.ofSeconds(120), x -> x.contains("Password for alice@localhost:"));
        t.type(TestSystem.PASSWORD);
        t.keys("Enter");
        String s = t.await("the prompt", Duration.ofSeconds(60), x -> x.contains("alice@localhost> "));
        assertThat(s).as("the password is not echoed").doesNotContain(TestSystem.PASSWORD);
        return t;
    }

    @Test
    void promptHistoryCompletionCtrlCAndCtrlD() throws Exception {
        try (Tmux t = cli()) {
            // Tab completes a server command...
            t.type("?mai");
            t.keys("Tab");
            t.await("?mailboxes completed", Duration.ofSeconds(30), s -> Tmux.lastLine(s).contains("alice@localhost> ?mailboxes"));
            t.keys("Enter");
            t.await("the MailBoxes, then the prompt again", Duration.ofSeconds(20),
                    s -> s.contains("TTY1: available") && Tmux.lastLine(s).equals("alice@localhost>"));
            // ... and a MailBox name after use.
            t.type("use <Cl");
            t.keys("Tab");
            t.await("the MailBox completed", Duration.ofSeconds(30), s -> Tmux.lastLine(s).contains("use " + BOX));
            t.keys("Enter");
            // The prompt shows the MailBox's handle.
            t.await("the prompt with the MailBox", Duration.ofSeconds(30), s -> Tmux.lastLine(s).equals("alice@localhost TTY1>"));
            t.type("echo hello from tmux");
            t.keys("Enter");
            t.await("the reply, then the prompt again", Duration.ofSeconds(20),
                    s -> s.contains("\nhello from tmux\n") && Tmux.lastLine(s).equals("alice@localhost TTY1>"));
            // Up recalls the last command.
            t.keys("Up");
            t.await("Up recalled the last command", Duration.ofSeconds(30),
                    s -> Tmux.lastLine(s).equals("alice@localhost TTY1> echo hello from tmux"));
            t.keys("C-u");
            // Ctrl-C while a request runs: the wait ends at once, the CLI stays usable.
            t.type("sleep 20000");
            t.keys("Enter");
            awaitRunning(); // not a fixed pause: a Ctrl-C before the request left would only clear the line
            long before = System.nanoTime();
            t.keys("C-c");
            t.awaitText("Cancelled: stopped waiting for 'sleep 20000'; the server: ");
            assertThat(Duration.ofNanos(System.nanoTime() - before)).as("well before the 20 s sleep ends").isLessThan(Duration.ofSeconds(15));
            t.type("echo still here");
            t.keys("Enter");
            t.await("the reply, then the prompt again", Duration.ofSeconds(20),
                    s -> s.contains("\nstill here\n") && Tmux.lastLine(s).equals("alice@localhost TTY1>"));
            // help shows the CLI's and the service's help, each labelled.
            t.type("help");
            t.keys("Enter");
            t.await("both helps, then the prompt again", Duration.ofSeconds(20),
                    s -> s.contains("Service help (" + BOX + ")") && Tmux.lastLine(s).equals("alice@localhost TTY1>"));
            assertThat(t.screen()).contains("CLI help");
            // Ctrl-D ends with status 0.
            t.keys("C-d");
            t.awaitText("CLI-EXIT=0");
        }
        assertThat(Files.readString(history)).contains("echo still here");
        // A new session recalls the last session's commands.
        try (Tmux t = cli()) {
            t.keys("Up");
            t.await("Up recalled the previous session's last command", Duration.ofSeconds(30),
                    s -> Tmux.lastLine(s).equals("alice@localhost> help"));
            t.keys("C-u");
            t.type("quit");
            t.keys("Enter");
            t.awaitText("CLI-EXIT=0");
        }
    }

    @Test
    void aLostConnectionIsMadeAgainAndTheSessionGoesOnInItsMailBox() throws Exception {
        try (Tmux t = cli()) {
            t.type("use " + BOX);
            t.keys("Enter");
            t.await("the prompt with the MailBox", Duration.ofSeconds(30), s -> Tmux.lastLine(s).equals("alice@localhost TTY1>"));
            sys.close(); // the server goes away while the pilot reads...
            Thread.sleep(1000);
            sys = TestSystem.start(config); // ...and is back (restarted, or a standby took over)
            sys.register(new ClockService("localhost"));
            t.type("echo after the restart");
            t.keys("Enter");
            t.await("logged in again, the reply, the same MailBox", Duration.ofSeconds(40),
                    s -> s.contains("was lost; logging in again") && s.contains("Logged in again to localhost:")
                            && s.contains("\nafter the restart\n") && Tmux.lastLine(s).equals("alice@localhost TTY1>"));
            t.type("quit");
            t.keys("Enter");
            t.awaitText("CLI-EXIT=0");
        }
    }
}
