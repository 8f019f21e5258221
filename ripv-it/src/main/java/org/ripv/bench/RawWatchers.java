package org.ripv.bench;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.Channels;
import java.nio.channels.SocketChannel;
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
 * Many watchers for the console benchmark on a few selector threads ({@link SelectorReaders}). Each speaks the real
 * protocol to log in and {@code ?watch} (blocking, one at a time), then its pushes are read as raw
 * frames and each line's send time is taken from the frame's bytes instead of deserializing it: a
 * thousand full clients, each with its own reader thread deserializing in the benchmark's own
 * JVM on two cores, would measure the clients rather than the server.
 */
final class RawWatchers extends SelectorReaders<SelectorReaders.Socket> {
    private static final byte[] MARK = "bench ".getBytes(StandardCharsets.US_ASCII);
    /** The size on the wire (length prefix included) of the last frame read: a console push's, for {@link FanOutFloor}. */
    private volatile int lastFrameBytes;
    /** A frame's bytes for the scan, per reading thread: a loop over an array beats {@code ByteBuffer.get(i)} per byte. */
    private final ThreadLocal<byte[]> frame = ThreadLocal.withInitial(() -> new byte[4096]);

    @Override
    protected boolean frames(Socket c, ByteBuffer b, long now) {
        byte[] f = frame.get();
        while (b.remaining() >= 4) {
            int len = b.getInt(b.position());
            if (len < 0 || b.remaining() < 4 + len) {
                break;
            }
            if (f.length < len) {
                f = new byte[len];
                frame.set(f);
            }
            b.position(b.position() + 4);
            b.get(f, 0, len);
            lastFrameBytes = 4 + len;
            scan(f, len, now, c.delays);
        }
        return true;
    }

    RawWatchers(int threads) throws IOException {
        super(threads, "bench-raw-watchers");
    }

    /** The size of the last frame read, length prefix included, or 0 before the first. */
    int lastFrameBytes() {
        return lastFrameBytes;
    }

    /** Connects, logs in and watches; the watcher's delays (nanoseconds) go to {@code delays}. */
    void add(String host, int port, String user, char[] password, String mailbox, LongConsumer delays) throws IOException {
        SocketChannel ch = SocketChannel.open(new InetSocketAddress(host, port));
        ch.socket().setTcpNoDelay(true);
        FrameCodec codec = new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME);
        // Unbuffered on purpose: nothing past the ?watch reply may be read here.
        DataInputStream in = new DataInputStream(Channels.newInputStream(ch));
        DataOutputStream out = new DataOutputStream(Channels.newOutputStream(ch));
        FrameCodec.writeGreeting(out);
        FrameCodec.readGreeting(in);
        codec.write(out, new IncomingServerMessage(new Header(1, new IdBadge("000000", user), List.of(), "", "",
                "?login " + user, Priority.URGENT, new Attachment("password", new String(password).getBytes(StandardCharsets.UTF_8)))));
        expectOk(codec, in, 1);
        codec.write(out, new IncomingServerMessage(Header.request(2, "", "?watch " + mailbox, Priority.NORMAL)));
        expectOk(codec, in, 2);
        watch(ch, delays);
    }

    /** Reads an already connected channel's frames from now on; its delays (nanoseconds) go to {@code delays}. */
    void watch(SocketChannel ch, LongConsumer delays) throws IOException {
        register(new Socket(ch, delays));
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

    /** Finds every "bench I NANOS" in the frame's first {@code to} bytes, reports now - NANOS for each, and returns how many. */
    static int scan(byte[] f, int to, long now, LongConsumer delay) {
        int found = 0;
        outer:
        for (int i = 0; i + MARK.length < to; i++) {
            if (f[i] != 'b') {
                continue;
            }
            for (int k = 1; k < MARK.length; k++) {
                if (f[i + k] != MARK[k]) {
                    continue outer;
                }
            }
            int j = i + MARK.length;
            while (j < to && f[j] != ' ') {
                j++;
            }
            long sent = 0;
            int digits = 0;
            for (j++; j < to && f[j] >= '0' && f[j] <= '9' && digits < 19; j++, digits++) {
                sent = sent * 10 + (f[j] - '0');
            }
            if (digits > 0) {
                delay.accept(now - sent);
                found++;
            }
            i = j;
        }
        return found;
    }
}
