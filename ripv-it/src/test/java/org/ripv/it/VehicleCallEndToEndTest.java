package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Predicate;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.server.RIPVServer;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;
import org.slf4j.LoggerFactory;
import picocli.CommandLine;

/**
 * A vehicle calling in, through the real server: the SerialPortServer registered over RMI with a
 * {@code listen://} link named ru29, the glider simulator calling it over TCP, an operator at
 * the CLI. The call's life shows in {@code ?status}; what the service publishes reaches
 * {@code RIPVServer.console} over RMI (read here from the server's log of it, until the fan-out
 * to watchers gives a client-side view).
 */
class VehicleCallEndToEndTest {
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
    ListAppender<ILoggingEvent> serverLog = new ListAppender<>();
    Logger serverLogger = (Logger) LoggerFactory.getLogger(RIPVServer.class);
    Level oldLevel;
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();

    @AfterEach
    void stop() {
        if (glider != null) {
            glider.close();
        }
        if (sys != null) {
            sys.close();
        }
        serverLogger.detachAppender(serverLog);
        serverLogger.setLevel(oldLevel);
    }

    private int cli(String... lines) {
        out.reset();
        err.reset();
        List<String> all = new ArrayList<>(List.of("--server", "localhost:" + sys.server().port(), "--user", "alice",
                "--password", TestSystem.PASSWORD, "--timeout", "60"));
        for (String l : lines) {
            all.add("--exec");
            all.add(l);
        }
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]),
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        return new CommandLine(cmd).execute(all.toArray(String[]::new));
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    private void awaitStatus(String mailbox, String expected) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (true) {
            cli("?status " + mailbox);
            if (out().contains(expected)) {
                return;
            }
            assertThat(System.nanoTime() - deadline).as("status of " + mailbox + ": " + out()).isNegative();
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(200)); // ?status is asked, never announced
        }
    }

    private List<String> consoleAtServer() {
        List<String> got = new ArrayList<>();
        for (ILoggingEvent e : serverLog.list) {
            if (e.getMessage().startsWith("console ")) {
                got.add(e.getFormattedMessage());
            }
        }
        return got;
    }

    private void awaitConsole(String what, Predicate<List<String>> done) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (!done.test(consoleAtServer())) {
            assertThat(System.nanoTime() - deadline).as(what + " in " + consoleAtServer()).isNegative();
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(50));
        }
    }

    @Test
    void theSimulatorCallsInThroughTheServerAndTheCallShowsInStatusAndTheConsole() throws Exception {
        oldLevel = serverLogger.getLevel();
        serverLogger.setLevel(Level.DEBUG);
        serverLog.start();
        serverLogger.addAppender(serverLog);

        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        LinkSettings link = LinkSettings.defaults("listen://127.0.0.1:0").withIdleTimeout(Duration.ofSeconds(1))
                .withYmodem(YMODEM);
        SerialPortServer serial = SerialPortServer.withCalls("localhost",
                List.of(new VehicleLink(link, CallSettings.defaults().withName("ru29"))), null, false, dir.resolve("work"));
        sys.register(serial);
        String mailbox = "<SerialPortServer>::<localhost>ru29";

        assertThat(cli("?status " + mailbox)).isZero();
        assertThat(out()).contains("not available").contains("no call yet");

        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(1), YMODEM);
        glider.call("127.0.0.1", serial.listenPort("ru29"), "ru29", Duration.ofSeconds(2), Duration.ofSeconds(8));
        awaitStatus(mailbox, "on call since");
        assertThat(cli("use " + mailbox, "dir")).as(err.toString()).isZero();
        assertThat(out()).contains("MISSION1.LOG");

        awaitConsole("the call's console", c -> c.stream().anyMatch(l -> l.contains("COMMAND dir")));
        List<String> c = consoleAtServer();
        assertThat(c).allSatisfy(l -> assertThat(l).startsWith("console " + mailbox + ": "));
        assertThat(c).anySatisfy(l -> assertThat(l).contains("LINE Glider ru29 at surface."));
        assertThat(c).anySatisfy(l -> assertThat(l).contains("EVENT call 1 (caller 127.0.0.1:").contains("at 41.63323, -70.53647"));
        assertThat(c).anySatisfy(l -> assertThat(l).contains("LINE MISSION1.LOG"));

        awaitStatus(mailbox, "dived at");
        awaitConsole("DIVED", l -> l.stream().anyMatch(s -> s.contains("EVENT the caller hung up")));
        assertThat(cli("use " + mailbox, "dir")).isNotZero();
        assertThat(out() + err).contains("not on a call");
        awaitStatus(mailbox, "call 2");
    }
}
