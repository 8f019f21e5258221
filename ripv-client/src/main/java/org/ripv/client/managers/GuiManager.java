package org.ripv.client.managers;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.atomic.AtomicInteger;
import javax.swing.SwingUtilities;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.client.managers.ClientModel.Connection;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.ServiceModel.LineKind;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.SessionInfo;
import org.ripv.messages.TableResult;

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
 *
 * <p>Parts. This class is the façade: it applies {@link GuiInterface} calls to the model and
 * hands the rest to package-private collaborators: {@link Session} (log-in, reconnect, periodic
 * refresh), {@link Requests} (sending, and which COM panel a reply belongs to),
 * {@link ReplyDispatcher} (SID/FID dispatch), {@link Transfers} (uploads, downloads, saves),
 * {@link WorkflowActions} (workflow queues), {@link MailboxTargets} (tabs, MailBoxes, targets and
 * the vehicle the window opens on) and {@link ConsoleRouter} (replies, progress, tables, pictures
 * and console lines to the panels that show them).
 *
 * <p>Longer than 400 lines for one job: it is the façade, so each of {@link GuiInterface}'s calls and
 * each operator action has its own short method here, handing the work to the parts above.
 */
public final class GuiManager implements GuiInterface, AutoCloseable {

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

    private final ClientModel model;
    private final Executor ui;
    private final ExecutorService io;
    private final ScheduledExecutorService timer;
    private final Session session;
    private final Requests requests;
    private final ReplyDispatcher dispatcher;
    private final Transfers transfers;
    private final WorkflowActions workflows;
    private final MailboxTargets targets;
    private final ConsoleRouter router;

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
        Objects.requireNonNull(connector, "connector");
        Objects.requireNonNull(timings, "timings");
        this.io = Executors.newCachedThreadPool(named("ripv-gui-io-"));
        this.timer = Executors.newSingleThreadScheduledExecutor(named("ripv-gui-timer"));
        this.session = new Session(model, ui, connector, timings, io, timer, this, this::dispatch, this::refresh,
                this::periodicRefresh);
        this.requests = new Requests(model, io, session::connection, this);
        this.dispatcher = new ReplyDispatcher(this, requests);
        this.transfers = new Transfers(model, ui, io, session::connection, this, requests);
        this.workflows = new WorkflowActions(model.workflows(), ui, io, session::connection);
        this.targets = new MailboxTargets(model, ui, requests);
        this.router = new ConsoleRouter(model, ui, requests, new DesktopNotice(model::notice));
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
        return session.connection();
    }

    // ---------------------------------------------------------------- connecting

    /**
     * Connects and logs in, off the calling thread. The future fails with a
     * {@link RipvErrorException} carrying the server's reason when the log-in is refused, or an
     * {@link IOException} when the server cannot be reached; the model says the same.
     * On success the client refreshes everything and keeps the connection alive from now on.
     */
    public CompletableFuture<SessionInfo> logIn(String host, int port, String user, char[] password) {
        return session.logIn(host, port, user, password);
    }

    /** Logs out and closes the connection; no reconnect. */
    public void logOut() {
        session.logOut();
    }

    // ---------------------------------------------------------------- operator actions

    /** Asks for everything the window shows: services, mailboxes, directories and files. */
    public void refresh() {
        refreshServices();
        refreshFiles();
    }

    /** {@code ?services} and {@code ?mailboxes}: the SEL tree, the tabs and the MAM trees. */
    public void refreshServices() {
        requests.refreshServices();
    }

    /**
     * Every refresh period: services, MailBoxes and the two file lists, so that the FIM tree shows
     * files other operators and services added.
     */
    void periodicRefresh() {
        refreshServices();
        refreshFileLists();
    }

    /** {@code ?ulfiles ?dlfiles}: the FIM trees' files (the window asks when it gets the focus back). */
    public void refreshFileLists() {
        requests.background("?ulfiles");
        requests.background("?dlfiles");
    }

    /** {@code ?uldir ?dldir ?ulfiles ?dlfiles}: the FIM FileTree. */
    public void refreshFiles() {
        requests.refreshFiles();
    }

    /**
     * Sends what the operator typed in a service's COM panel: {@code ?...} to the server, anything
     * else to the service's target MailBox with the panel's priority. Call on the UI thread.
     */
    public void sendCommand(String service, String line) {
        requests.sendCommand(service, line);
    }

    /** Makes a MailBox the service's target (TT) and asks for its status (SS). Call on the UI thread. */
    public void selectMailbox(String service, String mailbox) {
        requests.selectMailbox(service, mailbox);
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
        return transfers.upload(local, ClientSocketHandler.IfExists.ASK);
    }

    /**
     * Uploads again after the server said the name is taken ({@link Transfer#nameTaken()}):
     * {@code REPLACE} the stored file (with the right to) or {@code KEEP} both. Call on the UI thread.
     */
    public Transfer upload(Path local, ClientSocketHandler.IfExists ifExists) {
        return transfers.upload(local, ifExists);
    }

    /**
     * Deletes a file of the server's stores ({@code ?delete NAME}, with rights); the server's answer
     * shows in the status bar and the file lists are asked again. Call on the UI thread.
     */
    public void deleteFile(String name) {
        requests.serverAction("?delete " + name, this::refreshFiles);
    }

    /**
     * Downloads a file from the server's download directory into {@code localDir}, through a
     * temporary file (a cancelled or failed download leaves nothing). Call on the UI thread.
     */
    public Transfer download(String name, Path localDir) {
        return transfers.download(name, localDir);
    }

    /**
     * Sends a request whose final reply goes to the returned future only, not to the panels (the
     * Fleet view's queries to the DatabaseServer: no DAB tab opens for them). Any thread.
     */
    public CompletableFuture<OutgoingServerMessage> ask(String mailbox, String body) {
        return requests.ask(mailbox, body);
    }

    /** Writes bytes to a file off the UI thread (DAB export, DAV save); the outcome is a notice. */
    public void save(Path file, byte[] bytes) {
        transfers.save(file, bytes);
    }

    // ---------------------------------------------------------------- workflow queues (docs/workflows.md)

    /** Asks a MailBox's queue ({@code ?queue}) and its last receipts ({@code ?receipts --last N}). Any thread. */
    public void refreshQueue(String mailbox, int lastReceipts) {
        workflows.refresh(mailbox, Math.max(1, Math.min(1000, lastReceipts)));
    }

    /**
     * Uploads a workflow file from this computer and queues it ({@code ?queue add MAILBOX NAME});
     * a refusal names the line and reason in {@link WorkflowModel.Queue#refusals()}. Any thread.
     */
    public void queueFile(String mailbox, Path local, ClientSocketHandler.IfExists ifExists) {
        workflows.addFile(mailbox, local, ifExists);
    }

    /** Uploads a workflow written in the GUI as {@code name} and queues it. Any thread. */
    public void queueText(String mailbox, String name, String text, ClientSocketHandler.IfExists ifExists) {
        workflows.addText(mailbox, name, text, ifExists);
    }

    /** {@code ?queue remove MAILBOX ID}. Any thread. */
    public void unqueue(String mailbox, long id) {
        workflows.remove(mailbox, id);
    }

    /** {@code ?queue clear MAILBOX}. Any thread. */
    public void clearQueue(String mailbox) {
        workflows.clear(mailbox);
    }

    // ---------------------------------------------------------------- dispatch

    /**
     * Routes one reply to the model by its Footer's SID or FID (Appendix B). Safe on any thread;
     * decoding (images) happens here, the model change on the UI executor.
     */
    public void dispatch(OutgoingServerMessage reply) {
        dispatcher.dispatch(reply);
    }

    // ---------------------------------------------------------------- GuiInterface: model changes on the UI executor

    @Override
    public void showServices(List<ServiceDescriptor> services) {
        targets.services(services);
    }

    @Override
    public void showMailboxes(List<MailboxStatus> mailboxes) {
        targets.mailboxes(mailboxes);
    }

    @Override
    public void showMailboxStatus(MailboxStatus status) {
        targets.status(status);
    }

    @Override
    public void showSession(SessionInfo session) {
        targets.session(session);
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
    public void showReply(String service, LineKind kind, String text) {
        router.reply(service, kind, text);
    }

    @Override
    public void showProgress(String service, Progress progress) {
        router.progress(service, progress);
    }

    @Override
    public void requestStarted(String service, long messageId, String command) {
        router.started(service, messageId, command);
    }

    @Override
    public void requestProgress(String service, long messageId, Progress progress) {
        router.progress(service, messageId, progress);
    }

    @Override
    public void requestEnded(String service, long messageId, ErrorCode code) {
        router.ended(service, messageId, code);
    }

    /**
     * Asks the server to stop one of a tab's running requests ({@code ?cancel MESSAGE-ID}): the
     * request shows "cancelling" until its final reply, ERROR {@code CANCELLED}, ends it. When the
     * server refuses (the service cannot stop that command, no rights), the refusal shows in the
     * status bar and the request runs on. Call on the UI thread.
     */
    public void cancel(String service, long messageId) {
        router.cancel(service, messageId);
    }

    @Override
    public void showTable(String service, TableResult table) {
        router.table(service, table);
    }

    @Override
    public void showImage(String service, ImageResult image, BufferedImage decoded) {
        router.image(service, image, decoded);
    }

    /** Fetches older lines of a MailBox's console from the server's transcript. Any thread. */
    public void loadHistory(String mailbox) {
        router.loadHistory(mailbox);
    }

    @Override
    public void showHistory(ConsoleBatch batch) {
        router.history(batch);
    }

    @Override
    public void showConsole(ConsoleBatch batch, boolean live) {
        router.console(batch, live);
    }

    @Override
    public void showNotice(String text, boolean error) {
        router.notice(text, error);
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
        session.close();
        timer.shutdownNow();
        io.shutdownNow();
    }
}
