package org.ripv.services.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A TCP relay that behaves like a serial line of a given baud rate: each direction carries
 * at most baud/10 bytes per second (8 data bits plus start and stop bit), each byte leaving
 * when the line would have finished sending it. One connection; used by {@link YmodemBenchmark}
 * to put a real line rate between two YMODEM ends (ours or lrzsz's behind socat).
 */
public final class YmodemBaudRelay implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(YmodemBaudRelay.class);
    private final ServerSocket server;
    private final long nanosPerByte;
    private final InetSocketAddress target;
    private volatile Socket a;
    private volatile Socket b;

    /** Listens on a free port; the first connection is relayed to {@code target}. */
    public YmodemBaudRelay(int baud, InetSocketAddress target) throws IOException {
        this.server = new ServerSocket(0);
        this.nanosPerByte = 10_000_000_000L / baud;
        this.target = target;
        Thread t = new Thread(this::acceptOne, "baud-relay-" + server.getLocalPort());
        t.setDaemon(true);
        t.start();
    }

    public int port() {
        return server.getLocalPort();
    }

    private void acceptOne() {
        try {
            a = server.accept();
            b = connectWhenListening();
            a.setTcpNoDelay(true);
            b.setTcpNoDelay(true);
            pump(a.getInputStream(), b.getOutputStream(), "up");
            pump(b.getInputStream(), a.getOutputStream(), "down");
        } catch (IOException e) {
            log.warn("relay: {}", e.toString());
        }
    }

    /** The target (socat starting up) may not listen yet: retry for up to ten seconds. */
    private Socket connectWhenListening() throws IOException {
        IOException last = null;
        for (int attempt = 0; attempt < 1000; attempt++) {
            Socket s = new Socket();
            try {
                s.connect(target, 1_000);
                return s;
            } catch (IOException e) {
                s.close();
                last = e;
                LockSupport.parkNanos(10_000_000L); // short: a benchmark's clock may be running
            }
        }
        throw last;
    }

    private void pump(InputStream in, OutputStream out, String name) {
        Thread t = new Thread(() -> {
            byte[] buf = new byte[4096];
            long lineFreeAt = System.nanoTime();
            boolean queued = false;
            try {
                int n;
                while ((n = in.read(buf)) > 0) {
                    long arrived = System.nanoTime();
                    // The line was idle only if nothing waited when the last bytes went out. Bytes
                    // that did wait were the UART's: a pause of this thread (a GC in the JVM it shares
                    // with one end) does not idle the line, and the clock catches up below.
                    if (lineFreeAt < arrived && !queued) {
                        lineFreeAt = arrived;
                    }
                    int sent = 0;
                    while (sent < n) {
                        // the next byte reaches the far end once the line has clocked it out
                        long due = lineFreeAt + nanosPerByte;
                        long now = System.nanoTime();
                        if (due > now) {
                            LockSupport.parkNanos(due - now);
                            now = System.nanoTime();
                        }
                        // every byte whose time has come goes out in one write (parking overshoots)
                        int k = (int) Math.max(1, Math.min(n - sent, (now - lineFreeAt) / nanosPerByte));
                        out.write(buf, sent, k);
                        out.flush();
                        sent += k;
                        lineFreeAt += k * nanosPerByte;
                    }
                    queued = in.available() > 0;
                }
            } catch (IOException e) {
                log.debug("relay {} ended: {}", name, e.toString());
            } finally {
                closeQuietly();
            }
        }, "baud-relay-" + name);
        t.setDaemon(true);
        t.start();
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
        server.close();
        closeQuietly();
    }
}
