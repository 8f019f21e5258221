package org.ripv.bench;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import javax.net.SocketFactory;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.Message;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.wire.FrameCodec;

/**
 * Many idle logged-in clients at little cost to the benchmark's own JVM: a few threads open them
 * one after another (the real handshake, greeting and {@code ?login}), and then each is only a
 * socket nobody reads — no thread, no buffer — as an idle user's client is to the server.
 */
final class IdleClients implements AutoCloseable {
    private final List<Socket> open = Collections.synchronizedList(new ArrayList<>());

    /**
     * Opens {@code n} clients on {@code threads} threads. Fewer threads than the server lets one
     * address hold connections that have not logged in yet (16 by default), or the server refuses
     * the surplus as it should.
     */
    void open(int n, int threads, SocketFactory sockets, String host, int port, String user, char[] password) throws Exception {
        AtomicInteger left = new AtomicInteger(n);
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            List<Future<?>> all = new ArrayList<>();
            byte[] pw = new String(password).getBytes(StandardCharsets.UTF_8);
            for (int t = 0; t < threads; t++) {
                all.add(pool.submit(() -> {
                    FrameCodec codec = new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME);
                    while (left.getAndDecrement() > 0) {
                        open.add(login(sockets, host, port, user, pw, codec));
                    }
                    return null;
                }));
            }
            for (Future<?> f : all) {
                f.get();
            }
        } finally {
            pool.shutdownNow();
        }
    }

    int size() {
        return open.size();
    }

    private static Socket login(SocketFactory sockets, String host, int port, String user, byte[] pw, FrameCodec codec)
            throws IOException {
        Socket s = sockets.createSocket();
        try {
            s.connect(new InetSocketAddress(host, port), 30_000);
            s.setSoTimeout(60_000);
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(s.getOutputStream(), 1024));
            // Unbuffered reads: nothing past the log-in's reply is taken from the socket.
            DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream(), 1));
            FrameCodec.writeGreeting(out);
            FrameCodec.readGreeting(in);
            codec.write(out, new IncomingServerMessage(new Header(1, new IdBadge("000000", user), List.of(), "", "",
                    "?login " + user, Priority.URGENT, new Attachment("password", pw))));
            while (true) {
                Message m = codec.read(in);
                if (m.header().messageId() == 1 && m.footer().status().isFinal()) {
                    if (m.footer().status() != Status.OK) {
                        throw new IOException("log-in refused: " + m.footer().replyText());
                    }
                    return s;
                }
            }
        } catch (IOException | RuntimeException e) {
            s.close();
            throw e;
        }
    }

    @Override
    public void close() {
        synchronized (open) {
            for (Socket s : open) {
                try {
                    s.close();
                } catch (IOException ignored) {
                    // closing anyway
                }
            }
            open.clear();
        }
    }
}
