package org.ripv.client.managers;

import java.io.IOException;
import java.time.Duration;
import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.client.managers.ClientModel.Connection;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.SessionInfo;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** Owns the connection's life: log-in, log-out, the periodic refresh, and reconnecting with back-off after a drop. */
final class Session {
    // Logs under the façade's name, as before the split.
    private static final Logger log = LoggerFactory.getLogger(GuiManager.class);

    private record Credentials(String host, int port, String user, char[] password) {}

    private final ClientModel model;
    private final Executor ui;
    private final GuiManager.Connector connector;
    private final GuiManager.Timings timings;
    private final Executor io;
    private final ScheduledExecutorService timer;
    private final GuiInterface gui;
    private final Consumer<OutgoingServerMessage> replies;
    private final Runnable refreshAll;
    private final Runnable refreshServices;
    private volatile ClientSocketHandler conn;
    private volatile Credentials credentials;
    private volatile boolean closed;
    private ScheduledFuture<?> refresher;

    /**
     * @param replies         takes every reply, on the socket's reader thread
     * @param refreshAll      asks for everything the window shows (after each log-in)
     * @param refreshServices asks for services and MailBoxes (every refresh period)
     */
    Session(ClientModel model, Executor ui, GuiManager.Connector connector, GuiManager.Timings timings,
            Executor io, ScheduledExecutorService timer, GuiInterface gui, Consumer<OutgoingServerMessage> replies,
            Runnable refreshAll, Runnable refreshServices) {
        this.model = model;
        this.ui = ui;
        this.connector = connector;
        this.timings = timings;
        this.io = io;
        this.timer = timer;
        this.gui = gui;
        this.replies = replies;
        this.refreshAll = refreshAll;
        this.refreshServices = refreshServices;
    }

    /** The live connection, or null. */
    ClientSocketHandler connection() {
        return conn;
    }

    /** See {@link GuiManager#logIn}. */
    CompletableFuture<SessionInfo> logIn(String host, int port, String user, char[] password) {
        Credentials c = new Credentials(host, port, user, password.clone());
        CompletableFuture<SessionInfo> result = new CompletableFuture<>();
        gui.showConnection(Connection.CONNECTING, "connecting to " + host + ":" + port + " as " + user);
        io.execute(() -> {
            try {
                SessionInfo s = open(c);
                credentials = c;
                result.complete(s);
            } catch (IOException | RipvErrorException | RuntimeException e) {
                Arrays.fill(c.password(), '\0');
                gui.showConnection(Connection.DISCONNECTED, Failures.describe(e));
                result.completeExceptionally(e);
            }
        });
        return result;
    }

    /** Connects, logs in, starts listening and refreshes; on the calling (non-UI) thread. */
    private SessionInfo open(Credentials c) throws IOException, RipvErrorException {
        ClientSocketHandler h = connector.connect(c.host(), c.port());
        SessionInfo s;
        try {
            s = h.login(c.user(), c.password());
        } catch (IOException | RipvErrorException | RuntimeException e) {
            h.close();
            throw e;
        }
        h.addListener(new ConnectionListener(h));
        if (!h.isOpen()) {
            // It dropped between log-in and the listener: nobody would hear of it, so fail now.
            throw new IOException("the connection to " + h.server() + " closed right after log-in");
        }
        ClientSocketHandler old = conn;
        conn = h;
        if (old != null && old != h) {
            old.close();
        }
        String detail = "logged in to " + h.server() + " as " + s.user();
        ui.execute(() -> {
            model.connection(Connection.CONNECTED, detail, h.server());
            model.notice(detail, false);
        });
        gui.showSession(s);
        startRefresher();
        refreshAll.run();
        return s;
    }

    private synchronized void startRefresher() {
        if (refresher == null && !closed) {
            long p = timings.refreshPeriod().toMillis();
            refresher = timer.scheduleWithFixedDelay(refreshServices, p, p, TimeUnit.MILLISECONDS);
        }
    }

    /** Logs out and closes the connection; no reconnect. */
    void logOut() {
        forget();
        gui.showConnection(Connection.DISCONNECTED, "logged out");
    }

    /** For good: no reconnect, no refresh from now on. The caller stops the threads. */
    void close() {
        closed = true;
        forget();
    }

    private synchronized void stopRefresher() {
        if (refresher != null) {
            refresher.cancel(false);
            refresher = null;
        }
    }

    /** Wipes the credentials (so no reconnect), stops refreshing and closes the connection. */
    private void forget() {
        stopRefresher();
        Credentials c = credentials;
        credentials = null;
        if (c != null) {
            Arrays.fill(c.password(), '\0');
        }
        ClientSocketHandler h = conn;
        conn = null;
        if (h != null) {
            h.close();
        }
    }

    /** One per connection, so a late disconnect of an old connection is ignored. */
    private final class ConnectionListener implements ClientSocketHandler.Listener {
        private final ClientSocketHandler handler;

        ConnectionListener(ClientSocketHandler handler) {
            this.handler = handler;
        }

        @Override
        public void onReply(OutgoingServerMessage reply) {
            replies.accept(reply);
        }

        @Override
        public void onDisconnected(Exception cause) {
            if (conn != handler || closed) {
                return;
            }
            conn = null;
            Credentials c = credentials;
            String why = cause == null || cause.getMessage() == null ? "connection closed" : cause.getMessage();
            log.warn("lost the connection to {}: {}", handler.server(), why);
            if (c == null) {
                gui.showConnection(Connection.DISCONNECTED, "disconnected from " + handler.server() + ": " + why);
                return;
            }
            gui.showConnection(Connection.LOST, "lost the connection to " + handler.server() + " (" + why
                    + "); reconnecting...");
            scheduleReconnect(c, 1, timings.firstRetry());
        }
    }

    private void scheduleReconnect(Credentials c, int attempt, Duration delay) {
        if (closed || credentials != c) {
            return;
        }
        timer.schedule(() -> reconnect(c, attempt, delay), delay.toMillis(), TimeUnit.MILLISECONDS);
    }

    private void reconnect(Credentials c, int attempt, Duration delay) {
        if (closed || credentials != c) {
            return;
        }
        try {
            open(c);
            log.info("reconnected to {}:{} after {} attempt(s)", c.host(), c.port(), attempt);
            gui.showNotice("reconnected to " + c.host() + ":" + c.port(), false);
        } catch (RipvErrorException e) {
            // The server is back but refuses us (password changed, user removed): stop trying.
            credentials = null;
            gui.showConnection(Connection.DISCONNECTED, "the server refused the log-in again: " + e.getMessage());
        } catch (IOException | RuntimeException e) {
            Duration next = delay.multipliedBy(2);
            if (next.compareTo(timings.maxRetry()) > 0) {
                next = timings.maxRetry();
            }
            gui.showConnection(Connection.LOST, "cannot reach " + c.host() + ":" + c.port() + " ("
                    + Failures.describe(e) + "); retrying in " + Math.max(1, next.toSeconds()) + " s, attempt "
                    + (attempt + 1));
            scheduleReconnect(c, attempt + 1, next);
        }
    }
}
