package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.Priority;
import org.junit.jupiter.api.parallel.Isolated;

/** An idle client keeps only its reader thread; the writer comes back with the next reply (docs/performance.md). */
@Isolated // looks for a writer thread by its client id, which another in-process server may also have
class IdleConnectionTest {
    @TempDir
    Path dir;

    static boolean writerOf(String clientId) {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals("ripv-socket-writer-" + clientId));
    }

    @Test
    void theWriterThreadEndsWhenIdleAndRepliesStillArrive() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("server"))) {
            sys.user("alice", "operators");
            ClientSocketHandler c = sys.login("alice");
            String id = c.session().clientId();
            long end = System.nanoTime() + Duration.ofSeconds(20).toNanos();
            while (writerOf(id)) {
                assertThat(System.nanoTime()).as("the idle writer ends").isLessThan(end);
                Thread.sleep(200);
            }
            for (int i = 0; i < 3; i++) {
                assertThat(c.call("", "?ping", Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText()).isEqualTo("pong");
            }
            assertThat(c.call("", "?whoami", Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText()).startsWith("alice");
        }
    }
}
