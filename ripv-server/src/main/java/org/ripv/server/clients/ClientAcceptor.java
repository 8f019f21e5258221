package org.ripv.server.clients;

import java.io.Closeable;
import java.io.IOException;
import java.nio.channels.ClosedChannelException;
import java.nio.channels.ServerSocketChannel;
import java.nio.channels.SocketChannel;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.atomic.AtomicInteger;
import javax.net.ssl.SSLContext;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.handlers.WriterPool;
import org.ripv.server.security.ConnectionGate;
import org.ripv.server.transport.ClientLoops;
import org.ripv.wire.FrameCodec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The client port (thesis 5.2.2, the server's accept loop): takes each connection, gives it a
 * six-digit client id, asks the {@link ConnectionGate} before anything else happens on it (so a
 * refused address costs no TLS handshake), and starts its {@link SocketHandler} on one of the
 * server's few selector threads ({@link ClientLoops}): no client has a thread of its own. Knows
 * the connected clients by id.
 */
public final class ClientAcceptor {
    private static final Logger log = LoggerFactory.getLogger(ClientAcceptor.class);

    private final ServerSocketChannel listener;
    private final SSLContext tls;
    private final ClientLoops loops;
    private final ScheduledExecutorService timers;
    private final FrameCodec codec;
    private final WriterPool writers;
    private final SocketHandler.Dispatcher dispatch;
    private final ConnectionGate gate;
    private final Map<String, SocketHandler> clients = new ConcurrentHashMap<>();
    private final AtomicInteger nextClientId = new AtomicInteger(100_000);
    private final Thread thread;
    private volatile boolean running = true;
    private final Object closes = new Object();

    /**
     * Starts accepting on a bound listener.
     *
     * @param tls the TLS context, or null for plain TCP ({@code --plain})
     */
    public ClientAcceptor(ServerSocketChannel listener, SSLContext tls, ScheduledExecutorService timers,
                   FrameCodec codec, WriterPool writers, SocketHandler.Dispatcher dispatch, ConnectionGate gate) throws IOException {
        this.listener = listener;
        this.tls = tls;
        this.loops = new ClientLoops();
        this.timers = timers;
        this.codec = codec;
        this.writers = writers;
        this.dispatch = dispatch;
        this.gate = gate;
        this.thread = new Thread(this::acceptLoop, "ripv-server-acceptor");
        thread.setDaemon(true);
        thread.start();
    }

    int port() {
        return listener.socket().getLocalPort();
    }

    public Optional<SocketHandler> client(String clientId) {
        return Optional.ofNullable(clients.get(clientId));
    }

    /** Every connected client, socket and web page alike. */
    public Collection<SocketHandler> clients() {
        return clients.values();
    }

    /** A client closed: it is forgotten (only that handler, not a later one given the same id). */
    public void forget(SocketHandler client) {
        clients.remove(client.clientId(), client);
        synchronized (closes) {
            closes.notifyAll();
        }
    }

    /** Waits until a client closes (freeing its socket), a second at most: other files may be freed too. */
    private void awaitAClose() {
        synchronized (closes) {
            try {
                closes.wait(1_000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                running = false;
            }
        }
    }

    private void acceptLoop() {
        while (running) {
            SocketChannel s;
            SocketHandler h;
            String id = newClientId();
            try {
                s = listener.accept();
            } catch (ClosedChannelException e) {
                break;
            } catch (IOException e) {
                if (running) {
                    log.warn("accept failed: {}", e.toString());
                    awaitAClose(); // out of open files (ulimit -n): accepting again at once would only fail again
                }
                continue;
            }
            try {
                h = new SocketHandler(loops.connection(s, tls), id, codec, writers, dispatch, timers);
            } catch (IOException e) {
                log.debug("client {} gone before it was set up: {}", id, e.toString());
                closeQuietly(s);
                continue;
            }
            if (!gate.admit(id, h.remoteInetAddress(), h::close)) {
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
            log.debug("client {} connected from {}", id, h.remoteAddress());
            h.start();
        }
    }

    /**
     * A web console page as a client (org.ripv.server.web): in-process, with no socket or thread of
     * its own, given an id, admitted by the gate like any connection (the browser's address),
     * marked logged in as the user the web log-in checked — from here on a client like any other.
     */
    SocketHandler adopt(SocketHandler.Peer page, String user, List<String> roles) throws IOException {
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
    public void close() {
        running = false;
        closeQuietly(listener);
        clients.values().forEach(SocketHandler::close);
        loops.close();
    }

    private static void closeQuietly(Closeable c) {
        try {
            c.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }
}
