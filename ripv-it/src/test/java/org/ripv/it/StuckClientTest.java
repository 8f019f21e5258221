package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.wire.FrameCodec;

/**
 * The server's few writer threads are shared by all clients (docs/concurrency.md): clients that
 * ask for megabytes and never read them fill their sockets, and a writer blocked on one is taken
 * out of the pool and replaced, so more such clients than there are writers still leave everyone
 * else answered at once — over TLS, the default.
 */
class StuckClientTest {
    static final Duration T = Duration.ofSeconds(20);
    static final int STUCK = 4; // more than the pool's writers (at least 2; the cores here)

    @TempDir
    Path dir;

    @Test
    void clientsThatNeverReadTheirMegabytesHoldUpNobodyElse() throws Exception {
        try (TestSystem sys = TestSystem.start(dir)) {
            sys.user("alice", "operators").user("mallory", "operators");
            Path folder = Files.createDirectories(sys.downloadDir().resolve("ru29"));
            byte[] mib = new byte[1 << 20];
            new Random(1).nextBytes(mib); // incompressible, in case anything on the way compresses
            Files.write(folder.resolve("big.bin"), mib);
            ClientSocketHandler alice = sys.login("alice");
            assertThat(alice.call("", "?whoami", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);

            List<Socket> stuck = new ArrayList<>();
            for (int i = 0; i < STUCK; i++) {
                Socket s = sys.rawSocket();
                s.setReceiveBufferSize(64 * 1024);
                s.setSoTimeout((int) T.toMillis()); // its own log-in reply must come: the writers are not all caught
                stuck.add(s);
                FrameCodec codec = new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME);
                DataOutputStream out = new DataOutputStream(s.getOutputStream());
                DataInputStream in = new DataInputStream(s.getInputStream());
                FrameCodec.writeGreeting(out);
                FrameCodec.readGreeting(in);
                codec.write(out, new IncomingServerMessage(new Header(1, new IdBadge("000000", "mallory"), List.of(), "", "",
                        "?login mallory", Priority.URGENT, new Attachment("password",
                        TestSystem.PASSWORD.getBytes(StandardCharsets.UTF_8)))));
                Message ok = codec.read(in);
                assertThat(ok.footer().status()).isEqualTo(Status.OK);
                // 12 MiB of replies that this client will never read.
                for (int k = 0; k < 12; k++) {
                    codec.write(out, new IncomingServerMessage(Header.request(2 + k, "", "?download ru29/big.bin 0 1048576",
                            Priority.NORMAL)));
                }
            }
            Thread.sleep(1_000); // the writers fill those sockets and block in them

            for (int i = 0; i < 20; i++) {
                long start = System.nanoTime();
                OutgoingServerMessage r = alice.call("", "?whoami", Priority.NORMAL, T, null);
                long ms = (System.nanoTime() - start) / 1_000_000;
                assertThat(r.status()).isEqualTo(Status.OK);
                assertThat(ms).as("a reply to a client that reads, while " + STUCK + " never read").isLessThan(10_000);
            }
            ClientSocketHandler late = sys.login("alice"); // a new client is served too
            assertThat(late.call("", "?whoami", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
            for (Socket s : stuck) {
                s.close();
            }
            assertThat(alice.call("", "?whoami", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
        }
    }
}
