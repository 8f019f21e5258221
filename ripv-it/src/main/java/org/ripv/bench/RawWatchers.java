package org.ripv.bench;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.Channels;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
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
 * Many watchers for the console benchmark on a few selector threads. Each speaks the real
 * protocol to log in and {@code ?watch} (blocking, one at a time), then its pushes are read as raw
 * frames and each line's send time is taken from the frame's bytes instead of deserializing it: a
 * thousand full clients, each with its own reader thread deserializing in the benchmark's own
 * JVM on two cores, would measure the clients rather than the server.
 *
 * <p>There is one selector thread per core, each with its share of the connections. Real watchers
 * read on their own machines, side by side; with one thread here, the server's writers finished a
 * line while the one reader still had a third of the crowd to read, on one core, the other idle
 * (docs/performance.md).
 */
final class RawWatchers implements AutoCloseable {
    private static final byte[] MARK = "bench ".getBytes(StandardCharsets.US_ASCII);
    private final List<Loop> loops = new ArrayList<>();
    /** The size on the wire (length prefix included) of the last frame read: a console push's, for {@link FanOutFloor}. */
    private volatile int lastFrameBytes;
    private int next;

    /**
     * One connection: where its delays go, and the start of a frame that a read cut off (rare:
     * pushes are a few hundred bytes), kept until the rest arrives.
     */
    private static final class Conn {
        final SocketChannel ch;
        final LongConsumer delays;
        byte[] partial;

        Conn(SocketChannel ch, LongConsumer delays) {
            this.ch = ch;
            this.delays = delays;
        }
    }

    /** One selector thread and the buffer its connections are read into, in turn. */
    private final class Loop implements Runnable {
        final Selector selector;
        final Thread thread;
        volatile boolean closed;
        /**
         * One buffer for all this loop's connections: a buffer per connection (64 KiB each, 63 MB
         * for 990) cost a copy from a temporary direct buffer and a cache miss per read, and swelled
         * the heap the benchmark reports.
         */
        ByteBuffer scratch = ByteBuffer.allocateDirect(64 * 1024);
        /** A frame's bytes for the scan: a loop over an array beats {@code ByteBuffer.get(i)} per byte. */
        byte[] frame = new byte[4096];

        Loop(int i) throws IOException {
            selector = Selector.open();
            thread = new Thread(this, "bench-raw-watchers-" + i);
            thread.setDaemon(true);
            thread.start();
        }

        void register(Conn c) throws IOException {
            synchronized (this) {
                selector.wakeup();
                c.ch.register(selector, SelectionKey.OP_READ, c);
            }
        }

        @Override
        public void run() {
            while (!closed) {
                try {
                    selector.select();
                    synchronized (this) {
                        // lets register() run between selects
                    }
                    for (SelectionKey k : selector.selectedKeys()) {
                        if (!k.isValid() || !read((Conn) k.attachment())) {
                            k.cancel();
                        }
                    }
                    selector.selectedKeys().clear();
                } catch (IOException | java.nio.channels.ClosedSelectorException e) {
                    if (!closed) {
                        continue;
                    }
                }
            }
        }

        /** Reads what the connection has and takes the delays out of its whole frames; false at its end. */
        private boolean read(Conn c) throws IOException {
            ByteBuffer b = scratch;
            b.clear();
            if (c.partial != null) {
                b.put(c.partial);
                c.partial = null;
            }
            if (c.ch.read(b) < 0) {
                return false;
            }
            // The time of this read, not of the select: a read late in a long batch also takes
            // lines that arrived after the select returned (once timed before they were sent).
            long now = System.nanoTime();
            b.flip();
            while (b.remaining() >= 4) {
                int len = b.getInt(b.position());
                if (len < 0 || b.remaining() < 4 + len) {
                    break;
                }
                if (frame.length < len) {
                    frame = new byte[len];
                }
                b.position(b.position() + 4);
                b.get(frame, 0, len);
                lastFrameBytes = 4 + len;
                scan(frame, len, now, c.delays);
            }
            if (b.hasRemaining()) {
                c.partial = new byte[b.remaining()];
                b.get(c.partial);
                int len = c.partial.length >= 4 ? ByteBuffer.wrap(c.partial).getInt() : 0;
                if (4 + len > scratch.capacity()) {
                    scratch = ByteBuffer.allocateDirect(4 + len); // a frame larger than the buffer: grow it once
                }
            }
            return true;
        }

        void close() throws IOException {
            closed = true;
            for (SelectionKey k : selector.keys()) {
                k.channel().close();
            }
            selector.close();
        }
    }

    RawWatchers(int threads) throws IOException {
        for (int i = 0; i < Math.max(1, threads); i++) {
            loops.add(new Loop(i));
        }
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
        ch.configureBlocking(false);
        loops.get(next++ % loops.size()).register(new Conn(ch, delays));
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

    /** Finds every "bench I NANOS" in the frame's first {@code to} bytes and reports now - NANOS. */
    static void scan(byte[] f, int to, long now, LongConsumer delay) {
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
            }
            i = j;
        }
    }

    @Override
    public void close() throws IOException {
        for (Loop l : loops) {
            l.close();
        }
    }
}
