package org.ripv.bench;

import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.ByteBuffer;
import java.nio.channels.SelectionKey;
import java.nio.channels.Selector;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The floor under {@code bench web}'s CPU figure (issue 38): a process that does nothing but what the
 * server's fan-out cannot avoid — plain WebSocket text frames of a console push's size, one per
 * line to each of the same number of sockets, written non-blocking from a selector as Jetty does,
 * a socket that cannot take a frame keeping the rest for when it can. The bench reads its sockets
 * with the same readers as the web console's ({@link WebWatchers}: the page's upgrade and
 * {@code ?watch}, answered here without any checking) and takes this process's CPU from
 * {@code /proc}, so server CPU per delivery over this process's is RIPV's cost over the floor's.
 *
 * <p>Run by the bench as {@code java -cp ... org.ripv.bench.WebSocketFloor FRAME_BYTES WRITERS}: it
 * prints {@code port N}, then sends each line its standard input brings ({@code bench I NANOS})
 * to every socket, padded to FRAME_BYTES on the wire; it ends at the end of its input.
 */
public final class WebSocketFloor {
    private static final Pattern KEY = Pattern.compile("(?im)^Sec-WebSocket-Key:\\s*(\\S+)");

    /** One writer thread: a selector over its share of the sockets, and the frames they still owe. */
    private static final class Writer implements Runnable {
        final Selector selector;
        final ConcurrentLinkedQueue<Object> inbox = new ConcurrentLinkedQueue<>();
        final List<SocketChannel> sockets = new ArrayList<>();
        long delivered;

        Writer() throws IOException {
            selector = Selector.open();
        }

        @Override
        public void run() {
            try {
                while (true) {
                    selector.select(50);
                    for (SelectionKey k : selector.selectedKeys()) {
                        if (k.isValid() && k.isWritable()) {
                            flush(k);
                        }
                    }
                    selector.selectedKeys().clear();
                    for (Object o; (o = inbox.poll()) != null; ) {
                        if (o instanceof SocketChannel ch) {
                            ch.configureBlocking(false);
                            sockets.add(ch);
                            ch.register(selector, 0, new ArrayDeque<ByteBuffer>());
                        } else if (o instanceof byte[] frame) {
                            send(frame);
                        } else {
                            return;
                        }
                    }
                }
            } catch (IOException e) {
                System.err.println("floor writer: " + e);
            }
        }

        @SuppressWarnings("unchecked")
        private void send(byte[] frame) throws IOException {
            for (SocketChannel ch : sockets) {
                SelectionKey k = ch.keyFor(selector);
                if (k == null || !k.isValid()) {
                    continue;
                }
                ArrayDeque<ByteBuffer> owed = (ArrayDeque<ByteBuffer>) k.attachment();
                ByteBuffer b = ByteBuffer.wrap(frame);
                if (owed.isEmpty()) {
                    try {
                        ch.write(b);
                    } catch (IOException gone) {
                        k.cancel();
                        continue;
                    }
                }
                if (b.hasRemaining()) {
                    owed.add(b);
                    k.interestOps(SelectionKey.OP_WRITE);
                }
                delivered++;
            }
        }

        @SuppressWarnings("unchecked")
        private static void flush(SelectionKey k) {
            ArrayDeque<ByteBuffer> owed = (ArrayDeque<ByteBuffer>) k.attachment();
            try {
                // one gathering write of all it owes, as a server's writer does for a page behind
                ((SocketChannel) k.channel()).write(owed.toArray(new ByteBuffer[0]));
                while (!owed.isEmpty() && !owed.peek().hasRemaining()) {
                    owed.poll();
                }
                if (owed.isEmpty()) {
                    k.interestOps(0);
                }
            } catch (IOException gone) {
                k.cancel();
            }
        }
    }

    private WebSocketFloor() {}

    public static void main(String[] args) throws Exception {
        int frameBytes = Integer.parseInt(args[0]);
        int threads = args.length > 1 ? Integer.parseInt(args[1]) : 2;
        List<Writer> writers = new ArrayList<>();
        for (int i = 0; i < threads; i++) {
            Writer w = new Writer();
            writers.add(w);
            Thread t = new Thread(w, "floor-writer-" + i);
            t.setDaemon(true);
            t.start();
        }
        ServerSocketChannel listener = ServerSocketChannel.open();
        listener.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 20_000);
        Thread acceptor = new Thread(() -> accept(listener, writers), "floor-acceptor");
        acceptor.setDaemon(true);
        acceptor.start();
        System.out.println("port " + listener.socket().getLocalPort());
        System.out.flush();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.US_ASCII));
        for (String line; (line = in.readLine()) != null; ) {
            byte[] frame = frame(line, frameBytes);
            for (Writer w : writers) {
                w.inbox.add(frame);
                w.selector.wakeup();
            }
        }
        long delivered = 0;
        for (Writer w : writers) {
            delivered += w.delivered;
        }
        System.out.println("delivered " + delivered);
    }

    /** Upgrades each connection as a web console would, answers its ?watch, and hands it to a writer. */
    private static void accept(ServerSocketChannel listener, List<Writer> writers) {
        int next = 0;
        while (true) {
            try {
                SocketChannel ch = listener.accept();
                ch.socket().setTcpNoDelay(true);
                String head = head(ch);
                Matcher m = KEY.matcher(head);
                String accept = m.find() ? Base64.getEncoder().encodeToString(MessageDigest.getInstance("SHA-1").digest(
                        (m.group(1) + "258EAFA5-E914-47DA-95CA-C5AB0DC85B11").getBytes(StandardCharsets.US_ASCII))) : "";
                write(ch, ("HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Accept: "
                        + accept + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
                skipFrame(ch); // the page's ?watch
                write(ch, text("{\"type\":\"reply\",\"id\":1,\"status\":\"OK\"}".getBytes(StandardCharsets.US_ASCII)));
                Writer w = writers.get(next++ % writers.size());
                w.inbox.add(ch);
                w.selector.wakeup();
            } catch (IOException | NoSuchAlgorithmException e) {
                if (!listener.isOpen()) {
                    return;
                }
                System.err.println("floor accept: " + e);
            }
        }
    }

    /** A push's frame: {@code {"type":"push",...,"text":"LINE"}} padded so the frame on the wire is {@code bytes} long. */
    static byte[] frame(String line, int bytes) {
        String json = "{\"type\":\"push\",\"id\":0,\"mailbox\":\"floor\",\"status\":\"OK\",\"text\":\"" + line + "\",\"pad\":\"";
        int head = bytes - 2 < 126 ? 2 : 4;
        int pad = Math.max(0, bytes - head - json.length() - 2);
        return text((json + " ".repeat(pad) + "\"}").getBytes(StandardCharsets.US_ASCII));
    }

    /** A server's text frame: unmasked (RFC 6455 5.1). */
    static byte[] text(byte[] payload) {
        ByteArrayOutputStream f = new ByteArrayOutputStream(payload.length + 4);
        f.write(0x81);
        if (payload.length < 126) {
            f.write(payload.length);
        } else {
            f.write(126);
            f.write(payload.length >> 8);
            f.write(payload.length & 0xff);
        }
        f.writeBytes(payload);
        return f.toByteArray();
    }

    private static String head(SocketChannel ch) throws IOException {
        ByteArrayOutputStream h = new ByteArrayOutputStream();
        ByteBuffer one = ByteBuffer.allocate(1);
        int state = 0;
        while (state < 4) {
            one.clear();
            if (ch.read(one) < 0) {
                throw new IOException("closed during the upgrade");
            }
            int c = one.get(0);
            h.write(c);
            state = (c == '\r' && (state == 0 || state == 2)) || (c == '\n' && (state == 1 || state == 3)) ? state + 1 : 0;
        }
        return h.toString(StandardCharsets.US_ASCII);
    }

    private static void skipFrame(SocketChannel ch) throws IOException {
        ByteBuffer h = read(ch, 2);
        int len7 = h.get(1) & 0x7f;
        long len = len7 == 126 ? read(ch, 2).getShort() & 0xffff : len7 == 127 ? read(ch, 8).getLong() : len7;
        read(ch, (int) len + ((h.get(1) & 0x80) != 0 ? 4 : 0));
    }

    private static ByteBuffer read(SocketChannel ch, int n) throws IOException {
        ByteBuffer b = ByteBuffer.allocate(n);
        while (b.hasRemaining()) {
            if (ch.read(b) < 0) {
                throw new IOException("closed during the ?watch");
            }
        }
        return b.flip();
    }

    private static void write(SocketChannel ch, byte[] bytes) throws IOException {
        ByteBuffer b = ByteBuffer.wrap(bytes);
        while (b.hasRemaining()) {
            ch.write(b);
        }
    }
}
