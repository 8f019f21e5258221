package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

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
import org.ripv.server.workflow.WorkflowQueues;

/**
 * Issue 23, item 7: a user with queue rights queued 100 one-MiB workflows to each of any number
 * of invented MailBoxes — 30 MB of disk and 150 MB of heap in seconds, without end. Queues are now
 * only for MailBoxes that exist or have existed, with per-user and total caps.
 */
class QueueFloodAttackTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;

    @Test
    void noQueueForAnInventedMailBoxAndAUserIsCappedInCountAndSize() throws Exception {
        try (TestSystem sys = TestSystem.start(dir)) {
            sys.user("mallory", "operators");
            for (String host : new String[] {"h1", "h2", "h3"}) {
                sys.register(new VehicleConsoleService(host, "ru29"));
            }
            ClientSocketHandler mallory = sys.login("mallory");
            Path small = dir.resolve("small.wf");
            Files.writeString(small, "notify \"hello\"\n");
            mallory.upload(small, "small.wf", null);

            for (int i = 0; i < 3; i++) {
                OutgoingServerMessage r = call(mallory, "?queue add <SerialPortServer>::<nowhere>invented" + i + " small.wf");
                assertThat(r.status()).isEqualTo(Status.ERROR);
                assertThat(r.footer().replyText()).contains("exists or has existed");
            }
            assertThat(Files.exists(sys.dataDir().resolve("workflows/queues"))
                    && Files.list(sys.dataDir().resolve("workflows/queues")).findAny().isPresent()).as("nothing stored").isFalse();

            // Count: 100 per MailBox, 200 per user over all of them.
            int queued = 0;
            String refusal = "";
            outer:
            for (String host : new String[] {"h1", "h2", "h3"}) {
                for (int i = 0; i < WorkflowQueues.MAX_PER_MAILBOX; i++) {
                    OutgoingServerMessage r = call(mallory, "?queue add <VehicleConsole>::<" + host + ">ru29 small.wf");
                    if (r.status() != Status.OK) {
                        refusal = r.footer().replyText();
                        break outer;
                    }
                    queued++;
                }
            }
            assertThat(queued).as(refusal).isEqualTo(WorkflowQueues.MAX_PER_USER);
            assertThat(refusal).contains("mallory has " + WorkflowQueues.MAX_PER_USER + " workflows");
            for (String host : new String[] {"h1", "h2"}) {
                call(mallory, "?queue clear <VehicleConsole>::<" + host + ">ru29");
            }

            // Size: one-MiB workflows run into the per-user size cap long before the disk fills.
            StringBuilder big = new StringBuilder();
            String line = "notify \"" + "x".repeat(1000) + "\"\n";
            while (big.length() + line.length() < (1 << 20) - 100) {
                big.append(line);
            }
            Path bigFile = dir.resolve("big.wf");
            Files.writeString(bigFile, big);
            mallory.upload(bigFile, "big.wf", null);
            int bigQueued = 0;
            while (true) {
                OutgoingServerMessage r = call(mallory, "?queue add <VehicleConsole>::<h1>ru29 big.wf");
                if (r.status() != Status.OK) {
                    assertThat(r.footer().replyText()).contains("characters");
                    break;
                }
                bigQueued++;
                assertThat(bigQueued).isLessThanOrEqualTo(8);
            }
            assertThat((long) bigQueued * big.length()).isLessThanOrEqualTo(WorkflowQueues.MAX_CHARS_PER_USER);
        }
    }

    private static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }
}
