package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDate;
import java.time.ZoneOffset;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.it.TestSystem;

/**
 * The audit trail kept by the state store: every audit line of a real server lands in
 * {@code DATA/audit/DAY.log}, survives a restart, and an admin (a permit rule allowing
 * {@code ?audit}) reads it with {@code ?audit}; an observer may not.
 */
class AuditTrailTest {
    @TempDir
    Path dir;
    TestSystem sys;

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    private static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, Duration.ofSeconds(30), null);
    }

    @Test
    void auditLinesAreKeptReadByAnAdminAndSurviveARestart() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators").user("olga", "observers");
        try (ClientSocketHandler m = sys.connect()) {
            assertThatThrownBy(() -> m.login("mallory", "not the password".toCharArray()));
        }
        ClientSocketHandler alice = sys.login("alice");
        OutgoingServerMessage r = call(alice, "?audit --last 20");
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().serviceId()).isEqualTo(Ids.FID_AUDIT);
        assertThat(r.footer().replyText()).contains("audit line(s), oldest first")
                .containsPattern("\\n\\S+Z WARN login-failed user=mallory ")
                .containsPattern("\\n\\S+Z INFO login user=alice ");

        OutgoingServerMessage refused = call(sys.login("olga"), "?audit");
        assertThat(refused.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(call(alice, "?audit --last 0").footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(call(alice, "?audit --since yesterday").footer().replyText()).contains("--since takes");

        Path data = sys.dataDir();
        sys.close();
        sys = null;
        Path today = data.resolve("audit").resolve(LocalDate.now(ZoneOffset.UTC) + ".log");
        assertThat(Files.readString(today)).contains("WARN login-failed user=mallory")
                .contains("INFO login user=olga");

        sys = TestSystem.start(org.ripv.server.ServerConfig.forTests(data));
        ClientSocketHandler again = sys.login("alice");
        String after = call(again, "?audit --since " + LocalDate.now(ZoneOffset.UTC)).footer().replyText();
        assertThat(after).contains("login-failed user=mallory").contains("login user=olga");
    }
}
