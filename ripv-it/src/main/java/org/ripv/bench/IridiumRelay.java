package org.ripv.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

/**
 * A TCP relay that behaves like an Iridium call: each direction carries baud/10 bytes a second,
 * every byte arrives {@code latency} after it was sent, and the call drops {@code dropAfter}
 * after it was answered (both sockets closed, as a lost satellite link does). One connection.
 */
final class IridiumRelay implements AutoCloseable {
    private record Chunk(byte[] bytes, long dueNanos) {
    }

    private static final Chunk END = new Chunk(new byte[0], 0);
    private final ServerSocket server = new ServerSocket(0);
    private final long nanosPerByte;
    private final long latencyNanos;
    private final long dropAfterMillis;
    private final InetSocketAddress target;
    private final ScheduledExecutorService dropper = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "iridium-drop");
        t.setDaemon(true);
        return t;
    });
    private volatile Socket a;
    private volatile Socket b;
    private volatile boolean dropped;

    IridiumRelay(int baud, long latencyMillis, long dropAfterMillis, InetSocketAddress target) throws IOException {
        this.nanosPerByte = 10_000_000_000L / baud;
        this.latencyNanos = TimeUnit.MILLISECONDS.toNanos(latencyMillis);
        this.dropAfterMillis = dropAfterMillis;
        this.target = target;
        Thread t = new Thread(this::acceptOne, "iridium-relay-" + server.getLocalPort());
        t.setDaemon(true);
        t.start();
    }

    int port() {
        return server.getLocalPort();
    }

    /** True when the call ended by the drop, not by either end. */
    boolean dropped() {
        return dropped;
    }

    private void acceptOne() {
        try {
            a = server.accept();
            b = connectWhenListening();
            dropper.schedule(() -> {
                dropped = true;
                closeQuietly();
            }, dropAfterMillis, TimeUnit.MILLISECONDS);
            direction(a.getInputStream(), b.getOutputStream(), "up");
            direction(b.getInputStream(), a.getOutputStream(), "down");
        } catch (IOException e) {
            closeQuietly();
        }
    }

    private Socket connectWhenListening() throws IOException {
        IOException last = null;
        for (int attempt = 0; attempt < 100; attempt++) {
            Socket s = new Socket();
            try {
                s.connect(target, 1_000);
                return s;
            } catch (IOException e) {
                s.close();
                last = e;
                LockSupport.parkNanos(100_000_000L); // socat starting up
            }
        }
        throw last;
    }

    /** A reader that stamps what arrives, and a writer that lets it out after the latency at the line's rate. */
    private void direction(InputStream in, OutputStream out, String name) {
        BlockingQueue<Chunk> queue = new LinkedBlockingQueue<>();
        Thread reader = new Thread(() -> {
            byte[] buf = new byte[1024];
            try {
                int n;
                while ((n = in.read(buf)) > 0) {
                    queue.put(new Chunk(java.util.Arrays.copyOf(buf, n), System.nanoTime() + latencyNanos));
                }
            } catch (IOException | InterruptedException e) {
                // the call is over
            } finally {
                queue.add(END);
            }
        }, "iridium-" + name + "-in");
        Thread writer = new Thread(() -> {
            long lineFreeAt = 0;
            try {
                while (true) {
                    Chunk c = queue.take();
                    if (c == END) {
                        break;
                    }
                    lineFreeAt = Math.max(lineFreeAt, c.dueNanos());
                    for (int i = 0; i < c.bytes().length; ) {
                        long due = lineFreeAt + nanosPerByte;
                        long now = System.nanoTime();
                        if (due > now) {
                            LockSupport.parkNanos(due - now);
                            now = System.nanoTime();
                        }
                        int k = (int) Math.max(1, Math.min(c.bytes().length - i, (now - lineFreeAt) / nanosPerByte));
                        out.write(c.bytes(), i, k);
                        out.flush();
                        i += k;
                        lineFreeAt += k * nanosPerByte;
                    }
                }
            } catch (IOException | InterruptedException e) {
                // the call is over
            } finally {
                closeQuietly();
            }
        }, "iridium-" + name + "-out");
        reader.setDaemon(true);
        writer.setDaemon(true);
        reader.start();
        writer.start();
    }

    private void closeQuietly() {
        for (Socket s : new Socket[] {a, b}) {
            if (s != null) {
                try {
                    s.close();
                } catch (IOException ignored) {
                    // closing
                }
            }
        }
    }

    @Override
    public void close() throws IOException {
        dropper.shutdownNow();
        server.close();
        closeQuietly();
    }
}
