package org.ripv.services.bench;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.locks.LockSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The plumbing every benchmark relay shares: it listens on a free port, connects the first
 * caller to the target, and hands both sockets to a {@link Carrier} that moves the bytes its own
 * way (at a line rate in {@link YmodemBaudRelay}; with latency and drops in ripv-it's Iridium-like
 * relay). One connection; {@link #hangUp} ends it from either side.
 */
public final class OneCallRelay implements AutoCloseable {
    /** Moves the bytes between the two ends on threads of its own; called once, on the accepting thread. */
    @FunctionalInterface
    public interface Carrier {
        void carry(Socket caller, Socket target) throws IOException;
    }

    private static final Logger log = LoggerFactory.getLogger(OneCallRelay.class);
    private final ServerSocket server;
    private final InetSocketAddress target;
    private final Carrier carrier;
    private volatile Socket a;
    private volatile Socket b;

    /** Listens on a free port at once; the accepting thread is named {@code name-PORT}. */
    public OneCallRelay(String name, InetSocketAddress target, Carrier carrier) throws IOException {
        this.server = new ServerSocket(0);
        this.target = target;
        this.carrier = carrier;
        Thread t = new Thread(this::acceptOne, name + "-" + server.getLocalPort());
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
            carrier.carry(a, b);
        } catch (IOException e) {
            log.warn("relay: {}", e.toString());
            hangUp();
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

    /** Closes both ends, as a line that went dead does; the carrier's threads then end on their own. */
    public void hangUp() {
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
        hangUp();
    }
}
