package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;
import org.ripv.testing.Tools;

/**
 * Issue 3's "done when", through the real server and the CLI: the SerialPortServer registered
 * over RMI, the glider simulator on TCP (and on a socat pty pair), an operator at the CLI.
 */
class SerialEndToEndTest {
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
    Process socat;
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    ByteArrayOutputStream err = new ByteArrayOutputStream();

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
        if (socat != null) {
            socat.destroy();
            try {
                // socat removes its pty links as it exits; let it finish before @TempDir is deleted.
                socat.waitFor(10, java.util.concurrent.TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    private String start(String device) throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        LinkSettings link = LinkSettings.defaults(device).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(YMODEM);
        SerialPortServer serial = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
        sys.register(serial);
        return "<SerialPortServer>::<localhost>" + serial.handles().get(0);
    }

    private int cli(String... lines) {
        return InJvmCli.exec(out, err, InJvmCli.as("alice", "localhost:" + sys.server().port(), "--timeout", "120"), lines);
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    /** The operator's whole session against one link. */
    private void operatorSession(String mailbox) throws Exception {
        // dir returns the glider's listing
        assertThat(cli("use " + mailbox, "dir")).as(err.toString()).isZero();
        assertThat(out()).contains("MISSION1.LOG").contains("GLIDER.CFG");

        // ymodem:get of a 1 MB log lands byte-identical in the server's download directory
        byte[] log = new byte[1024 * 1024];
        new Random(11).nextBytes(log);
        Files.write(glider.directory().resolve("BIG.LOG"), log);
        assertThat(cli("use " + mailbox, "ymodem:get BIG.LOG", "?dlfiles")).as(err.toString()).isZero();
        assertThat(out()).contains("received BIG.LOG (1048576 bytes)").contains("BIG.LOG");
        assertThat(Files.readAllBytes(sys.downloaded("BIG.LOG"))).isEqualTo(log);
        Path back = dir.resolve("back");
        assertThat(cli("get BIG.LOG " + back)).as(err.toString()).isZero();
        assertThat(Files.readAllBytes(back.resolve("BIG.LOG"))).isEqualTo(log);

        // a binary sent with put, then ymodem:put, arrives byte-identical on the glider
        byte[] binary = new byte[250_000];
        new Random(12).nextBytes(binary);
        Path local = dir.resolve("GLIDER.BIN");
        Files.write(local, binary);
        assertThat(cli("put " + local, "use " + mailbox, "ymodem:put GLIDER.BIN")).as(err.toString()).isZero();
        assertThat(out()).contains("sent GLIDER.BIN (250000 bytes)");
        assertThat(Files.readAllBytes(glider.directory().resolve("GLIDER.BIN"))).isEqualTo(binary);
    }

    @Test
    void overTcp() throws Exception {
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), YMODEM);
        int port = glider.listen(0);
        String mailbox = start("tcp://127.0.0.1:" + port);
        operatorSession(mailbox);

        // GO submerges the glider: the MailBox is not available until it surfaces
        assertThat(cli("use " + mailbox, "GO")).as(err.toString()).isZero();
        assertThat(out()).contains("submerging");
        assertThat(cli("?status " + mailbox)).isZero();
        assertThat(out()).contains("not available");
        awaitStatus(mailbox, ": available", Duration.ofSeconds(15));
        assertThat(cli("use " + mailbox, "dir")).isZero();
        assertThat(out()).contains("MISSION1.LOG");
    }

    @Test
    void overAPseudoTerminal() throws Exception {
        Tools.require("socat");
        Path a = dir.resolve("ttyV0");
        Path b = dir.resolve("ttyV1");
        socat = new ProcessBuilder("socat", "pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b)
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        awaitFile(a);
        awaitFile(b);
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), YMODEM);
        glider.attach(b.toString());
        String mailbox = start(a.toString());
        assertThat(mailbox).endsWith(">ttyV0");
        operatorSession(mailbox);
    }

    private void awaitStatus(String mailbox, String expected, Duration timeout) throws IOException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            cli("?status " + mailbox);
            if (out().contains(expected)) {
                return;
            }
            assertThat(System.nanoTime() - deadline).as("status of " + mailbox + ": " + out()).isNegative();
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(200)); // ?status is asked, never announced
        }
    }

    private static void awaitFile(Path p) {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!Files.exists(p)) {
            assertThat(System.nanoTime() - deadline).as("socat made " + p).isNegative();
            LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(20));
        }
    }
}
