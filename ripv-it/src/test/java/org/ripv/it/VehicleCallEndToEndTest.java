package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/**
 * A vehicle calling in, through the real server: the SerialPortServer registered over RMI with a
 * {@code listen://} link named ru29, the glider simulator calling it over TCP, an operator at
 * the CLI. The call's life shows in {@code ?status}; what the service publishes reaches two
 * watchers over their sockets ({@code ?watch}, one of them an observer), identically.
 */
class VehicleCallEndToEndTest {
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
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
    }

    private int cli(String... lines) {
        return InJvmCli.exec(out, err, InJvmCli.as("alice", "localhost:" + sys.server().port(), "--timeout", "60"), lines);
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

    @Test
    void theSimulatorCallsInThroughTheServerAndTheCallShowsInStatusAndTheConsole() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators").user("olga", "observers");
        LinkSettings link = LinkSettings.defaults("listen://127.0.0.1:0").withIdleTimeout(Duration.ofSeconds(1))
                .withYmodem(YMODEM);
        SerialPortServer serial = SerialPortServer.withCalls("localhost",
                List.of(new VehicleLink(link, CallSettings.defaults().withName("ru29"))), null, false, dir.resolve("work"));
        sys.register(serial);
        String mailbox = "<SerialPortServer>::<localhost>ru29";

        assertThat(cli("?status " + mailbox)).isZero();
        assertThat(out()).contains("not available").contains("no call yet");
        var alice = sys.login("alice");
        var olga = sys.login("olga");
        org.ripv.it.console.Pushes a = org.ripv.it.console.Pushes.on(alice);
        org.ripv.it.console.Pushes o = org.ripv.it.console.Pushes.on(olga);
        for (var c : List.of(alice, olga)) {
            assertThat(c.call("", "?watch " + mailbox, org.ripv.messages.Priority.NORMAL, Duration.ofSeconds(20), null)
                    .status()).isEqualTo(org.ripv.messages.Status.OK);
        }

        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(1), YMODEM);
        glider.call("127.0.0.1", serial.listenPort("ru29"), "ru29", Duration.ofSeconds(2), Duration.ofSeconds(8));
        awaitStatus(mailbox, "on call since");
        assertThat(cli("use " + mailbox, "dir")).as(err.toString()).isZero();
        assertThat(out()).contains("MISSION1.LOG");

        Duration t = Duration.ofSeconds(30);
        assertThat(a.await(e -> e.kind() == org.ripv.messages.ConsoleEntry.Kind.COMMAND && e.text().equals("dir"), t)).isTrue();
        var command = a.entries.stream().filter(e -> e.kind() == org.ripv.messages.ConsoleEntry.Kind.COMMAND).findFirst().orElseThrow();
        assertThat(command.user()).isEqualTo("alice");
        assertThat(a.entries).allSatisfy(e -> assertThat(e.mailbox()).isEqualTo(mailbox));
        assertThat(a.texts()).contains("Glider ru29 at surface.");
        var surfaced = a.entries.stream().filter(e -> e.event() == org.ripv.messages.VehicleEvent.SURFACED).findFirst().orElseThrow();
        assertThat(surfaced.text()).contains("call 1 (caller 127.0.0.1:");
        assertThat(surfaced.lat()).isCloseTo(41.63323, org.assertj.core.data.Offset.offset(1e-5)); // 4137.994 N
        assertThat(surfaced.lon()).isCloseTo(-70.53647, org.assertj.core.data.Offset.offset(1e-5)); // -7032.188 E
        // dir's output follows its COMMAND entry in pushes of their own: on a loaded machine a moment later
        assertThat(a.await(e -> e.text().contains("MISSION1.LOG"), t)).as(String.join("\n", a.texts())).isTrue();

        awaitStatus(mailbox, "dived at");
        assertThat(a.await(e -> e.event() == org.ripv.messages.VehicleEvent.DIVED, t)).isTrue();
        assertThat(o.await(e -> e.event() == org.ripv.messages.VehicleEvent.DIVED, t)).isTrue();
        assertThat(o.entries).isEqualTo(a.entries);
        assertThat(out()).contains("vehicle (dived").contains("at 41.63323, -70.53647").contains("1 call");
        var h = (org.ripv.messages.ConsoleBatch) olga.call("", "?history " + mailbox, org.ripv.messages.Priority.NORMAL,
                Duration.ofSeconds(20), null).footer().result();
        assertThat(h.entries()).extracting(org.ripv.messages.ConsoleEntry::text).contains("Glider ru29 at surface.", "dir");
        assertThat(cli("use " + mailbox, "dir")).isNotZero();
        assertThat(out() + err).contains("not on a call");
        // The next call is taken: SURFACED says which call of this run it is (the status counts them once, as "N calls").
        assertThat(a.await(e -> e.event() == org.ripv.messages.VehicleEvent.SURFACED && e.text().startsWith("call 2 "), t)).isTrue();
        awaitStatus(mailbox, "on call since");
    }
}
