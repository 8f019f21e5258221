package org.ripv.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.Arrays;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.ripv.services.bench.LineClock;
import org.ripv.services.bench.OneCallRelay;

/**
 * A TCP relay that behaves like an Iridium call: each direction carries baud/10 bytes a second
 * ({@link LineClock}), every byte arrives {@code latency} after it was sent, and the call drops
 * {@code dropAfter} after it was answered (both sockets closed, as a lost satellite link does).
 * One connection ({@link OneCallRelay}).
 */
final class IridiumRelay implements AutoCloseable {
    private record Chunk(byte[] bytes, long dueNanos) {
    }

    private static final Chunk END = new Chunk(new byte[0], 0);
    private final int baud;
    private final long latencyNanos;
    private final long dropAfterMillis;
    private final ScheduledExecutorService dropper = Executors.newSingleThreadScheduledExecutor(r -> {
        Thread t = new Thread(r, "iridium-drop");
        t.setDaemon(true);
        return t;
    });
    private final OneCallRelay relay;
    private volatile boolean dropped;

    IridiumRelay(int baud, long latencyMillis, long dropAfterMillis, InetSocketAddress target) throws IOException {
        this.baud = baud;
        this.latencyNanos = TimeUnit.MILLISECONDS.toNanos(latencyMillis);
        this.dropAfterMillis = dropAfterMillis;
        this.relay = new OneCallRelay("iridium-relay", target, this::call);
    }

    int port() {
        return relay.port();
    }

    /** True when the call ended by the drop, not by either end. */
    boolean dropped() {
        return dropped;
    }

    private void call(Socket a, Socket b) throws IOException {
        dropper.schedule(() -> {
            dropped = true;
            relay.hangUp();
        }, dropAfterMillis, TimeUnit.MILLISECONDS);
        direction(a.getInputStream(), b.getOutputStream(), "up");
        direction(b.getInputStream(), a.getOutputStream(), "down");
    }

    /** A reader that stamps what arrives, and a writer that lets it out after the latency at the line's rate. */
    private void direction(InputStream in, OutputStream out, String name) {
        BlockingQueue<Chunk> queue = new LinkedBlockingQueue<>();
        Thread reader = new Thread(() -> {
            byte[] buf = new byte[1024];
            try {
                int n;
                while ((n = in.read(buf)) > 0) {
                    queue.put(new Chunk(Arrays.copyOf(buf, n), System.nanoTime() + latencyNanos));
                }
            } catch (IOException | InterruptedException e) {
                // the call is over
            } finally {
                queue.add(END);
            }
        }, "iridium-" + name + "-in");
        Thread writer = new Thread(() -> {
            LineClock line = new LineClock(baud);
            try {
                while (true) {
                    Chunk c = queue.take();
                    if (c == END) {
                        break;
                    }
                    line.idleUntil(c.dueNanos());
                    line.send(out, c.bytes(), 0, c.bytes().length);
                }
            } catch (IOException | InterruptedException e) {
                // the call is over
            } finally {
                relay.hangUp();
            }
        }, "iridium-" + name + "-out");
        reader.setDaemon(true);
        writer.setDaemon(true);
        reader.start();
        writer.start();
    }

    @Override
    public void close() throws IOException {
        dropper.shutdownNow();
        relay.close();
    }
}
