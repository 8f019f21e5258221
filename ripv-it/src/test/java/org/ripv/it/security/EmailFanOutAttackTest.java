package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import com.icegreen.greenmail.util.GreenMail;
import com.icegreen.greenmail.util.ServerSetup;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;
import org.ripv.server.SessionOptions;
import org.ripv.server.notify.Smtp;

/**
 * Issue 23, item 9: {@code ?notify add email 'g:a@x.org,c@y.org,…;'} was taken as one address
 * and mailed every member of the group, past the per-user cap on subscriptions.
 */
class EmailFanOutAttackTest {
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path dir;

    @Test
    void aSubscriptionMailsOneMailboxNeverAGroupOrAList() throws Exception {
        GreenMail mail = new GreenMail(new ServerSetup(0, "127.0.0.1", ServerSetup.PROTOCOL_SMTP).dynamicPort());
        mail.setUser("ripv@example.org", "ripv", "mail secret");
        mail.start();
        try {
            Path credentials = dir.resolve("smtp.properties");
            Files.writeString(credentials, "user=ripv\npassword=mail secret\nfrom=ripv@example.org\n");
            Smtp smtp = Smtp.parse("127.0.0.1:" + mail.getSmtp().getPort(), credentials);
            try (TestSystem sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")),
                    SessionOptions.defaults().withSmtp(smtp).withNotifyTiming(Duration.ofMillis(200), Duration.ofSeconds(2)))) {
                sys.user("mallory", "operators");
                VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
                sys.register(vehicle);
                ClientSocketHandler mallory = sys.login("mallory");
                StringBuilder group = new StringBuilder("g:");
                for (int i = 0; i < 50; i++) {
                    group.append(i == 0 ? "" : ",").append("v").append(i).append("@example.org");
                }
                group.append(';');
                for (String fanOut : new String[] {group.toString(), "a@example.org,c@example.org", "Eve<e@example.org>"}) {
                    OutgoingServerMessage r = call(mallory, "?notify add email " + fanOut + " SURFACED");
                    assertThat(r.status()).as(fanOut).isEqualTo(Status.ERROR);
                    assertThat(r.footer().replyText()).contains("one e-mail address");
                }
                assertThat(call(mallory, "?notify add email ops@example.org SURFACED").status()).isEqualTo(Status.OK);
                assertThat(call(mallory, "?notify list").footer().replyText()).contains("1 subscription(s)").doesNotContain("v1@");

                vehicle.event(VehicleEvent.SURFACED, "", 41.0, -70.0);
                assertThat(mail.waitForIncomingEmail(T.toMillis(), 1)).isTrue();
                Thread.sleep(1_000); // nothing else follows
                assertThat(mail.getReceivedMessages()).hasSize(1);
                assertThat(mail.getReceivedMessages()[0].getAllRecipients()).extracting(Object::toString)
                        .containsExactly("ops@example.org");
            }
        } finally {
            mail.stop();
        }
    }

    private static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }
}
