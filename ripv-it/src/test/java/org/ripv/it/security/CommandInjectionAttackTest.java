package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
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
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.InJvmCli;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 10, attack 1: a user allowed only {@code dir*} (and an operator allowed everything) sends
 * line breaks, ^C, ESC and a megabyte-long command, through the CLI and in crafted frames. None of
 * it reaches the glider: its files and its dive state are as before, and the next plain command works.
 */
class CommandInjectionAttackTest {
    static final Duration T = Duration.ofSeconds(30);
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
    String mailbox;
    final ByteArrayOutputStream out = new ByteArrayOutputStream();
    final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @BeforeEach
    void start() throws Exception {
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(30), YMODEM);
        int port = glider.listen(0);
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("dora").user("olga", "observers").user("alice", "operators");
        sys.rules("allow dora SerialPortServer * dir*",
                "allow @operators * * *",
                "allow @observers SerialPortServer * dir*",
                "deny  @observers SerialPortServer * *");
        SerialPortServer serial = new SerialPortServer("localhost", List.of(LinkSettings.defaults("tcp://127.0.0.1:" + port)
                .withIdleTimeout(Duration.ofSeconds(1)).withReconnectEvery(Duration.ofMillis(300)).withYmodem(YMODEM)),
                null, false, dir.resolve("work"));
        sys.register(serial);
        mailbox = "<SerialPortServer>::<localhost>" + serial.handles().get(0);
    }

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
    }

    static List<String> attacks() {
        return List.of("dir\rGO", "dir\r\ndel GLIDER.CFG", "dir\ndel GLIDER.CFG", "dir\u0003", "dir\u001b", "dir\u0000GO",
                "dir\u007f", "dir\u0085GO", "dir\u009b", "dir " + "x".repeat(1_000_000) + "\rGO", "dir" + "x".repeat(1_000_000));
    }

    private void assertGliderUntouched() throws Exception {
        assertThat(glider.submerged()).as("the glider did not dive").isFalse();
        assertThat(Files.exists(glider.directory().resolve("GLIDER.CFG"))).as("GLIDER.CFG not deleted").isTrue();
    }

    @Test
    void craftedFramesWithControlCharactersOrOverLongAreRefusedBeforeAnyRule() throws Exception {
        for (String user : List.of("dora", "olga", "alice")) {
            ClientSocketHandler c = sys.login(user);
            for (String attack : attacks()) {
                Header h = new Header(c.nextId(), new IdBadge("000000", user), List.of("operators"), "", mailbox, attack,
                        Priority.URGENT, null);
                OutgoingServerMessage r = c.send(h, null).get(T.toSeconds(), TimeUnit.SECONDS);
                assertThat(r.status()).as(user + ": " + Header.abbreviate(attack)).isEqualTo(Status.ERROR);
                assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.BAD_REQUEST);
                assertThat(r.footer().replyText()).as("quoted short").hasSizeLessThan(400)
                        .containsAnyOf("control character", "characters long");
            }
            assertGliderUntouched();
        }
        // the link and the glider are fine: the plain command still works
        OutgoingServerMessage dir = sys.login("dora").call(mailbox, "dir", Priority.NORMAL, T, null);
        assertThat(dir.status()).as(dir.footer().replyText()).isEqualTo(Status.OK);
        assertThat(dir.footer().replyText()).contains("GLIDER.CFG");
        assertGliderUntouched();
    }

    @Test
    void theCliCannotSmuggleASecondLine() throws Exception {
        for (String attack : List.of("dir\rGO", "dir\r\ndel GLIDER.CFG", "dir\u0003", "dir\u001b[2J")) {
            assertThat(cli("dora", "use " + mailbox, attack)).as(out + "" + err).isNotZero();
            assertThat(err.toString(StandardCharsets.UTF_8)).contains("control character").contains("BAD_REQUEST");
            assertGliderUntouched();
        }
        assertThat(cli("dora", "use " + mailbox, "dir")).as(err.toString(StandardCharsets.UTF_8)).isZero();
        assertThat(out.toString(StandardCharsets.UTF_8)).contains("GLIDER.CFG");
        // a permitted line is still permitted; the forbidden one alone is still forbidden
        assertThat(cli("dora", "use " + mailbox, "GO")).isNotZero();
        assertThat(err.toString(StandardCharsets.UTF_8)).contains("FORBIDDEN");
        assertGliderUntouched();
    }

    private int cli(String user, String... lines) {
        return InJvmCli.exec(out, err, InJvmCli.as(user, "localhost:" + sys.server().port(), "--timeout", "60"), lines);
    }
}
