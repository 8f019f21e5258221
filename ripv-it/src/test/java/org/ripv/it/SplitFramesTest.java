package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.wire.FrameCodec;

/**
 * The client port reads bytes as they come, not a frame per read (issue 26: selector threads and
 * SSLEngine): a frame split into one-byte TLS records is put back together, and requests sent in
 * one write behind a {@code ?login} are read only once the log-in is answered, in order.
 */
class SplitFramesTest {
    private static final FrameCodec CODEC = new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME);

    @TempDir
    Path dir;
    TestSystem sys;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators");
    }

    @AfterEach
    void stop() {
        sys.close();
    }

    private static IncomingServerMessage login(long id) {
        return new IncomingServerMessage(new Header(id, new IdBadge("000000", "alice"), List.of(), "", "", "?login alice",
                Priority.URGENT, new Attachment("password", TestSystem.PASSWORD.getBytes(StandardCharsets.UTF_8))));
    }

    private static byte[] frames(IncomingServerMessage... messages) throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        for (IncomingServerMessage m : messages) {
            CODEC.write(out, m);
        }
        return bytes.toByteArray();
    }

    /** The final replies' ids and statuses, in the order they came. */
    private static List<String> finals(DataInputStream in, int n) throws Exception {
        List<String> got = new ArrayList<>();
        while (got.size() < n) {
            Message m = CODEC.read(in);
            if (m.footer().status().isFinal()) {
                got.add(m.header().messageId() + " " + m.footer().status());
            }
        }
        return got;
    }

    @Test
    void aFrameInOneByteRecordsIsReadWhole() throws Exception {
        try (Socket s = sys.rawSocket()) {
            s.setSoTimeout(20_000);
            s.setTcpNoDelay(true);
            OutputStream raw = s.getOutputStream(); // unbuffered: over TLS each write is a record of its own
            DataInputStream in = new DataInputStream(s.getInputStream());
            ByteArrayOutputStream greeting = new ByteArrayOutputStream();
            FrameCodec.writeGreeting(new DataOutputStream(greeting));
            byte[] all = concat(greeting.toByteArray(), frames(login(1),
                    new IncomingServerMessage(Header.request(2, "", "?services", Priority.NORMAL))));
            for (byte b : all) {
                raw.write(b);
                raw.flush();
            }
            FrameCodec.readGreeting(in);
            assertThat(finals(in, 2)).containsExactly("1 " + Status.OK, "2 " + Status.OK);
        }
    }

    @Test
    void requestsSentBehindALoginInOneWriteAreAnsweredAfterItInOrder() throws Exception {
        try (Socket s = sys.rawSocket()) {
            s.setSoTimeout(20_000);
            DataOutputStream out = new DataOutputStream(s.getOutputStream());
            DataInputStream in = new DataInputStream(s.getInputStream());
            FrameCodec.writeGreeting(out);
            FrameCodec.readGreeting(in);
            // One write: the log-in and what needs it. Read before the log-in was answered, they
            // would be refused NOT_LOGGED_IN.
            out.write(frames(login(1), new IncomingServerMessage(Header.request(2, "", "?services", Priority.NORMAL)),
                    new IncomingServerMessage(Header.request(3, "", "?services", Priority.NORMAL))));
            out.flush();
            assertThat(finals(in, 3)).containsExactly("1 " + Status.OK, "2 " + Status.OK, "3 " + Status.OK);
        }
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] all = new byte[a.length + b.length];
        System.arraycopy(a, 0, all, 0, a.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }
}
