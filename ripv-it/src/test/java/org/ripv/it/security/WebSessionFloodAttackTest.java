package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.it.TestSystem;
import org.ripv.it.web.WebVisitor;
import org.ripv.messages.Status;
import org.ripv.server.ServerConfig;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Issue 33 items 2 and 3: one web log-in opened 1,010 WebSockets, each a logged-in client counted
 * against {@code --max-clients}, so nobody else could log in, web or TLS; and 1,001 log-ins by any
 * user pushed every other user's web session out of the 1,000-entry table. Now a session opens at
 * most 32 sockets and a user 64, and a user's log-ins past 16 end that user's own oldest session,
 * never another's.
 */
@ResourceLock(Shared.CPU)
class WebSessionFloodAttackTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    static Path dir;
    static TestSystem sys;
    static WebVisitor web;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("alice", "operators").user("mallory", "observers").user("bob", "operators");
        web = new WebVisitor(sys.server().httpPort(), true);
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    /** Opens sockets for the session until the server refuses one (or {@code most} are open); the open ones. */
    static List<WebVisitor.Socket> openUntilRefused(String cookie, int most) throws Exception {
        List<WebVisitor.Socket> open = new ArrayList<>();
        String csrf = web.csrf(cookie);
        for (int i = 0; i < most; i++) {
            WebVisitor.Socket s;
            try {
                s = web.socket(cookie, web.base);
            } catch (Exception refused) {
                assertThat(refused).rootCause().hasMessageContaining("429");
                break;
            }
            s.send(1, "", "?ping", csrf);
            String got = s.await("\"id\":1", T);
            if (got == null || got.startsWith("CLOSED")) {
                break;
            }
            open.add(s);
        }
        return open;
    }

    @Test
    void oneLogInCannotOpenEveryClientPlace() throws Exception {
        String cookie = web.login("mallory", TestSystem.PASSWORD);
        List<WebVisitor.Socket> first = openUntilRefused(cookie, 200);
        assertThat(first).as("sockets one log-in may open").hasSize(32);
        // More log-ins of the same user: 64 sockets over all of them, then refused.
        int more = 0;
        for (int i = 0; i < 3; i++) {
            more += openUntilRefused(web.login("mallory", TestSystem.PASSWORD), 200).size();
        }
        assertThat(first.size() + more).as("sockets one user may open").isEqualTo(64);
        // Everyone else still logs in: on the client port and on the web console.
        var bob = sys.login("bob");
        assertThat(bob.call("", "?whoami", org.ripv.messages.Priority.NORMAL, T, p -> { }).status()).isEqualTo(Status.OK);
        String alice = web.login("alice", TestSystem.PASSWORD);
        assertThat(openUntilRefused(alice, 1)).hasSize(1);
        bob.close();
    }

    @Test
    void aThousandLogInsOfOneUserEvictNoOtherUser() throws Exception {
        String alice = web.login("alice", TestSystem.PASSWORD);
        String firstOfMallory = web.login("mallory", TestSystem.PASSWORD);
        ExecutorService pool = Executors.newFixedThreadPool(8);
        try {
            List<Future<String>> logins = new ArrayList<>();
            for (int i = 0; i < 1_001; i++) {
                logins.add(pool.submit(() -> web.login("mallory", TestSystem.PASSWORD)));
            }
            for (Future<String> f : logins) {
                f.get();
            }
        } finally {
            pool.shutdownNow();
        }
        assertThat(web.get("/api/session", "Cookie", alice).statusCode()).as("alice's session survives").isEqualTo(200);
        assertThat(web.get("/api/session", "Cookie", firstOfMallory).statusCode())
                .as("mallory's own oldest session made room").isEqualTo(401);
        assertThat(web.get("/api/session", "Cookie", web.login("bob", TestSystem.PASSWORD)).statusCode()).isEqualTo(200);
    }
}
