package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Priority;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.ConsoleTap;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 23, item 3: {@code wait-for '((.*)*)*X'}, queued by a user with queue rights, ran
 * against every vehicle line with Java's backtracking regex on the RMI thread of the service's
 * console call: the server burned CPU and every MailBox of the service stopped streaming.
 */
class RegexStallAttackTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;

    @Test
    void aCatastrophicWaitForNeitherStallsTheConsoleNorMissesItsLine() throws Exception {
        try (GliderSimulator glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), org.ripv.services.serial.ymodem.YmodemConfig.lrzsz());
             TestSystem sys = TestSystem.start(dir.resolve("sys"))) {
            int port = glider.listen(0);
            sys.user("mallory", "operators");
            LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                    .withReconnectEvery(Duration.ofMillis(300));
            SerialPortServer serial = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
            sys.register(serial);
            String mb = "<SerialPortServer>::<localhost>" + serial.handles().get(0);
            ClientSocketHandler mallory = sys.login("mallory");
            Path wf = dir.resolve("stall.wf");
            Files.writeString(wf, "wait-for '((.*)*)*X' timeout=5m\nnotify \"seen\"\n", StandardCharsets.UTF_8);
            mallory.upload(wf, "stall.wf", null);
            assertThat(reply(mallory, "?queue add " + mb + " stall.wf")).contains("queued workflow");

            ConsoleTap.publish(serial, ConsoleEntry.event(mb, VehicleEvent.SURFACED, "test", null, null));
            long end = System.nanoTime() + T.toNanos();
            while (!reply(mallory, "?queue " + mb).contains("running")) {
                assertThat(System.nanoTime()).as("the wait-for step runs").isLessThan(end);
                Thread.sleep(100);
            }
            // 40 characters without X: a backtracking match of ((.*)*)*X takes longer than the universe.
            String line = "a".repeat(40);
            CompletableFuture<Void> call = CompletableFuture.runAsync(() -> {
                try {
                    for (int i = 0; i < 20; i++) {
                        ConsoleTap.publish(serial, ConsoleEntry.line(mb, line));
                    }
                    ConsoleTap.publish(serial, ConsoleEntry.line(mb, "the X at last"));
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            call.get(20, TimeUnit.SECONDS); // before the fix: a TimeoutException, the console call stuck
            end = System.nanoTime() + T.toNanos();
            String receipts;
            while (!(receipts = reply(mallory, "?receipts " + mb)).matches("(?s).*result: (DONE|FAILED|CUT).*")) {
                assertThat(System.nanoTime()).as("the wait-for step sees its line").isLessThan(end);
                Thread.sleep(100);
            }
            assertThat(receipts).contains("result: DONE");

            // A pattern RE2 cannot run in linear time (a back-reference) is refused with the reason.
            Path bad = dir.resolve("backref.wf");
            Files.writeString(bad, "send dir expect='(a)\\1'\n", StandardCharsets.UTF_8);
            mallory.upload(bad, "backref.wf", null);
            assertThat(reply(mallory, "?queue add " + mb + " backref.wf")).contains("bad expect regex").contains("RE2");
        }
    }

    private static String reply(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null).footer().replyText();
    }
}
