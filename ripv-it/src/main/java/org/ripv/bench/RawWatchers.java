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
 * Many watchers for the console benchmark on one selector thread. Each speaks the real protocol
 * to log in and {@code ?watch} (blocking, one at a time), then its pushes are read as raw frames
 * and each line's send time is taken from the frame's bytes instead of deserializing it: a
 * thousand full clients, each with its own reader thread deserializing in the benchmark's own
 * JVM on two cores, would measure the clients rather than the server.
 */
final class RawWatchers implements AutoCloseable {
    private static final byte[] MARK = "bench ".getBytes(StandardCharsets.US_ASCII);
    private final Selector selector;
    private final Thread loop;
    private volatile boolean closed;

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

    /**
     * The one buffer every connection is read into, in turn, on the selector thread: a buffer per
     * connection (64 KiB each, 63 MB for 990) cost a copy from a temporary direct buffer and a
     * cache miss per read, and swelled the heap the benchmark reports.
     */
    private ByteBuffer scratch = ByteBuffer.allocateDirect(64 * 1024);

    RawWatchers() throws IOException {
        selector = Selector.open();
        loop = new Thread(this::run, "bench-raw-watchers");
        loop.setDaemon(true);
        loop.start();
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
        ch.configureBlocking(false);
        synchronized (this) {
            selector.wakeup();
            ch.register(selector, SelectionKey.OP_READ, new Conn(ch, delays));
        }
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

    private void run() {
        while (!closed) {
            try {
                selector.select();
                synchronized (this) {
                    // lets add() register between selects
                }
                long now = System.nanoTime();
                for (SelectionKey k : selector.selectedKeys()) {
                    if (!k.isValid() || !read((Conn) k.attachment(), now)) {
                        k.cancel();
                    }
                }
                selector.selectedKeys().clear();
            } catch (IOException e) {
                if (!closed) {
                    continue;
                }
            }
        }
    }

    /** Reads what the connection has and takes the delays out of its whole frames; false at its end. */
    private boolean read(Conn c, long now) throws IOException {
        ByteBuffer b = scratch;
        b.clear();
        if (c.partial != null) {
            b.put(c.partial);
            c.partial = null;
        }
        if (c.ch.read(b) < 0) {
            return false;
        }
        b.flip();
        while (b.remaining() >= 4) {
            int len = b.getInt(b.position());
            if (b.remaining() < 4 + len) {
                break;
            }
            scan(b, b.position() + 4, b.position() + 4 + len, now, c.delays);
            b.position(b.position() + 4 + len);
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

    /** Finds every "bench I NANOS" in the frame and reports now - NANOS. */
    private static void scan(ByteBuffer b, int from, int to, long now, LongConsumer delay) {
        outer:
        for (int i = from; i + MARK.length < to; i++) {
            for (int k = 0; k < MARK.length; k++) {
                if (b.get(i + k) != MARK[k]) {
                    continue outer;
                }
            }
            int j = i + MARK.length;
            while (j < to && b.get(j) != ' ') {
                j++;
            }
            long sent = 0;
            int digits = 0;
            for (j++; j < to && b.get(j) >= '0' && b.get(j) <= '9' && digits < 19; j++, digits++) {
                sent = sent * 10 + (b.get(j) - '0');
            }
            if (digits > 0) {
                delay.accept(now - sent);
            }
            i = j;
        }
    }

    @Override
    public void close() throws IOException {
        closed = true;
        for (SelectionKey k : selector.keys()) {
            k.channel().close();
        }
        selector.close();
    }
}
