package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.ConsoleTap;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 23, item 11: {@code ?mailboxes} showed every vehicle's state and last position to any
 * logged-in user. A user without the read right on a MailBox now sees its address only.
 */
class PositionLeakAttackTest {
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path dir;

    @Test
    void aUserWithoutTheReadRightSeesNoStateOrPosition() throws Exception {
        try (GliderSimulator glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), YmodemConfig.lrzsz());
             TestSystem sys = TestSystem.start(dir.resolve("sys"))) {
            int port = glider.listen(0);
            sys.user("alice", "operators").user("eve", "guests");
            SerialPortServer serial = new SerialPortServer("localhost", List.of(LinkSettings.defaults("tcp://127.0.0.1:" + port)
                    .withIdleTimeout(Duration.ofSeconds(1)).withReconnectEvery(Duration.ofMillis(300))), null, false, dir.resolve("work"));
            sys.register(serial);
            String mb = "<SerialPortServer>::<localhost>" + serial.handles().get(0);
            ConsoleTap.publish(serial, ConsoleEntry.event(mb, VehicleEvent.SURFACED, "GPS Location: 4130.000 N -7040.000 E", 41.5, -70.6667));

            ClientSocketHandler alice = sys.login("alice");
            long end = System.nanoTime() + T.toNanos();
            String seen;
            while (!(seen = call(alice, "?mailboxes").footer().replyText()).contains("41.5")) {
                assertThat(System.nanoTime()).as("the operator sees the position: " + seen).isLessThan(end);
                Thread.sleep(100);
            }

            ClientSocketHandler eve = sys.login("eve");
            OutgoingServerMessage r = call(eve, "?mailboxes");
            assertThat(r.footer().replyText()).contains(mb).doesNotContain("41.5").doesNotContain("70.6")
                    .doesNotContain("on call").contains("?read");
            MailboxList list = (MailboxList) r.footer().result();
            for (MailboxStatus s : list.mailboxes()) {
                assertThat(s.session()).as("no session state for " + s.address()).isNull();
                assertThat(s.running()).isEmpty();
            }
            OutgoingServerMessage status = call(eve, "?status " + mb);
            assertThat(status.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(status.footer().replyText()).contains("eve").doesNotContain("41.5");
        }
    }

    private static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }
}
