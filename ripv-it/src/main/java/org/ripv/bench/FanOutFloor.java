package org.ripv.bench;

import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.ByteBuffer;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;

/**
 * The floor under the console benchmark: the same fan-out with no RIPV in it. A frame the size of
 * a console push goes to N loopback sockets, written by as many threads as the server's writer
 * pool and read by the same {@link RawWatchers} loops as the crowd. What is left between this and
 * the crowd's figures is RIPV's; this itself is what this machine's kernel costs for a thousand
 * TCP sends and receives on the same cores (docs/performance.md).
 */
final class FanOutFloor implements AutoCloseable {
    private final ServerSocket listener;
    private final List<Socket> sent = new ArrayList<>();
    private final List<Writer> writers = new ArrayList<>();
    private final RawWatchers readers;
    private final int frameBytes;

    /** One writer thread and its share of the sockets. */
    private static final class Writer implements Runnable {
        final List<OutputStream> outs = new ArrayList<>();
        final BlockingQueue<byte[]> frames = new ArrayBlockingQueue<>(1024);
        final Thread thread;

        Writer(int i) {
            thread = new Thread(this, "bench-floor-writer-" + i);
            thread.setDaemon(true);
        }

        @Override
        public void run() {
            try {
                while (true) {
                    byte[] f = frames.take();
                    if (f.length == 0) {
                        return;
                    }
                    for (OutputStream o : outs) {
                        o.write(f); // one write(2) per socket, as the server's writer after its flush
                    }
                }
            } catch (InterruptedException | IOException e) {
                // closed
            }
        }
    }

    /**
     * @param watches    one per socket: where its delays go
     * @param writers    writer threads (the server's pool has one per core, at least two)
     * @param readers    selector threads reading the sockets
     * @param frameBytes the frame's size on the wire, length prefix included
     */
    FanOutFloor(List<ConsoleBench.Watch> watches, int writers, int readers, int frameBytes) throws IOException {
        this.frameBytes = frameBytes;
        this.listener = new ServerSocket(0, watches.size() + 50, InetAddress.getLoopbackAddress());
        this.readers = new RawWatchers(readers);
        for (int i = 0; i < writers; i++) {
            this.writers.add(new Writer(i));
        }
        InetSocketAddress to = new InetSocketAddress(InetAddress.getLoopbackAddress(), listener.getLocalPort());
        for (int i = 0; i < watches.size(); i++) {
            SocketChannel ch = SocketChannel.open(to);
            ch.socket().setTcpNoDelay(true);
            Socket s = listener.accept();
            s.setTcpNoDelay(true);
            sent.add(s);
            this.writers.get(i % writers).outs.add(s.getOutputStream());
            this.readers.watch(ch, watches.get(i)::record);
        }
        this.writers.forEach(w -> w.thread.start());
    }

    /** Sends one line: its text in a frame of {@code frameBytes}, to every socket. */
    void line(String text) {
        byte[] t = text.getBytes(StandardCharsets.US_ASCII);
        byte[] f = new byte[Math.max(frameBytes, 4 + t.length + 1)];
        Arrays.fill(f, 4, f.length, (byte) 'x');
        ByteBuffer.wrap(f).putInt(f.length - 4);
        System.arraycopy(t, 0, f, 4, t.length);
        f[4 + t.length] = 0; // ends the number for the readers' scan
        for (Writer w : writers) {
            if (!w.frames.offer(f)) {
                throw new IllegalStateException("the floor's writers fell 1,024 lines behind");
            }
        }
    }

    @Override
    public void close() throws IOException {
        for (Writer w : writers) {
            w.frames.offer(new byte[0]);
        }
        readers.close();
        for (Socket s : sent) {
            s.close();
        }
        listener.close();
    }
}
