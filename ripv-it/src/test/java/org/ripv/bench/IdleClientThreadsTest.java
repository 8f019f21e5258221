package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.net.SocketFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.Tls;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.permit.PermitFile;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Issue 26: idle clients cost the server no thread each. The server jar is launched as
 * {@code ./ripv server} runs it, with the 1 GiB heap of the 10,000-client benchmark; 1,000 clients
 * log in over TLS and stay idle; the server's threads grow by a bounded few (before: one per
 * client), a logged-in user is still answered, and the client cap still refuses with its message.
 */
@ResourceLock(Shared.CPU)
class IdleClientThreadsTest {
    private static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
    private static final Path JAR = ROOT.resolve("ripv-server/target/ripv-server.jar");
    private static final int CLIENTS = 1_000;
    /** Selector threads (at most 8), log-in waiters (one per opener at most), pools that start lazily: far below 1,000. */
    private static final int MORE_THREADS_AT_MOST = 60;

    @TempDir
    Path tmp;

    @Test
    void aThousandIdleTlsClientsUseABoundedNumberOfServerThreads() throws Exception {
        assertThat(JAR).as("the server jar (mvn -pl ripv-it -am verify builds it)").isRegularFile();
        Path data = Files.createDirectories(tmp.resolve("data"));
        PermitFile.setUser(data.resolve("permit.txt"), "idle", "idle-password".toCharArray(), List.of("operators"), 1000);
        Path log = tmp.resolve("server.log");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        // The cap: the thousand idle clients and the user below; one more is refused.
        Process server = new ProcessBuilder(java, "-Xmx1g", "-Duser.home=" + tmp.resolve("home"), "-jar", JAR.toString(),
                "server", "--data", data.toString(), "--port", "0", "--registry-port", "0", "--http-port", "0",
                "--outbound-port", "-1", "--max-clients", Integer.toString(CLIENTS + 1))
                .redirectErrorStream(true).redirectOutput(log.toFile()).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .start();
        Path known = tmp.resolve("known_hosts");
        try (IdleClients idle = new IdleClients()) {
            int port = awaitReady(server, log);
            SocketFactory tls = Tls.trustOnFirstUse("localhost", port, known, n -> { });
            try (ClientSocketHandler user = ClientSocketHandler.connect("localhost", port, tls, Duration.ofSeconds(30))) {
                user.login("idle", "idle-password".toCharArray());
                assertThat(user.call("", "?services", Priority.NORMAL, Duration.ofSeconds(30), null).status()).isEqualTo(Status.OK);
                long before = threads(server.pid());

                idle.open(CLIENTS, 8, tls, "localhost", port, "idle", "idle-password".toCharArray());
                assertThat(idle.size()).isEqualTo(CLIENTS);
                long after = threads(server.pid());
                assertThat(after - before).as("server threads %d with 1 client, %d with %d more", before, after, CLIENTS)
                        .isLessThanOrEqualTo(MORE_THREADS_AT_MOST);

                assertThat(user.call("", "?services", Priority.NORMAL, Duration.ofSeconds(30), null).status())
                        .as("a logged-in user is answered with %d idle clients connected", CLIENTS).isEqualTo(Status.OK);
                assertThatThrownBy(() -> new IdleClients().open(1, 1, tls, "localhost", port, "idle", "idle-password".toCharArray()))
                        .hasStackTraceContaining("the server has " + (CLIENTS + 1) + " clients logged in, the most it takes");
            }
        } finally {
            server.destroy();
            if (!server.waitFor(30, TimeUnit.SECONDS)) {
                server.destroyForcibly().waitFor(30, TimeUnit.SECONDS);
            }
        }
    }

    private static int awaitReady(Process p, Path log) throws Exception {
        Pattern ready = Pattern.compile("RIPVServer ready: clients on port (\\d+)");
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (true) {
            String text = Files.readString(log, StandardCharsets.UTF_8);
            Matcher m = ready.matcher(text);
            if (m.find()) {
                return Integer.parseInt(m.group(1));
            }
            assertThat(p.isAlive()).as("the server ended: " + text).isTrue();
            assertThat(System.nanoTime()).as("the server is ready").isLessThan(end);
            p.waitFor(100, TimeUnit.MILLISECONDS);
        }
    }

    private static long threads(long pid) throws Exception {
        return ConnectionCostBench.sample(pid)[0];
    }
}
