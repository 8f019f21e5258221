package org.ripv.it;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/**
 * A TCP relay in front of a simulated vehicle that carries its bytes toward the service at a
 * radio modem's pace (bytes per second), so a transfer lasts long enough to watch and cancel
 * the way it does at sea; the other direction passes at once.
 */
final class SlowLinkRelay implements AutoCloseable {
    private static final InetAddress LOOPBACK = InetAddress.getLoopbackAddress();
    private final ServerSocket front;
    private final int targetPort;
    private final int bytesPerSecond;
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();
    private volatile boolean closed;

    SlowLinkRelay(int targetPort, int bytesPerSecond) throws IOException {
        this.targetPort = targetPort;
        this.bytesPerSecond = bytesPerSecond;
        front = new ServerSocket(0, 50, LOOPBACK);
        Thread t = new Thread(this::acceptLoop, "slow-link-relay");
        t.setDaemon(true);
        t.start();
    }

    int port() {
        return front.getLocalPort();
    }

    private void acceptLoop() {
        while (!closed) {
            try {
                Socket in = front.accept();
                Socket out = new Socket(LOOPBACK, targetPort);
                sockets.add(in);
                sockets.add(out);
                pump(out.getInputStream(), in.getOutputStream(), bytesPerSecond, "vehicle->service");
                pump(in.getInputStream(), out.getOutputStream(), 0, "service->vehicle");
            } catch (IOException e) {
                if (closed) {
                    return;
                }
            }
        }
    }

    private void pump(InputStream from, OutputStream to, int rate, String name) {
        Thread t = new Thread(() -> {
            byte[] buf = new byte[rate > 0 ? Math.max(64, rate / 20) : 8192];
            long start = System.nanoTime();
            long sent = 0;
            try {
                for (int n; (n = from.read(buf)) > 0; ) {
                    to.write(buf, 0, n);
                    to.flush();
                    sent += n;
                    if (rate > 0) {
                        long due = start + sent * 1_000_000_000L / rate;
                        long wait = due - System.nanoTime();
                        if (wait > 0) {
                            Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
                        }
                    }
                }
            } catch (IOException | InterruptedException e) {
                // the other side went; close both below
            } finally {
                try {
                    to.close();
                } catch (IOException e) {
                    // closing anyway
                }
            }
        }, "slow-link-" + name);
        t.setDaemon(true);
        t.start();
    }

    @Override
    public void close() {
        closed = true;
        try {
            front.close();
        } catch (IOException e) {
            // closing anyway
        }
        for (Socket s : sockets) {
            try {
                s.close();
            } catch (IOException e) {
                // closing anyway
            }
        }
    }
}
