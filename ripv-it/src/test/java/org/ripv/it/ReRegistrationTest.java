package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.messages.Priority;
import org.ripv.probe.FreePorts;
import org.ripv.server.ServerConfig;
import org.ripv.service.ServiceConnector;

/** A server restart does not need services restarted by hand. */
class ReRegistrationTest {
    @TempDir
    Path dir;

    @Test
    void aServiceRegistersAgainWhenTheServerComesBack() throws Exception {
        int port = FreePorts.one();
        int registry = FreePorts.one();
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(port, registry, -1);
        ClockService clock = new ClockService("localhost");
        ServiceConnector connector;
        try (TestSystem first = TestSystem.start(config)) {
            first.user("alice", "operators");
            connector = ServiceConnector.connect(clock, first.serviceOptions());
            assertThat(connector.awaitRegistered(Duration.ofSeconds(20))).isTrue();
        }
        try (TestSystem second = TestSystem.start(config)) {
            ClientSocketHandler c = second.login("alice");
            long end = System.nanoTime() + Duration.ofSeconds(20).toNanos();
            while (second.server().serviceCount() == 0) {
                assertThat(System.nanoTime()).as("the service registered again").isLessThan(end);
                Thread.sleep(100);
            }
            assertThat(c.call("<ClockService>::<localhost>TTY1", "echo back again", Priority.NORMAL, Duration.ofSeconds(20), null)
                    .footer().replyText()).isEqualTo("back again");
        } finally {
            clock.stop();
        }
        connector.close();
    }
}
