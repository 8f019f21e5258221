package org.ripv.services.serial;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;
import org.ripv.security.AddressRanges;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Waits on a {@code listen://[ADDR:]PORT} link for vehicles, modems or RUDICS gateways to call
 * in, on a thread of its own, and hands every connection to the link's handler (which takes one
 * call at a time and refuses the others).
 */
final class CallListener implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(CallListener.class);
    private static final byte[] REFUSAL = "RIPV: calls from this address are not taken on this link\r\n"
            .getBytes(StandardCharsets.US_ASCII);

    private final ServerSocket server;
    private final Consumer<Socket> onCall;
    private final AddressRanges callers;
    private final String description;
    private volatile boolean closed;
    private long refusedFrom;
    private long lastRefusalLog;

    private CallListener(ServerSocket server, AddressRanges callers, Consumer<Socket> onCall) {
        this.server = server;
        this.callers = callers;
        this.onCall = onCall;
        this.description = "listen://" + server.getInetAddress().getHostAddress() + ":" + server.getLocalPort();
    }

    /** Binds the address now (so a port in use fails the start) and starts accepting. */
    static CallListener open(URI listen, String name, AddressRanges callers, Consumer<Socket> onCall) throws IOException {
        ServerSocket s = new ServerSocket();
        try {
            s.setReuseAddress(true);
            s.bind(new InetSocketAddress(listen.getHost(), listen.getPort()), 16);
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot listen on " + listen.getHost() + ":" + listen.getPort() + " for " + name
                    + ": " + e.getMessage(), e);
        }
        CallListener l = new CallListener(s, callers, onCall);
        Thread t = new Thread(l::run, "serial-calls-" + name);
        t.setDaemon(true);
        t.start();
        log.info("{}: waiting for calls on {}{}", name, l.description,
                callers.isEmpty() ? "" : " from " + callers);
        return l;
    }

    int port() {
        return server.getLocalPort();
    }

    String describe() {
        return description;
    }

    private void run() {
        while (!closed) {
            Socket s;
            try {
                s = server.accept();
            } catch (IOException e) {
                if (!closed) {
                    log.warn("{}: accepting a call failed: {}", description, e.toString());
                }
                continue;
            }
            if (!callers.isEmpty() && !callers.contains(s.getInetAddress())) {
                refuse(s);
                continue;
            }
            try {
                onCall.accept(s);
            } catch (RuntimeException e) {
                log.warn("{}: a call could not be taken: {}", description, e.toString());
                try {
                    s.close();
                } catch (IOException ignored) {
                    // already failing
                }
            }
        }
    }

    /**
     * A caller from an address the link does not take calls from: one line, hung up, never the
     * vehicle. Logged at most every 10 s with a count, so a flood cannot fill the log.
     */
    private void refuse(Socket s) {
        refusedFrom++;
        long now = System.nanoTime();
        if (lastRefusalLog == 0 || now - lastRefusalLog > 10_000_000_000L) {
            log.warn("{}: refused a call from {}: not in callers={} ({} refused so far)", description,
                    s.getInetAddress().getHostAddress(), callers, refusedFrom);
            lastRefusalLog = now;
        }
        try (s) {
            s.setSoTimeout(1000);
            s.getOutputStream().write(REFUSAL);
            s.getOutputStream().flush();
        } catch (IOException e) {
            log.debug("refusing {}: {}", s.getRemoteSocketAddress(), e.toString());
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            server.close();
        } catch (IOException e) {
            log.debug("closing {}: {}", description, e.toString());
        }
    }
}
