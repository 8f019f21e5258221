package org.ripv.services.bench;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A TCP relay that behaves like a serial line of a given baud rate: each direction carries
 * at most baud/10 bytes per second ({@link LineClock}), each byte leaving when the line would have
 * finished sending it. One connection ({@link OneCallRelay}); used by {@link YmodemBenchmark}
 * to put a real line rate between two YMODEM ends (ours or lrzsz's behind socat).
 */
public final class YmodemBaudRelay implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(YmodemBaudRelay.class);
    private final int baud;
    private final OneCallRelay relay;

    /** Listens on a free port; the first connection is relayed to {@code target}. */
    public YmodemBaudRelay(int baud, InetSocketAddress target) throws IOException {
        this.baud = baud;
        this.relay = new OneCallRelay("baud-relay", target, (a, b) -> {
            a.setTcpNoDelay(true);
            b.setTcpNoDelay(true);
            pump(a.getInputStream(), b.getOutputStream(), "up");
            pump(b.getInputStream(), a.getOutputStream(), "down");
        });
    }

    public int port() {
        return relay.port();
    }

    private void pump(InputStream in, OutputStream out, String name) {
        Thread t = new Thread(() -> {
            byte[] buf = new byte[4096];
            LineClock line = new LineClock(baud);
            boolean queued = false;
            try {
                int n;
                while ((n = in.read(buf)) > 0) {
                    // The line was idle only if nothing waited when the last bytes went out. Bytes
                    // that did wait were the UART's: a pause of this thread (a GC in the JVM it shares
                    // with one end) does not idle the line, and the clock catches up in send.
                    if (!queued) {
                        line.idleUntil(System.nanoTime());
                    }
                    line.send(out, buf, 0, n);
                    queued = in.available() > 0;
                }
            } catch (IOException e) {
                log.debug("relay {} ended: {}", name, e.toString());
            } finally {
                relay.hangUp();
            }
        }, "baud-relay-" + name);
        t.setDaemon(true);
        t.start();
    }

    @Override
    public void close() throws IOException {
        relay.close();
    }
}
