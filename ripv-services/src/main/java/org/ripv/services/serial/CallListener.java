package org.ripv.services.serial;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Waits on a {@code listen://[ADDR:]PORT} link for vehicles, modems or RUDICS gateways to call
 * in, on a thread of its own, and hands every connection to the link's handler (which takes one
 * call at a time and refuses the others).
 */
final class CallListener implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(CallListener.class);

    private final ServerSocket server;
    private final Consumer<Socket> onCall;
    private final String description;
    private volatile boolean closed;

    private CallListener(ServerSocket server, Consumer<Socket> onCall) {
        this.server = server;
        this.onCall = onCall;
        this.description = "listen://" + server.getInetAddress().getHostAddress() + ":" + server.getLocalPort();
    }

    /** Binds the address now (so a port in use fails the start) and starts accepting. */
    static CallListener open(URI listen, String name, Consumer<Socket> onCall) throws IOException {
        ServerSocket s = new ServerSocket();
        try {
            s.setReuseAddress(true);
            s.bind(new InetSocketAddress(listen.getHost(), listen.getPort()), 16);
        } catch (IOException e) {
            s.close();
            throw new IOException("cannot listen on " + listen.getHost() + ":" + listen.getPort() + " for " + name
                    + ": " + e.getMessage(), e);
        }
        CallListener l = new CallListener(s, onCall);
        Thread t = new Thread(l::run, "serial-calls-" + name);
        t.setDaemon(true);
        t.start();
        log.info("{}: waiting for calls on {}", name, l.description);
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
