package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.Socket;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.naming.Handles;
import org.ripv.outbound.OutboundHandshake;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;

/**
 * Outbound-only mode over loopback: the service listens nowhere, connects out to the server's
 * outbound port, proves the secret by HMAC, and everything a service does works over that one
 * connection; a wrong secret, a stranger and garbage are turned away without harm.
 */
class OutboundOnlyTest {
    private static final String NAT = "<ClockService>::<natted>";

    @TempDir
    Path dir;

    private static ServiceOptions outbound(TestSystem sys, int port, String secret) throws Exception {
        ServiceOptions o = sys.serviceOptions();
        return new ServiceOptions(o.serverHost(), o.registryPort(), secret, 0, o.heartbeat()).outboundOnly(port);
    }

    @Test
    void aServiceThatOnlyConnectsOutWorksLikeAnyOther() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("server"))) {
            sys.user("alice", "operators");
            int port = sys.server().openOutbound(0);
            ClockService clock = new ClockService("natted");
            ServiceConnector c = ServiceConnector.connect(clock, outbound(sys, port, sys.secret()));
            try {
                assertThat(c.awaitRegistered(Duration.ofSeconds(20))).isTrue();
                ClientSocketHandler client = sys.login("alice");
                String box = NAT + Handles.platformDefault();
                assertThat(client.call(box, "echo over the service's own line", Priority.NORMAL, Duration.ofSeconds(10), null)
                        .footer().replyText()).isEqualTo("over the service's own line");
                assertThat(client.call("", "?mailboxes", Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText())
                        .contains(box + ": available");
                assertThat(client.call("", "?status " + box, Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText())
                        .contains("available");
                assertThat(client.call("", "?services", Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText())
                        .contains(NAT).doesNotContain("NOT ANSWERING");
                // Many at once: batching and PROGRESS replies over the channel keep their order.
                var futures = new java.util.ArrayList<java.util.concurrent.CompletableFuture<OutgoingServerMessage>>();
                for (int i = 0; i < 200; i++) {
                    futures.add(client.send(box, "echo " + i, Priority.NORMAL, null));
                }
                for (int i = 0; i < 200; i++) {
                    assertThat(futures.get(i).get(20, TimeUnit.SECONDS).footer().replyText()).isEqualTo(Integer.toString(i));
                }
                // Closing the connection drops the service at once; its in-flight request ends.
                var sleeping = client.send(box, "sleep 5000", Priority.NORMAL, null);
                Thread.sleep(300);
                c.close();
                OutgoingServerMessage gone = sleeping.get(10, TimeUnit.SECONDS);
                assertThat(gone.footer().errorCode()).isEqualTo(ErrorCode.SERVICE_GONE);
                assertThat(gone.footer().replyText()).contains("closed its outbound connection");
                assertThat(sys.server().serviceCount()).isZero();
            } finally {
                c.close();
                clock.stop();
            }
        }
    }

    @Test
    void aWrongSecretIsFinalAndTheSecretNeverCrossesTheWire() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("server"))) {
            int port = sys.server().openOutbound(0);
            ClockService clock = new ClockService("natted");
            ServiceConnector c = ServiceConnector.connect(clock, outbound(sys, port, "not-the-secret"));
            try {
                assertThat(c.awaitFailure()).contains("wrong service secret");
                assertThat(sys.server().serviceCount()).isZero();
            } finally {
                c.close();
                clock.stop();
            }
            // A stranger: the server's challenge, then silence or junk never gets past the handshake.
            try (Socket s = new Socket("127.0.0.1", port)) {
                s.setSoTimeout(15_000);
                DataOutputStream out = new DataOutputStream(s.getOutputStream());
                DataInputStream in = new DataInputStream(s.getInputStream());
                out.writeUTF(OutboundHandshake.HELLO);
                String challenge = in.readUTF();
                assertThat(challenge).hasSize(64);
                out.writeUTF(NAT);
                out.writeUTF("0".repeat(64));
                out.writeUTF(sys.secret()); // sending the secret itself is no proof
                assertThat(in.readUTF()).startsWith("ERR wrong service secret");
                assertThat(in.read()).isEqualTo(-1);
            }
            try (Socket s = new Socket("127.0.0.1", port)) {
                s.setSoTimeout(15_000);
                s.getOutputStream().write(new byte[] {0, 5, 'h', 'e', 'l', 'l', 'o', 1, 2, 3});
                assertThat(s.getInputStream().read()).isEqualTo(-1);
            }
            // The server serves on.
            sys.user("alice", "operators");
            assertThat(sys.login("alice").call("", "?ping", Priority.NORMAL, Duration.ofSeconds(5), null).footer().replyText())
                    .isEqualTo("pong");
        }
    }
}
