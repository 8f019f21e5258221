package org.ripv.bench;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.ByteBuffer;
import java.nio.channels.Channels;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.concurrent.ThreadLocalRandom;
import java.util.function.LongConsumer;

/**
 * Many web console WebSockets for {@code ./ripv bench web}, on a few selector threads
 * ({@link SelectorReaders}): each one
 * does what a page does — the HTTP upgrade with the session cookie and the page's Origin, then
 * {@code ?watch} as a JSON request with the CSRF token (blocking, one at a time) — and from then on
 * its frames are read raw and each line's send time is taken from the bytes ({@link RawWatchers#scan}),
 * so that ten thousand JSON parsers in the benchmark's own JVM do not measure the clients instead of
 * the server. Server frames are unmasked (RFC 6455 5.1); text, continuation and close are all a page sees here.
 */
final class WebWatchers extends SelectorReaders<WebWatchers.Conn> {
    private static final byte[] SKIPPED = "lines skipped".getBytes(StandardCharsets.US_ASCII);

    /** What a page needs to open its socket: where, its cookie, its Origin and its CSRF token. */
    record Page(String host, int port, String cookie, String origin, String csrf) {}

    /** One socket, and how many frames and skip markers it saw. */
    static final class Conn extends SelectorReaders.Socket {
        volatile long markers;
        volatile long frames;

        Conn(SocketChannel ch, LongConsumer delays) {
            super(ch, delays);
        }
    }

    private volatile int lastPayloadBytes;
    /** The smallest frame that carried a bench line: one line's push (a page behind gets several lines in one). */
    private volatile int smallestPush = Integer.MAX_VALUE;
    /** A frame's payload for the scan, per reading thread. */
    private final ThreadLocal<byte[]> payload = ThreadLocal.withInitial(() -> new byte[4096]);

    WebWatchers(int threads) throws IOException {
        super(threads, "bench-web-watchers");
    }

    @Override
    protected boolean frames(Conn c, ByteBuffer b, long now) throws IOException {
        byte[] p = payload.get();
        while (b.remaining() >= 2) {
            int at = b.position();
            int op = b.get(at) & 0x0f;
            int len7 = b.get(at + 1) & 0x7f;
            int head = len7 == 126 ? 4 : len7 == 127 ? 10 : 2;
            if (b.remaining() < head) {
                break;
            }
            long len = len7 == 126 ? b.getShort(at + 2) & 0xffff : len7 == 127 ? b.getLong(at + 2) : len7;
            if (len > 16 << 20) {
                throw new IOException("a WebSocket frame of " + len + " bytes");
            }
            if (b.remaining() < head + len) {
                break;
            }
            if (op == 8) {
                return false;
            }
            int n = (int) len;
            if (p.length < n) {
                p = new byte[n];
                payload.set(p);
            }
            b.position(at + head);
            b.get(p, 0, n);
            lastPayloadBytes = head + n;
            if (RawWatchers.scan(p, n, now, c.delays) == 1 && head + n < smallestPush) {
                smallestPush = head + n;
            }
            c.frames++;
            if (contains(p, n, SKIPPED)) {
                c.markers++;
            }
        }
        return true;
    }

    /** The size on the wire of the smallest frame that carried one bench line, or 0 before the first. */
    int smallestPushBytes() {
        int s = smallestPush;
        return s == Integer.MAX_VALUE ? 0 : s;
    }

    /** The size on the wire of the last frame read (a console push's), or 0 before the first. */
    int lastFrameBytes() {
        return lastPayloadBytes;
    }

    /** Opens a page's socket and watches the MailBox; its delays (nanoseconds) go to {@code delays}. */
    Conn add(Page page, String mailbox, LongConsumer delays) throws IOException {
        return register(new Conn(open(page, mailbox, false), delays));
    }

    /**
     * Opens a page's socket and watches the MailBox, but reads nothing more: a page that stopped
     * reading. Its receive buffer is fixed small (a phone's, not the loopback's tens of megabytes
     * the kernel would grow it to), so what the server holds for it shows.
     */
    static SocketChannel stalled(Page page, String mailbox) throws IOException {
        return open(page, mailbox, true);
    }

    /** A stalled page starts reading again: what it gets from now on is scanned (skip markers counted). */
    Conn resume(SocketChannel ch, LongConsumer delays) throws IOException {
        return registerFirst(new Conn(ch, delays));
    }

    private static SocketChannel open(Page page, String mailbox, boolean smallBuffer) throws IOException {
        SocketChannel ch = SocketChannel.open();
        try {
            if (smallBuffer) {
                ch.setOption(StandardSocketOptions.SO_RCVBUF, 16 * 1024);
            }
            ch.connect(new InetSocketAddress(page.host(), page.port()));
            ch.socket().setTcpNoDelay(true);
            // Unbuffered on purpose: nothing past the ?watch reply may be read here.
            InputStream in = Channels.newInputStream(ch);
            byte[] key = new byte[16];
            ThreadLocalRandom.current().nextBytes(key);
            String upgrade = "GET /ws HTTP/1.1\r\nHost: " + page.host() + ":" + page.port() + "\r\nUpgrade: websocket\r\n"
                    + "Connection: Upgrade\r\nSec-WebSocket-Version: 13\r\nSec-WebSocket-Key: " + Base64.getEncoder().encodeToString(key)
                    + "\r\nOrigin: " + page.origin() + "\r\nCookie: " + page.cookie() + "\r\n\r\n";
            write(ch, upgrade.getBytes(StandardCharsets.US_ASCII));
            String response = head(in);
            if (!response.startsWith("HTTP/1.1 101")) {
                throw new IOException("the web console refused the WebSocket: " + response.lines().findFirst().orElse(response));
            }
            write(ch, masked(("{\"id\":1,\"mailbox\":\"\",\"body\":\"?watch " + mailbox + "\",\"csrf\":\"" + page.csrf() + "\"}")
                    .getBytes(StandardCharsets.UTF_8)));
            DataInputStream d = new DataInputStream(in);
            while (true) {
                String text = frame(d);
                if (text == null) {
                    throw new IOException("the web console closed the WebSocket before the ?watch reply");
                }
                if (text.contains("\"type\":\"reply\"") && text.contains("\"id\":1,")) {
                    if (!text.contains("\"status\":\"OK\"")) {
                        throw new IOException("?watch " + mailbox + " refused: " + text);
                    }
                    return ch;
                }
            }
        } catch (IOException | RuntimeException e) {
            ch.close();
            throw e;
        }
    }

    private static void write(SocketChannel ch, byte[] bytes) throws IOException {
        ByteBuffer b = ByteBuffer.wrap(bytes);
        while (b.hasRemaining()) {
            ch.write(b);
        }
    }

    /** The response head, read a byte at a time up to its blank line (SharedPushFrameTest reads its pages' too). */
    static String head(InputStream in) throws IOException {
        ByteArrayOutputStream h = new ByteArrayOutputStream();
        int state = 0;
        while (state < 4) {
            int c = in.read();
            if (c < 0) {
                throw new IOException("the web console closed the connection during the upgrade: " + h);
            }
            h.write(c);
            state = (c == '\r' && (state == 0 || state == 2)) || (c == '\n' && (state == 1 || state == 3)) ? state + 1 : 0;
        }
        return h.toString(StandardCharsets.US_ASCII);
    }

    /** One whole message from the server as text (fragments joined), or null at a close frame. */
    private static String frame(DataInputStream in) throws IOException {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        while (true) {
            int b0 = in.readUnsignedByte();
            int len7 = in.readUnsignedByte() & 0x7f;
            long len = len7 == 126 ? in.readUnsignedShort() : len7 == 127 ? in.readLong() : len7;
            byte[] p = new byte[(int) len];
            in.readFully(p);
            if ((b0 & 0x0f) == 8) {
                return null;
            }
            text.write(p);
            if ((b0 & 0x80) != 0) {
                return text.toString(StandardCharsets.UTF_8);
            }
        }
    }

    /** A client's text frame, masked as RFC 6455 requires of clients. */
    static byte[] masked(byte[] payload) {
        ByteArrayOutputStream f = new ByteArrayOutputStream(payload.length + 14);
        f.write(0x81);
        if (payload.length < 126) {
            f.write(0x80 | payload.length);
        } else {
            f.write(0x80 | 126);
            f.write(payload.length >> 8);
            f.write(payload.length & 0xff);
        }
        byte[] mask = new byte[4];
        ThreadLocalRandom.current().nextBytes(mask);
        f.writeBytes(mask);
        for (int i = 0; i < payload.length; i++) {
            f.write(payload[i] ^ mask[i & 3]);
        }
        return f.toByteArray();
    }

    private static boolean contains(byte[] f, int to, byte[] what) {
        outer:
        for (int i = 0; i + what.length <= to; i++) {
            for (int k = 0; k < what.length; k++) {
                if (f[i + k] != what[k]) {
                    continue outer;
                }
            }
            return true;
        }
        return false;
    }
}
