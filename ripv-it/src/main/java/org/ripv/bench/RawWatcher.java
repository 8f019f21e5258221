package org.ripv.bench;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.function.LongConsumer;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.wire.FrameCodec;

/**
 * A watcher for the console benchmark that speaks the real protocol (greeting, {@code ?login},
 * {@code ?watch}) but reads pushes as raw frames, taking each line's send time from the frame's
 * bytes instead of deserializing it: a thousand full clients deserializing in the benchmark's own
 * JVM on two cores would measure the clients, not the server.
 */
final class RawWatcher implements AutoCloseable {
    private static final byte[] MARK = "bench ".getBytes(StandardCharsets.US_ASCII);
    private final Socket socket;
    private final Thread reader;

    RawWatcher(String host, int port, String user, char[] password, String mailbox, LongConsumer sentNanos) throws IOException {
        socket = new Socket(host, port);
        socket.setTcpNoDelay(true);
        FrameCodec codec = new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME);
        DataOutputStream out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
        DataInputStream in = new DataInputStream(new BufferedInputStream(socket.getInputStream(), 64 * 1024));
        FrameCodec.writeGreeting(out);
        FrameCodec.readGreeting(in);
        codec.write(out, new IncomingServerMessage(new Header(1, new IdBadge("000000", user), List.of(), "", "",
                "?login " + user, Priority.URGENT, new Attachment("password", new String(password).getBytes(StandardCharsets.UTF_8)))));
        expectOk(codec, in, 1);
        codec.write(out, new IncomingServerMessage(Header.request(2, "", "?watch " + mailbox, Priority.NORMAL)));
        expectOk(codec, in, 2);
        reader = new Thread(() -> {
            try {
                byte[] buf = new byte[1 << 16];
                while (true) {
                    int n = in.readInt();
                    if (n > buf.length) {
                        buf = new byte[n];
                    }
                    in.readFully(buf, 0, n);
                    long now = System.nanoTime();
                    scan(buf, n, now, sentNanos);
                }
            } catch (IOException e) {
                // closed
            }
        }, "bench-raw-watcher");
        reader.setDaemon(true);
        reader.start();
    }

    private static void expectOk(FrameCodec codec, DataInputStream in, long id) throws IOException {
        while (true) {
            Message m = codec.read(in);
            if (m.header().messageId() == id && m.footer().status().isFinal()) {
                if (m.footer().status() != Status.OK) {
                    throw new IOException(m.footer().replyText());
                }
                return;
            }
        }
    }

    /** Finds every "bench I NANOS" in the frame and reports now - NANOS. */
    private static void scan(byte[] b, int n, long now, LongConsumer delay) {
        outer:
        for (int i = 0; i + MARK.length < n; i++) {
            for (int k = 0; k < MARK.length; k++) {
                if (b[i + k] != MARK[k]) {
                    continue outer;
                }
            }
            int j = i + MARK.length;
            while (j < n && b[j] != ' ') {
                j++;
            }
            long sent = 0;
            int digits = 0;
            for (j++; j < n && b[j] >= '0' && b[j] <= '9' && digits < 19; j++, digits++) {
                sent = sent * 10 + (b[j] - '0');
            }
            if (digits > 0) {
                delay.accept(now - sent);
            }
            i = j;
        }
    }

    @Override
    public void close() throws IOException {
        socket.close();
    }
}
