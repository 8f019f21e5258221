package org.ripv.server;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.Collection;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.handlers.WriterPool;
import org.ripv.server.security.ConnectionGate;
import org.ripv.wire.FrameCodec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The client port (thesis 5.2.2, the server's accept loop): takes each connection, gives it a
 * six-digit client id, asks the {@link ConnectionGate} before anything else happens on it (so a
 * refused address costs no TLS handshake and no thread), and starts its {@link SocketHandler}.
 * Knows the connected clients by id.
 */
final class ClientAcceptor {
    private static final Logger log = LoggerFactory.getLogger(ClientAcceptor.class);

    private final ServerSocket listener;
    private final FrameCodec codec;
    private final WriterPool writers;
    private final SocketHandler.Dispatcher dispatch;
    private final ConnectionGate gate;
    private final Map<String, SocketHandler> clients = new ConcurrentHashMap<>();
    private final AtomicInteger nextClientId = new AtomicInteger(100_000);
    private final Thread thread;
    private volatile boolean running = true;

    /** Starts accepting on a bound listener. */
    ClientAcceptor(ServerSocket listener, FrameCodec codec, WriterPool writers, SocketHandler.Dispatcher dispatch,
                   ConnectionGate gate) {
        this.listener = listener;
        this.codec = codec;
        this.writers = writers;
        this.dispatch = dispatch;
        this.gate = gate;
        this.thread = new Thread(this::acceptLoop, "ripv-server-acceptor");
        thread.setDaemon(true);
        thread.start();
    }

    int port() {
        return listener.getLocalPort();
    }

    Optional<SocketHandler> client(String clientId) {
        return Optional.ofNullable(clients.get(clientId));
    }

    Collection<SocketHandler> clients() {
        return clients.values();
    }

    /** A client closed: it is forgotten (only that handler, not a later one given the same id). */
    void forget(SocketHandler client) {
        clients.remove(client.clientId(), client);
    }

    private void acceptLoop() {
        while (running) {
            Socket s;
            try {
                s = listener.accept();
            } catch (IOException e) {
                if (running) {
                    log.warn("accept failed: {}", e.toString());
                }
                continue;
            }
            String id = newClientId();
            SocketHandler h = new SocketHandler(s, id, codec, writers, dispatch);
            if (!gate.admit(id, s.getInetAddress(), h::close)) {
                closeQuietly(s);
                continue;
            }
            clients.put(id, h);
            if (!running) {
                // Accepted just as the server stopped: close() may already have closed the others,
                // and this one must not live on, talking to a stopped server.
                h.close();
                break;
            }
            log.debug("client {} connected from {}", id, s.getRemoteSocketAddress());
            h.start();
        }
    }

    /**
     * A web console page as a client (org.ripv.server.web): in-process, with no socket or thread of
     * its own, given an id, admitted by the gate like any connection (the browser's address),
     * marked logged in as the user the web log-in checked — from here on a client like any other.
     */
    SocketHandler adopt(SocketHandler.Peer page, String user, java.util.List<String> roles) throws IOException {
        String id = newClientId();
        SocketHandler h = SocketHandler.inProcess(id, page, dispatch);
        if (!running || !gate.admit(id, page.address(), h::close)) {
            throw new IOException("the server takes no more connections now");
        }
        if (!gate.loggedIn(id)) {
            h.close();
            throw new IOException("the server has " + gate.limits().maxLoggedIn() + " clients logged in, the most it takes");
        }
        h.loggedIn(user, roles);
        clients.put(id, h);
        if (!running) {
            h.close(); // the server stopped meanwhile: close() may have missed this one
            throw new IOException("the server is stopping");
        }
        return h;
    }

    private String newClientId() {
        while (true) {
            int n = nextClientId.incrementAndGet();
            if (n > 999_999) {
                nextClientId.compareAndSet(n, 100_000);
                continue;
            }
            String id = Integer.toString(n);
            if (!clients.containsKey(id)) {
                return id;
            }
        }
    }

    /** Stops accepting and disconnects every client. */
    void close() {
        running = false;
        closeQuietly(listener);
        clients.values().forEach(SocketHandler::close);
    }

    private static void closeQuietly(java.io.Closeable c) {
        try {
            c.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}
