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

    /** One connection's frame reassembly and where its delays go. */
    private static final class Conn {
        final SocketChannel ch;
        final LongConsumer delays;
        ByteBuffer buf = ByteBuffer.allocate(64 * 1024);

        Conn(SocketChannel ch, LongConsumer delays) {
            this.ch = ch;
            this.delays = delays;
        }
    }

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
                    Conn c = (Conn) k.attachment();
                    if (!k.isValid() || c.ch.read(c.buf) < 0) {
                        k.cancel();
                        continue;
                    }
                    frames(c, now);
                }
                selector.selectedKeys().clear();
            } catch (IOException e) {
                if (!closed) {
                    continue;
                }
            }
        }
    }

    private static void frames(Conn c, long now) {
        ByteBuffer b = c.buf;
        b.flip();
        while (b.remaining() >= 4) {
            int len = b.getInt(b.position());
            if (b.remaining() < 4 + len) {
                if (4 + len > b.capacity()) {
                    ByteBuffer bigger = ByteBuffer.allocate(4 + len);
                    bigger.put(b);
                    c.buf = bigger;
                    return;
                }
                break;
            }
            scan(b.array(), b.position() + 4, b.position() + 4 + len, now, c.delays);
            b.position(b.position() + 4 + len);
        }
        b.compact();
    }

    /** Finds every "bench I NANOS" in the frame and reports now - NANOS. */
    private static void scan(byte[] b, int from, int to, long now, LongConsumer delay) {
        outer:
        for (int i = from; i + MARK.length < to; i++) {
            for (int k = 0; k < MARK.length; k++) {
                if (b[i + k] != MARK[k]) {
                    continue outer;
                }
            }
            int j = i + MARK.length;
            while (j < to && b[j] != ' ') {
                j++;
            }
            long sent = 0;
            int digits = 0;
            for (j++; j < to && b[j] >= '0' && b[j] <= '9' && digits < 19; j++, digits++) {
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
        closed = true;
        for (SelectionKey k : selector.keys()) {
            k.channel().close();
        }
        selector.close();
    }
}
