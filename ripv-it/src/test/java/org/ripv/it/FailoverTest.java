package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.failover.ServerList;
import org.ripv.messages.Priority;
import org.ripv.probe.FreePorts;
import org.ripv.server.ServerConfig;
import org.ripv.service.ServiceConnector;
import picocli.CommandLine;

/**
 * {@code --server host1,host2} on one machine: a service, the CLI and the GUI's connection go to
 * whichever server of the list answers, and the service moves to the second server by itself
 * when the first goes away (the takeover itself, with PostgreSQL, is MultiHostTest's).
 */
class FailoverTest {
    @TempDir
    Path dir;

    @Test
    void servicesAndClientsUseWhicheverServerOfTheListAnswers() throws Exception {
        int[] p = FreePorts.several(4);
        ServerConfig a = ServerConfig.forTests(dir.resolve("a")).withPorts(p[0], p[1], -1);
        ServerConfig b = ServerConfig.forTests(dir.resolve("b")).withPorts(p[2], p[3], -1);
        ServerList registries = ServerList.parse("localhost:" + p[1] + ",localhost:" + p[3], 1099);
        ClockService clock = new ClockService("localhost");
        ServiceConnector connector;
        try (TestSystem first = TestSystem.start(a)) {
            first.user("alice", "operators");
            connector = ServiceConnector.connect(clock, first.serviceOptions().withServers(registries));
            assertThat(connector.awaitRegistered(Duration.ofSeconds(20))).isTrue();
            // The standby shares the secret and the users (docs/operations.md "A hot standby").
            Files.createDirectories(dir.resolve("b"));
            Files.copy(dir.resolve("a").resolve("service.secret"), dir.resolve("b").resolve("service.secret"));
            Files.copy(a.permitFile(), b.permitFile());
        }
        try (TestSystem second = TestSystem.start(b)) {
            long end = System.nanoTime() + Duration.ofSeconds(15).toNanos();
            while (second.server().serviceCount() == 0) {
                assertThat(System.nanoTime()).as("the service registered with the second server").isLessThan(end);
                Thread.sleep(100);
            }
            // The GUI's connection: a list as the host, the dead first server skipped.
            String list = "localhost:" + p[0] + ",localhost:" + p[2];
            try (ClientSocketHandler c = ClientSocketHandler.connect(list, 4444)) {
                c.login("alice", TestSystem.PASSWORD.toCharArray());
                assertThat(c.server()).isEqualTo("localhost:" + p[2]);
                assertThat(c.call("<ClockService>::<localhost>TTY1", "echo via the list", Priority.NORMAL, Duration.ofSeconds(20), null)
                        .footer().replyText()).isEqualTo("via the list");
            }
            // The CLI says which server it took and why.
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(out, true, StandardCharsets.UTF_8),
                    new PrintStream(err, true, StandardCharsets.UTF_8));
            int code = new CommandLine(cmd).execute("--server", list, "--user", "alice", "--password", TestSystem.PASSWORD,
                    "--known-hosts", TestSystem.knownHosts().toString(), "--exec", "use <ClockService>::<localhost>TTY1",
                    "--exec", "echo from the cli");
            assertThat(code).as(err.toString(StandardCharsets.UTF_8)).isZero();
            assertThat(out.toString(StandardCharsets.UTF_8)).contains("from the cli");
            assertThat(err.toString(StandardCharsets.UTF_8)).contains("connected to localhost:" + p[2] + " (server 2 of 2)")
                    .contains("localhost:" + p[0] + " did not answer");
        } finally {
            clock.stop();
            connector.close();
        }
    }

    @Test
    void theGuiReconnectsToTheSecondServerWhenTheFirstGoesAway() throws Exception {
        int[] p = FreePorts.several(4);
        ServerConfig a = ServerConfig.forTests(dir.resolve("a")).withPorts(p[0], p[1], -1);
        ServerConfig b = ServerConfig.forTests(dir.resolve("b")).withPorts(p[2], p[3], -1);
        java.util.concurrent.ExecutorService ui = java.util.concurrent.Executors.newSingleThreadExecutor();
        org.ripv.client.managers.GuiManager gui = new org.ripv.client.managers.GuiManager(new org.ripv.client.managers.ClientModel(),
                ui, ClientSocketHandler::connect, new org.ripv.client.managers.GuiManager.Timings(Duration.ofSeconds(30),
                Duration.ofMillis(200), Duration.ofSeconds(1)));
        try {
            try (TestSystem first = TestSystem.start(a)) {
                first.user("alice", "operators");
                Files.createDirectories(dir.resolve("b"));
                Files.copy(dir.resolve("a").resolve("service.secret"), dir.resolve("b").resolve("service.secret"));
                Files.copy(a.permitFile(), b.permitFile());
                // What the log-in dialog passes for "localhost:A, localhost:B" (HostPort keeps a list whole).
                String list = org.ripv.client.panels.HostPort.parse("localhost:" + p[0] + ", localhost:" + p[2], 4444).host();
                gui.logIn(list, 4444, "alice", TestSystem.PASSWORD.toCharArray()).get(20, java.util.concurrent.TimeUnit.SECONDS);
                assertThat(gui.connection().server()).isEqualTo("localhost:" + p[0]);
            }
            try (TestSystem second = TestSystem.start(b)) {
                long end = System.nanoTime() + Duration.ofSeconds(15).toNanos();
                while (gui.connection() == null || !gui.connection().server().equals("localhost:" + p[2])) {
                    assertThat(System.nanoTime()).as("the GUI logged in to the second server by itself").isLessThan(end);
                    Thread.sleep(100);
                }
                assertThat(gui.connection().call("", "?ping", org.ripv.messages.Priority.NORMAL, Duration.ofSeconds(10), null)
                        .footer().status().toString()).isEqualTo("OK");
            }
        } finally {
            gui.close();
            ui.shutdownNow();
        }
    }

    @Test
    void aListNobodyAnswersNamesEveryServer() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err, true, StandardCharsets.UTF_8));
        int code = new CommandLine(cmd).execute("--server", "localhost:1,127.0.0.1:2", "--user", "a", "--password", "b", "--exec", "?ping");
        assertThat(code).isEqualTo(CliCommand.EXIT_NO_SESSION);
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("no server of localhost:1,127.0.0.1:2 answers")
                .contains("localhost:1 did not answer").contains("127.0.0.1:2 did not answer");
        assertThat(new CommandLine(new CliCommand(new ByteArrayInputStream(new byte[0]), new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(err))).execute("--server", "a:1,b:x", "--user", "a", "--password", "b")).isEqualTo(2);
    }
}
