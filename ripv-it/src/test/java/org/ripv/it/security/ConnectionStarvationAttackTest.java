package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.server.ServerConfig;
import org.ripv.wire.FrameCodec;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Issue 10, item 3: connections that never log in cannot lock anybody out. Before the fix, 1,000
 * connections that sent only the greeting filled the 1,000-client cap for as long as they stayed.
 */
@ResourceLock(Shared.CPU)
class ConnectionStarvationAttackTest {
    @TempDir
    Path dir;
    TestSystem sys;
    final List<Socket> attack = new ArrayList<>();

    @AfterEach
    void stop() {
        attack.forEach(s -> {
            try {
                s.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        });
        if (sys != null) {
            sys.close();
        }
    }

    /** A connection from a chosen loopback source address (Linux routes all of 127/8 to lo). */
    private Socket from(String source) throws IOException {
        Socket s = new Socket();
        s.bind(new InetSocketAddress(source, 0));
        s.connect(new InetSocketAddress("127.0.0.1", sys.server().port()), 5_000);
        attack.add(s);
        return s;
    }

    @Test
    void greetingOnlyAndSilentConnectionsDoNotKeepAUserOut() throws Exception {
        // Plain TCP: the attacker's best case (no TLS handshake to pay); the greeting reaches the server.
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).plain();
        config = config.withSecurity(config.security().withLoginDeadline(Duration.ofSeconds(8)));
        sys = TestSystem.start(config);
        sys.user("alice", "operators");

        // 1,000 greeting-only connections from 100 addresses (10 each, under the per-address limit)...
        for (int i = 0; i < 1000; i++) {
            Socket s = from("127.0.1." + (1 + i % 100));
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            FrameCodec.writeGreeting(out);
        }
        for (int i = 0; i < 1000; i += 97) {
            FrameCodec.readGreeting(new DataInputStream(attack.get(i).getInputStream()));
        }
        // ...and silent ones from one address, of which only the first 16 are kept.
        List<Socket> silent = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            silent.add(from("127.0.2.1"));
        }
        int refused = 0;
        for (Socket s : silent) {
            s.setSoTimeout(250);
            if (closedByServer(s.getInputStream())) {
                refused++;
            }
        }
        assertThat(refused).as("connections over the per-address limit are closed at once").isEqualTo(40 - 16);

        long t0 = System.nanoTime();
        ClientSocketHandler alice = ClientSocketHandler.connectPlain("127.0.0.1", sys.server().port());
        alice.login("alice", TestSystem.PASSWORD.toCharArray());
        long millis = (System.nanoTime() - t0) / 1_000_000;
        assertThat(millis).as("a user logs in while 1,000+ connections hold on without logging in"
                + " (starved, it would wait for the 8 s log-in deadline to free a slot)").isLessThan(6_000);
        alice.close();

        // The log-in deadline (8 s here) closes every connection that did not log in.
        for (int i = 0; i < attack.size(); i += 53) {
            Socket s = attack.get(i);
            s.setSoTimeout(15_000);
            assertThat(closedByServer(s.getInputStream())).as("connection %d closed at the deadline", i).isTrue();
        }
    }

    @Test
    void theClientCapCountsLoggedInClientsOnly() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withMaxClients(2);
        sys = TestSystem.start(config);
        sys.user("alice", "operators");
        for (int i = 0; i < 10; i++) {
            from("127.0.3." + (1 + i)); // silent: they take no place under the cap
        }
        sys.login("alice");
        sys.login("alice");
        ClientSocketHandler third = sys.connect();
        try {
            third.login("alice", TestSystem.PASSWORD.toCharArray());
            throw new AssertionError("a third log-in passed a cap of 2");
        } catch (RipvErrorException e) {
            assertThat(e.code()).isEqualTo(ErrorCode.NOT_AVAILABLE);
            assertThat(e.getMessage()).contains("2 clients logged in");
        }
    }

    /** True when the server closed the connection (end of stream or reset) before the timeout. */
    private static boolean closedByServer(InputStream in) {
        try {
            while (true) {
                if (in.read() < 0) {
                    return true;
                }
            }
        } catch (java.net.SocketTimeoutException e) {
            return false;
        } catch (IOException e) {
            return true;
        }
    }
}
