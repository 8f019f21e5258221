package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;

/**
 * Issue 32, item 12: a workflow typed in the GUI's editor or the web page is uploaded only to be
 * queued; when {@code ?queue add MAILBOX NAME --typed} refuses it, it leaves the upload store
 * again. A file uploaded on its own stays when refused, and --typed never deletes another user's file.
 */
class TypedWorkflowRefusalTest {
    static final String BOX = "<ClockService>::<localhost>TTY1";
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path dir;
    TestSystem sys;

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    void upload(ClientSocketHandler c, String name, String text) throws Exception {
        Path local = Files.createDirectories(dir.resolve("local")).resolve(name);
        Files.writeString(local, text, StandardCharsets.UTF_8);
        c.upload(local, name, null);
    }

    @Test
    void aRefusedTypedWorkflowLeavesTheStoreAndOthersStay() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        sys.user("bob", "operators");
        sys.register(new ClockService("localhost"));
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler bob = sys.login("bob");

        upload(alice, "typo.wf", "send time\nymodem:gte x\n");
        OutgoingServerMessage r = call(alice, "?queue add " + BOX + " typo.wf --typed");
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().replyText()).contains("typo.wf:2:");
        assertThat(call(alice, "?ulfiles").footer().replyText()).doesNotContain("typo.wf");

        // the same refusal of a file uploaded on its own: it stays, to be mended
        upload(alice, "kept.wf", "ymodem:gte x\n");
        assertThat(call(alice, "?queue add " + BOX + " kept.wf").status()).isEqualTo(Status.ERROR);
        assertThat(call(alice, "?ulfiles").footer().replyText()).contains("kept.wf");
        // --typed by someone who did not upload it deletes nothing
        assertThat(call(bob, "?queue add " + BOX + " kept.wf --typed").status()).isEqualTo(Status.ERROR);
        assertThat(call(alice, "?ulfiles").footer().replyText()).contains("kept.wf");

        // a typed workflow that parses is queued, and its file stays as any upload does
        upload(alice, "good.wf", "send time\n");
        OutgoingServerMessage ok = call(alice, "?queue add " + BOX + " good.wf --typed");
        assertThat(ok.status()).as(ok.footer().replyText()).isEqualTo(Status.OK);
        assertThat(call(alice, "?ulfiles").footer().replyText()).contains("good.wf");
        assertThat(call(alice, "?queue add " + BOX + " good.wf --typo").footer().replyText())
                .contains("usage: ?queue add MAILBOX NAME [--typed]");
    }
}
