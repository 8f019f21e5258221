package org.ripv.client.managers;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executor;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.client.managers.ClientModel.Connection;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.ServiceModel.LineKind;
import org.ripv.messages.FileListing;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.SessionInfo;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.UpdateCount;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.MalformedNameException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The overseer of the RIPVClient's GUI (thesis 4.1.2, 5.2.6): it holds the connection to the
 * server, turns operator actions into requests, and dispatches every reply by its Footer's SID
 * or FID (Appendix B) to the part of the {@link ClientModel} that shows it.
 *
 * <p>Threading. Model changes run on the UI executor ({@code SwingUtilities::invokeLater} in
 * the GUI; the calling thread in headless tests). Network and file work runs on the
 * {@code ripv-gui-io-N} threads; replies arrive on the socket's reader thread; periodic refresh
 * and reconnect run on {@code ripv-gui-timer}. The event thread never waits for the network.
 *
 * <p>Live system: {@code ?services} and {@code ?mailboxes} are asked for every
 * {@code refreshPeriod} (thesis default behaviour) and on demand ({@link #refresh}). When the
 * connection drops, the model says so and the manager reconnects with growing back-off and
 * logs in again with the same credentials (kept in memory only).
 */
public final class GuiManager implements GuiInterface, AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(GuiManager.class);

    /** Opens a connection; {@link ClientSocketHandler#connect(String, int)} in production. */
    @FunctionalInterface
    public interface Connector {
        ClientSocketHandler connect(String host, int port) throws IOException;
    }

    /** Tunable timings. */
    public record Timings(Duration refreshPeriod, Duration firstRetry, Duration maxRetry) {
        public static final Timings DEFAULT = new Timings(Duration.ofSeconds(15), Duration.ofSeconds(1),
                Duration.ofSeconds(30));
    }

    private record Credentials(String host, int port, String user, char[] password) {}

    /** Where a request came from: the service tab whose COM panel sent it, and whether to echo its text. */
    private record Origin(String service, boolean echo) {}

    private final ClientModel model;
    private final Executor ui;
    private final Connector connector;
    private final Timings timings;
    private final ExecutorService io;
    private final ScheduledExecutorService timer;
    private final Map<Long, Origin> origins = new ConcurrentHashMap<>();
    private final AtomicLong transferIds = new AtomicLong();
    private volatile ClientSocketHandler conn;
    private volatile Credentials credentials;
    private volatile boolean closed;
    private ScheduledFuture<?> refresher;

    /** A manager for the Swing GUI: changes go to the event thread. */
    public GuiManager(ClientModel model) {
        this(model, SwingUtilities::invokeLater, ClientSocketHandler::connect, Timings.DEFAULT);
    }

    /**
     * @param model     the model to keep up to date
     * @param ui        runs model changes; must run them in order, on one thread at a time
     * @param connector opens connections
     * @param timings   refresh period and reconnect back-off
     */
    public GuiManager(ClientModel model, Executor ui, Connector connector, Timings timings) {
        this.model = Objects.requireNonNull(model, "model");
        this.ui = Objects.requireNonNull(ui, "ui");
        this.connector = Objects.requireNonNull(connector, "connector");
        this.timings = Objects.requireNonNull(timings, "timings");
        this.io = Executors.newCachedThreadPool(named("ripv-gui-io-"));
        this.timer = Executors.newSingleThreadScheduledExecutor(named("ripv-gui-timer"));
    }

    private static ThreadFactory named(String prefix) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, prefix.endsWith("-") ? prefix + n.incrementAndGet() : prefix);
            t.setDaemon(true);
            return t;
        };
    }

    public ClientModel model() {
        return model;
    }

    /** The live connection, or null. */
    public ClientSocketHandler connection() {
        return conn;
    }

    // ---------------------------------------------------------------- connecting

    /**
     * Connects and logs in, off the calling thread. The future fails with a
     * {@link RipvErrorException} carrying the server's reason when the log-in is refused, or an
     * {@link IOException} when the server cannot be reached; the model says the same.
     * On success the client refreshes everything and keeps the connection alive from now on.
     */
    public CompletableFuture<SessionInfo> logIn(String host, int port, String user, char[] password) {
        Credentials c = new Credentials(host, port, user, password.clone());
        CompletableFuture<SessionInfo> result = new CompletableFuture<>();
        showConnection(Connection.CONNECTING, "connecting to " + host + ":" + port + " as " + user);
        io.execute(() -> {
            try {
                SessionInfo s = open(c);
                credentials = c;
                result.complete(s);
            } catch (IOException | RipvErrorException | RuntimeException e) {
                Arrays.fill(c.password(), '\0');
                showConnection(Connection.DISCONNECTED, describe(e));
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
        showSession(s);
        startRefresher();
        refresh();
        return s;
    }

    private synchronized void startRefresher() {
        if (refresher == null && !closed) {
            long p = timings.refreshPeriod().toMillis();
            refresher = timer.scheduleWithFixedDelay(this::refreshServices, p, p, TimeUnit.MILLISECONDS);
        }
    }

    /** Logs out and closes the connection; no reconnect. */
    public void logOut() {
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
        showConnection(Connection.DISCONNECTED, "logged out");
    }

    /** One per connection, so a late disconnect of an old connection is ignored. */
    private final class ConnectionListener implements ClientSocketHandler.Listener {
        private final ClientSocketHandler handler;

        ConnectionListener(ClientSocketHandler handler) {
            this.handler = handler;
        }

        @Override
        public void onReply(OutgoingServerMessage reply) {
            dispatch(reply);
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
                showConnection(Connection.DISCONNECTED, "disconnected from " + handler.server() + ": " + why);
                return;
            }
            showConnection(Connection.LOST, "lost the connection to " + handler.server() + " (" + why
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
            showNotice("reconnected to " + c.host() + ":" + c.port(), false);
        } catch (RipvErrorException e) {
            // The server is back but refuses us (password changed, user removed): stop trying.
            credentials = null;
            showConnection(Connection.DISCONNECTED, "the server refused the log-in again: " + e.getMessage());
        } catch (IOException | RuntimeException e) {
            Duration next = delay.multipliedBy(2);
            if (next.compareTo(timings.maxRetry()) > 0) {
                next = timings.maxRetry();
            }
            showConnection(Connection.LOST, "cannot reach " + c.host() + ":" + c.port() + " (" + describe(e)
                    + "); retrying in " + Math.max(1, next.toSeconds()) + " s, attempt " + (attempt + 1));
            scheduleReconnect(c, attempt + 1, next);
        }
    }

    // ---------------------------------------------------------------- operator actions

    /** Asks for everything the window shows: services, mailboxes, directories and files. */
    public void refresh() {
        refreshServices();
        refreshFiles();
    }

    /** {@code ?services} and {@code ?mailboxes}: the SEL tree, the tabs and the MAM trees. */
    public void refreshServices() {
        background("?services");
        background("?mailboxes");
    }

    /** {@code ?uldir ?dldir ?ulfiles ?dlfiles}: the FIM FileTree. */
    public void refreshFiles() {
        background("?uldir");
        background("?dldir");
        background("?ulfiles");
        background("?dlfiles");
    }

    private void background(String command) {
        send("", command, Priority.NORMAL, null);
    }

    /**
     * Sends what the operator typed in a service's COM panel: {@code ?...} to the server, anything
     * else to the service's target MailBox with the panel's priority. Call on the UI thread.
     */
    public void sendCommand(String service, String line) {
        ServiceModel m = model.service(service);
        String command = line == null ? "" : line.strip();
        if (m == null || command.isEmpty()) {
            return;
        }
        if (command.startsWith("?")) {
            m.sent(command);
            model.fire(ClientModel.Kind.COM, service);
            send("", command, m.priority(), new Origin(service, true));
            return;
        }
        if (m.target().isEmpty()) {
            m.append(LineKind.ERROR, "pick a mailbox in the MAM tree first: '" + command + "' was not sent");
            model.fire(ClientModel.Kind.COM, service);
            return;
        }
        m.sent(command);
        model.fire(ClientModel.Kind.COM, service);
        send(m.target(), command, m.priority(), new Origin(service, true));
    }

    /** Makes a MailBox the service's target (TT) and asks for its status (SS). Call on the UI thread. */
    public void selectMailbox(String service, String mailbox) {
        ServiceModel m = model.service(service);
        if (m == null || mailbox == null || mailbox.equals(m.target())) {
            return;
        }
        m.target(mailbox);
        model.fire(ClientModel.Kind.COM, service);
        send("", "?status " + mailbox, Priority.NORMAL, new Origin(service, false));
    }

    /** Sets the priority of the service's next commands (PR). Call on the UI thread. */
    public void setPriority(String service, Priority priority) {
        ServiceModel m = model.service(service);
        if (m != null && priority != null && priority != m.priority()) {
            m.priority(priority);
            model.fire(ClientModel.Kind.COM, service);
        }
    }

    /** Closes one DAB table tab. Call on the UI thread. */
    public void closeTable(String service, int index) {
        ServiceModel m = model.service(service);
        if (m != null && index >= 0 && index < m.tables().size()) {
            m.removeTable(index);
            model.fire(ClientModel.Kind.TABLES, service);
        }
    }

    /** Empties a service's reply area. Call on the UI thread. */
    public void clearTranscript(String service) {
        ServiceModel m = model.service(service);
        if (m != null) {
            m.clearTranscript();
            model.fire(ClientModel.Kind.COM, service);
        }
    }

    /** Forgets finished transfers. Call on the UI thread. */
    public void clearFinishedTransfers() {
        model.clearFinishedTransfers();
    }

    /**
     * Uploads a file from this computer to the server's upload directory under its own name,
     * with progress in the model; cancel with {@link Transfer#cancel()}. Call on the UI thread.
     */
    public Transfer upload(Path local) {
        String name = local.getFileName() == null ? local.toString() : local.getFileName().toString();
        Transfer t = new Transfer(transferIds.incrementAndGet(), Transfer.Direction.UPLOAD, name, local, -1);
        model.addTransfer(t);
        io.execute(() -> {
            ClientSocketHandler h = conn;
            try {
                if (h == null) {
                    throw new IOException("not connected to a server");
                }
                long total = Files.size(local);
                ui.execute(() -> {
                    t.progress(0, total);
                    model.transferChanged(t);
                });
                h.upload(local, name, (done, all) -> {
                    ui.execute(() -> {
                        t.progress(done, all);
                        model.transferChanged(t);
                    });
                    return !t.cancelRequested();
                });
                finish(t, Transfer.State.DONE, "uploaded " + name + " to the server's upload directory");
                background("?ulfiles");
            } catch (RipvErrorException e) {
                finish(t, Transfer.State.FAILED, "upload of " + name + " refused: " + describe(e));
            } catch (IOException | RuntimeException e) {
                finish(t, t.cancelRequested() ? Transfer.State.CANCELLED : Transfer.State.FAILED,
                        (t.cancelRequested() ? "upload of " + name + " cancelled" : "upload of " + name
                                + " failed: " + describe(e)));
            }
        });
        return t;
    }

    /**
     * Downloads a file from the server's download directory into {@code localDir}, through a
     * temporary file (a cancelled or failed download leaves nothing). Call on the UI thread.
     */
    public Transfer download(String name, Path localDir) {
        Transfer t = new Transfer(transferIds.incrementAndGet(), Transfer.Direction.DOWNLOAD, name, localDir, -1);
        model.addTransfer(t);
        io.execute(() -> {
            ClientSocketHandler h = conn;
            try {
                if (h == null) {
                    throw new IOException("not connected to a server");
                }
                Path saved = h.download(name, localDir, (done, all) -> {
                    ui.execute(() -> {
                        t.progress(done, all);
                        model.transferChanged(t);
                    });
                    return !t.cancelRequested();
                });
                finish(t, Transfer.State.DONE, "downloaded " + name + " to " + saved);
            } catch (RipvErrorException e) {
                finish(t, Transfer.State.FAILED, "download of " + name + " refused: " + describe(e));
            } catch (IOException | RuntimeException e) {
                finish(t, t.cancelRequested() ? Transfer.State.CANCELLED : Transfer.State.FAILED,
                        t.cancelRequested() ? "download of " + name + " cancelled" : "download of " + name
                                + " failed: " + describe(e));
            }
        });
        return t;
    }

    private void finish(Transfer t, Transfer.State state, String text) {
        if (state == Transfer.State.FAILED) {
            log.warn(text);
        } else {
            log.info(text);
        }
        ui.execute(() -> {
            t.finish(state, text);
            model.transferChanged(t);
            model.notice(text, state == Transfer.State.FAILED);
        });
    }

    /** Writes bytes to a file off the UI thread (DAB export, DAV save); the outcome is a notice. */
    public void save(Path file, byte[] bytes) {
        io.execute(() -> {
            try {
                Path tmp = Files.createTempFile(file.toAbsolutePath().getParent(), ".ripv-", ".part");
                try {
                    Files.write(tmp, bytes);
                    Files.move(tmp, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING,
                            java.nio.file.StandardCopyOption.ATOMIC_MOVE);
                } finally {
                    Files.deleteIfExists(tmp);
                }
                showNotice("saved " + file, false);
            } catch (IOException | RuntimeException e) {
                showNotice("could not save " + file + ": " + describe(e), true);
            }
        });
    }

    /** Sends off the UI thread; a send that fails is reported where the operator looks. */
    private void send(String mailbox, String body, Priority priority, Origin origin) {
        io.execute(() -> {
            ClientSocketHandler h = conn;
            if (h == null) {
                failed(origin, body, "not connected to a server");
                return;
            }
            Header header = Header.request(h.nextId(), mailbox, body, priority);
            if (origin != null) {
                origins.put(header.messageId(), origin); // before sending: the reply may beat us back
            }
            try {
                h.send(header, null).whenComplete((reply, e) -> {
                    if (e != null) {
                        origins.remove(header.messageId());
                        failed(origin, body, describe(e));
                    }
                });
            } catch (IOException | RuntimeException e) {
                origins.remove(header.messageId());
                failed(origin, body, describe(e));
            }
        });
    }

    private void failed(Origin origin, String body, String why) {
        log.debug("'{}' failed: {}", body, why);
        if (origin != null && origin.echo()) {
            showReply(origin.service(), LineKind.ERROR, "'" + body + "' got no reply: " + why);
        }
    }

    // ---------------------------------------------------------------- dispatch

    /**
     * Routes one reply to the model by its Footer's SID or FID (Appendix B). Safe on any thread;
     * decoding (images) happens here, the model change on the UI executor.
     */
    public void dispatch(OutgoingServerMessage reply) {
        Footer f = reply.footer();
        Header h = reply.header();
        Origin origin = f.status().isFinal() ? origins.remove(h.messageId()) : origins.get(h.messageId());
        String originService = origin == null ? null : origin.service();
        boolean echo = origin != null && origin.echo();
        Result result = f.result();
        if (f.status() == Status.ERROR) {
            error(reply, origin);
            if (h.isServerCommand()) {
                showProgress(serviceOf(h, originService), null);
            } else {
                afterServiceReply(reply, originService);
            }
            return;
        }
        switch (f.serviceId()) {
            case Ids.FID_SERVICES -> {
                if (result instanceof ServiceList list) {
                    showServices(list.services());
                }
            }
            case Ids.FID_MAILBOXES -> {
                if (result instanceof MailboxList list) {
                    showMailboxes(list.mailboxes());
                }
            }
            case Ids.FID_STATUS -> {
                if (result instanceof MailboxStatus s) {
                    showMailboxStatus(s);
                }
            }
            case Ids.FID_LOCK, Ids.FID_UNLOCK -> {
                if (result instanceof MailboxStatus s) {
                    showMailboxStatus(s);
                } else {
                    // The lock changed: ask for the MailBox's status so SS and the MAM node show it.
                    String[] w = h.body().strip().split("\\s+");
                    if (w.length >= 2) {
                        send("", "?status " + w[1], Priority.NORMAL, new Origin(originService, false));
                    }
                }
            }
            case Ids.FID_ULDIR -> showDirectory(FileArea.UPLOAD, f.replyText().strip());
            case Ids.FID_DLDIR -> showDirectory(FileArea.DOWNLOAD, f.replyText().strip());
            case Ids.FID_ULFILES -> {
                if (result instanceof FileListing l) {
                    showFiles(FileArea.UPLOAD, l);
                }
            }
            case Ids.FID_DLFILES -> {
                if (result instanceof FileListing l) {
                    showFiles(FileArea.DOWNLOAD, l);
                }
            }
            case Ids.FID_LOGIN, Ids.FID_WHOAMI -> {
                if (result instanceof SessionInfo s) {
                    showSession(s);
                }
            }
            case Ids.FID_UPLOAD, Ids.FID_DOWNLOAD -> {
                // Chunks of the client's own transfers: their progress goes through the Transfer.
                return;
            }
            case Ids.SID_DATABASE -> {
                database(reply, serviceOf(h, originService));
                afterServiceReply(reply, originService);
                return;
            }
            case Ids.SID_DATAVIS -> {
                datavis(reply, serviceOf(h, originService));
                afterServiceReply(reply, originService);
                return;
            }
            case Ids.SID_SERIAL -> {
                serial(reply, serviceOf(h, originService));
                afterServiceReply(reply, originService);
                return;
            }
            default -> {
                if (!h.isServerCommand()) {
                    other(reply, serviceOf(h, originService));
                    afterServiceReply(reply, originService);
                    return;
                }
            }
        }
        // A server command typed in a COM panel: its text goes to that panel too.
        if (echo && f.status().isFinal()) {
            showReply(originService, LineKind.REPLY, serverText(reply));
        }
    }

    /**
     * After a service's final reply: the progress bar goes, and the MailBox's status is asked
     * again, since a command may have changed it (GO submerges a glider, a plot counts).
     */
    private void afterServiceReply(OutgoingServerMessage reply, String originService) {
        if (!reply.status().isFinal()) {
            return;
        }
        String service = serviceOf(reply.header(), originService);
        showProgress(service, null);
        String mailbox = reply.header().mailboxAddress();
        if (!mailbox.isBlank() && service != null) {
            send("", "?status " + mailbox, Priority.NORMAL, new Origin(service, false));
        }
    }

    private void error(OutgoingServerMessage reply, Origin origin) {
        Footer f = reply.footer();
        String text = f.replyText().isBlank() ? "the server answered ERROR without a reason" : f.replyText();
        String full = text + " [" + f.errorCode() + " " + f.errorCode().number() + "]";
        String service = serviceOf(reply.header(), origin == null ? null : origin.service());
        log.info("error reply to '{}': {}", reply.header().body(), full);
        if (service != null) {
            showReply(service, LineKind.ERROR, full);
        } else {
            // A background request (refresh, status): the status bar is where it shows.
            showNotice("'" + reply.header().body() + "': " + full, true);
        }
    }

    private void database(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        if (f.result() instanceof TableResult t) {
            showTable(service, t);
            showReply(service, LineKind.REPLY, f.replyText().isBlank()
                    ? t.rows().size() + " row(s)" + (t.truncated() ? ", truncated" : "") : f.replyText());
        } else if (f.result() instanceof UpdateCount u) {
            showReply(service, LineKind.REPLY, f.replyText().isBlank() ? u.count() + " row(s) changed" : f.replyText());
        } else {
            other(reply, service);
        }
    }

    private void datavis(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        if (f.result() instanceof ImageResult img) {
            BufferedImage decoded = decode(img);
            showImage(service, img, decoded);
            showReply(service, LineKind.REPLY, f.replyText().isBlank() ? "plot " + img.name() : f.replyText());
            // The server stored the JPEG in its download directory as well.
            background("?dlfiles");
        } else {
            other(reply, service);
        }
    }

    private void serial(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        if (f.status() == Status.PROGRESS) {
            other(reply, service);
            return;
        }
        showProgress(service, null);
        if (f.result() instanceof FileListing l) {
            // After ymodem:get the server stored the files and lists what it stored.
            StringBuilder b = new StringBuilder(f.replyText().isBlank() ? "stored in the download directory:" : f.replyText());
            for (FileListing.Entry e : l.files()) {
                b.append("\n  ").append(e.name()).append("  ").append(e.size()).append(" bytes");
            }
            showReply(service, LineKind.REPLY, b.toString());
            background("?dlfiles");
        } else {
            showReply(service, LineKind.REPLY, f.replyText());
        }
    }

    /** Any service's reply, by its result's type (new services work without GUI changes). */
    private void other(OutgoingServerMessage reply, String service) {
        Footer f = reply.footer();
        Result result = f.result();
        if (f.status() == Status.PROGRESS) {
            if (result instanceof Progress p) {
                showProgress(service, p);
            }
            if (!f.replyText().isBlank() && !(result instanceof Progress)) {
                showReply(service, LineKind.PROGRESS, f.replyText());
            }
            return;
        }
        showProgress(service, null);
        if (result instanceof TableResult t) {
            showTable(service, t);
        } else if (result instanceof ImageResult img) {
            showImage(service, img, decode(img));
        }
        showReply(service, LineKind.REPLY, f.replyText().isBlank() && result != null
                ? result.getClass().getSimpleName() : f.replyText());
    }

    private static String serverText(OutgoingServerMessage reply) {
        Footer f = reply.footer();
        StringBuilder b = new StringBuilder(f.replyText());
        if (f.result() instanceof FileListing l && !f.replyText().contains("\n")) {
            for (FileListing.Entry e : l.files()) {
                b.append("\n  ").append(e.name()).append("  ").append(e.size()).append(" bytes");
            }
        } else if (f.result() instanceof ServiceList l && f.replyText().isBlank()) {
            l.services().forEach(d -> b.append(d.name()).append("  ").append(d.description()).append('\n'));
        } else if (f.result() instanceof MailboxList l && f.replyText().isBlank()) {
            l.mailboxes().forEach(m -> b.append(m.address()).append("  ").append(ServiceModel.describe(m)).append('\n'));
        } else if (f.result() instanceof MailboxStatus s && f.replyText().isBlank()) {
            b.append(s.address()).append("  ").append(ServiceModel.describe(s));
        }
        return b.length() == 0 ? "OK" : b.toString();
    }

    /** The service a reply belongs to: its destination, its mailbox's service, or where it was sent from. */
    static String serviceOf(Header h, String fallback) {
        if (!h.serviceDestination().isBlank()) {
            return h.serviceDestination();
        }
        if (!h.mailboxAddress().isBlank()) {
            try {
                return MailboxAddress.parse(h.mailboxAddress()).service().toString();
            } catch (MalformedNameException e) {
                return fallback;
            }
        }
        return fallback;
    }

    private static BufferedImage decode(ImageResult img) {
        try {
            return ImageIO.read(new ByteArrayInputStream(img.jpeg()));
        } catch (IOException | RuntimeException e) {
            log.warn("{} does not decode as an image: {}", img.name(), e.toString());
            return null;
        }
    }

    private static String describe(Throwable e) {
        Throwable t = e;
        while ((t instanceof java.util.concurrent.CompletionException
                || t instanceof java.util.concurrent.ExecutionException) && t.getCause() != null) {
            t = t.getCause();
        }
        String m = t.getMessage();
        if (t instanceof java.net.ConnectException) {
            return "connection refused" + (m == null ? "" : " (" + m + ")");
        }
        if (t instanceof java.net.UnknownHostException) {
            return "unknown host " + m;
        }
        return m == null || m.isBlank() ? t.getClass().getSimpleName() : m;
    }

    // ---------------------------------------------------------------- GuiInterface: model changes on the UI executor

    @Override
    public void showServices(List<ServiceDescriptor> services) {
        ui.execute(() -> {
            if (model.services(services)) {
                // A new service: its MailBoxes now, not at the next periodic refresh.
                background("?mailboxes");
            }
        });
    }

    @Override
    public void showMailboxes(List<MailboxStatus> mailboxes) {
        ui.execute(() -> {
            for (ServiceModel s : model.services()) {
                List<MailboxStatus> mine = mailboxes.stream().filter(m -> belongsTo(m.address(), s.name())).toList();
                boolean pickFirst = s.target().isEmpty() && !mine.isEmpty();
                if (!mine.equals(s.mailboxes())) {
                    s.mailboxes(mine);
                    model.fire(ClientModel.Kind.MAILBOXES, s.name());
                    model.fire(ClientModel.Kind.COM, s.name());
                }
                if (pickFirst) {
                    // One obvious target saves a click; the MAM tree still shows the choice.
                    selectMailbox(s.name(), mine.get(0).address());
                }
            }
        });
    }

    @Override
    public void showMailboxStatus(MailboxStatus status) {
        ui.execute(() -> {
            for (ServiceModel s : model.services()) {
                if (belongsTo(status.address(), s.name())) {
                    s.status(status);
                    model.fire(ClientModel.Kind.MAILBOXES, s.name());
                    model.fire(ClientModel.Kind.COM, s.name());
                }
            }
        });
    }

    private static boolean belongsTo(String mailbox, String service) {
        return mailbox.startsWith(service) && mailbox.length() > service.length();
    }

    @Override
    public void showDirectory(FileArea area, String path) {
        ui.execute(() -> model.directory(area, path));
    }

    @Override
    public void showFiles(FileArea area, FileListing listing) {
        ui.execute(() -> model.files(area, listing));
    }

    @Override
    public void showSession(SessionInfo session) {
        ui.execute(() -> model.session(session));
    }

    @Override
    public void showReply(String service, LineKind kind, String text) {
        ui.execute(() -> {
            ServiceModel m = service == null ? null : model.service(service);
            if (m == null) {
                // The service vanished meanwhile (or never registered): say it in the status bar.
                model.notice((service == null ? "" : service + ": ") + text, kind == LineKind.ERROR);
                return;
            }
            m.append(kind, text);
            model.fire(ClientModel.Kind.COM, service);
            if (kind == LineKind.ERROR) {
                model.notice(service + ": " + text, true);
            }
        });
    }

    @Override
    public void showProgress(String service, Progress progress) {
        if (service == null) {
            return;
        }
        ui.execute(() -> {
            ServiceModel m = model.service(service);
            if (m != null && !Objects.equals(m.progress(), progress)) {
                m.progress(progress);
                model.fire(ClientModel.Kind.COM, service);
            }
        });
    }

    @Override
    public void showTable(String service, TableResult table) {
        ui.execute(() -> {
            ServiceModel m = service == null ? null : model.service(service);
            if (m != null) {
                m.addTable(table);
                model.fire(ClientModel.Kind.TABLES, service);
            }
        });
    }

    @Override
    public void showImage(String service, ImageResult image, BufferedImage decoded) {
        ui.execute(() -> {
            ServiceModel m = service == null ? null : model.service(service);
            if (m != null) {
                m.picture(new ServiceModel.Picture(image, decoded));
                model.fire(ClientModel.Kind.IMAGE, service);
            }
        });
    }

    @Override
    public void showNotice(String text, boolean error) {
        ui.execute(() -> model.notice(text, error));
    }

    @Override
    public void showConnection(Connection state, String detail) {
        ui.execute(() -> {
            model.connection(state, detail, null);
            model.notice(detail, state == Connection.LOST || state == Connection.DISCONNECTED);
        });
    }

    // ---------------------------------------------------------------- lifecycle

    /** Closes the connection and stops the manager's threads. */
    @Override
    public void close() {
        closed = true;
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
        timer.shutdownNow();
        io.shutdownNow();
    }
}
