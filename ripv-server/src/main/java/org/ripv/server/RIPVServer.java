package org.ripv.server;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.StandardSocketOptions;
import java.nio.channels.ServerSocketChannel;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.naming.Handles;
import org.ripv.post.MailBox;
import org.ripv.post.PostOffice;
import org.ripv.rmi.RmiSupport;
import org.ripv.server.clients.ClientAcceptor;
import org.ripv.server.clients.ClientDispatch;
import org.ripv.server.clients.ServerSessions;
import org.ripv.server.clients.WaitingRequests;
import org.ripv.server.clients.WebClients;
import org.ripv.server.commands.ServerCommands;
import org.ripv.server.commands.ServiceQueries;
import org.ripv.server.dataloop.DataLoop;
import org.ripv.server.handout.HandoutTickets;
import org.ripv.server.files.FileStore;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.handlers.WriterPool;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.plans.PlanBridge;
import org.ripv.server.plans.Plans;
import org.ripv.server.remote.OutboundListener;
import org.ripv.server.remote.RmiDoor;
import org.ripv.server.remote.ServerRemote;
import org.ripv.server.requests.InternalCalls;
import org.ripv.server.requests.RequestCancels;
import org.ripv.server.requests.RequestForwarder;
import org.ripv.server.requests.ServiceReplies;
import org.ripv.server.routing.Admission;
import org.ripv.server.routing.ServerTaskManager;
import org.ripv.server.security.StaleLogins;
import org.ripv.server.services.ServiceAdmission;
import org.ripv.server.services.ServiceRegistry;
import org.ripv.server.web.PublicVehicles;
import org.ripv.server.web.WebConsole;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.PermitWatcher;
import org.ripv.server.requests.PendingRequests;
import org.ripv.server.requests.RequestEndings;
import org.ripv.server.security.ServerSecurity;
import org.ripv.server.security.ServerTls;
import org.ripv.server.services.ServiceLiveness;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceSecret;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.workflow.WorkflowBridge;
import org.ripv.server.workflow.Workflows;
import org.ripv.wire.FrameCodec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The central broker (thesis 4.1.1, figure 5.3). Clients connect to its socket port; services
 * register over RMI in the registry it creates. Every request lands in the "RIPV Post Office"
 * MailBox, whose TaskManager either runs a {@code ?} command or forwards the request to the
 * service that owns the addressed MailBox; replies come back through {@code serviceReply} and go
 * out to the client that asked.
 *
 * <pre>{@code
 * RIPVServer server = new RIPVServer(ServerConfig.defaults(Path.of("data")));
 * server.start();          // returns at once; port(), registryPort() are now bound
 * ...
 * server.stop();           // releases threads, ports and files
 * }</pre>
 *
 * <p>Longer than 400 lines for one reason: it is the one place that opens the parts in order,
 * hands each the collaborators it uses and closes them again, and that tells the parts of the
 * events that concern several of them; the parts themselves (the RMI door, the thread pools, the
 * client port, the web console…) live in their own classes.
 */
public final class RIPVServer implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(RIPVServer.class);
    /** The server's one MailBox. */
    public static final String POST_OFFICE = "RIPV Post Office";

    private final ServerConfig config;
    private final SessionOptions sessionOptions;
    private final ServiceRegistry services = new ServiceRegistry();
    private final Map<String, OperatorLock> locks = new ConcurrentHashMap<>();
    private final PostOffice<IncomingServerMessage, OutgoingServerMessage> postOffice = new PostOffice<>(200_000);
    private final Threads threads = new Threads();
    private final ScheduledExecutorService timers = threads.timers;
    private final ExecutorService checkers = threads.checkers;
    /** The threads that write every client's socket. */
    private final WriterPool writers = new WriterPool(timers);
    private final ServiceLiveness serviceLiveness;
    private ServerRemote remote;
    private volatile InternalCalls internalCalls;
    private volatile DataLoop dataLoop;
    private ServiceAdmission admission;
    /** Each client's requests waiting for their final reply, capped (issue 33 item 10). */
    private final WaitingRequests waiting = new WaitingRequests();

    private PermitWatcher permits;
    private FileStore files;
    private String secret;
    private FrameCodec codec;
    private MailBox<IncomingServerMessage, OutgoingServerMessage> box;
    private PendingRequests pending;
    private volatile RequestEndings endings;
    private ServerSocketChannel listener;
    private volatile ClientAcceptor acceptor;
    /** The RMI registry and the server's remote object on the registry port. */
    private RmiDoor rmi;
    private WebConsole landingPage;
    private volatile String mapTiles;
    private volatile String publicNames;
    private ServerSecurity security;
    private ServerTls tls;
    private Workflows workflows;
    /** Plans and their changes (org.ripv.server.plans, docs/plans.md). */
    private Plans plans;
    private OutboundListener outbound;
    private volatile boolean running;
    private ServerSessions sessions;
    private ServerState state;
    private ClientDispatch dispatch;
    private PublicVehicles publicVehicles;

    public RIPVServer(ServerConfig config) {
        this(config, SessionOptions.defaults());
    }

    /** A server with vehicle-session options (transcripts, e-mail, notifications; docs/sessions.md). */
    public RIPVServer(ServerConfig config, SessionOptions sessionOptions) {
        this.config = config;
        this.sessionOptions = sessionOptions;
        this.serviceLiveness = new ServiceLiveness(services, threads.liveness, checkers, timers, config.serviceCheck(), this::drop);
    }

    /** The web console's map tiles ({@code --map-tiles URL}, checked by {@link WebConsole.Options}); set before {@link #start()}. */
    public RIPVServer withMapTiles(String template) {
        this.mapTiles = template;
        return this;
    }

    /** The web console's public view of the vehicles whose names match ({@code --public GLOB}); null: off. Set before {@link #start()}. */
    public RIPVServer withPublicView(String glob) {
        if (glob != null) {
            PublicVehicles.glob(glob); // a bad glob is refused now, not at the first visitor
        }
        this.publicNames = glob;
        return this;
    }

    /** Opens the data directory, the permit file, the RMI registry and the client port. Returns at once. */
    public synchronized void start() throws IOException {
        if (running) {
            return;
        }
        RmiSupport.configure(5_000, 15_000);
        PrivateFiles.createDirectories(config.dataDir());
        PrivateFiles.restrict(config.dataDir()); // the data directory is RIPV's alone (0700)
        state = ServerState.open(config, sessionOptions); // first: an unreachable database leaves nothing open
        permits = new PermitWatcher(config.permitFile());
        Supplier<PermitFile> permitFile = permits::current;
        files = new FileStore(config.dataDir().resolve("upload"), config.dataDir().resolve("download"), config.maxUpload());
        secret = ServiceSecret.loadOrCreate(config.dataDir().resolve("service.secret"));
        codec = new FrameCodec(config.maxFrame());
        pending = new PendingRequests(timers, config.requestTimeout(), this::timedOut);
        endings = new RequestEndings(this::reply, pending, threads.withdrawals, config.requestTimeout());
        // A log-in looks at the file first (one stat): a user just added with ripv passwd can log in
        // at once, not only after the next periodic check.
        security = new ServerSecurity(config.security(), config.maxClients(), timers, () -> {
            permits.reloadIfChanged();
            return permits.current();
        }, () -> secret);
        sessions = new ServerSessions(config.dataDir(), state.store(), sessionOptions, permitFile, this::client, codec);
        sessions.countRepliesIn(waiting);
        ConsoleHub console = sessions.console();
        RequestForwarder forwarder = new RequestForwarder(pending, this::reply);
        RequestCancels cancels = new RequestCancels(pending, services, permitFile, this::reply, this::publishServerEntry);
        workflows = new Workflows(state.store(), new WorkflowBridge(this::deliver, console, this::publishServerEntry, files,
                services, checkers, permitFile, locks, cancels));
        plans = new Plans(new PlanBridge(files, permitFile, this::publishServerEntry, workflows::queueGenerated),
                config.dataDir().resolve("plans"));
        sessions.surfacings().onSurfacing(plans::surfacing); // plans judge changes by the parsed dialogs
        sessions.expireLocks(timers, locks, mailbox -> workflows.lockReleased(mailbox));
        permits.onChange(sessions::permitsChanged);
        internalCalls = new InternalCalls(services, permitFile, files, forwarder);
        dataLoop = new DataLoop(internalCalls, new HandoutTickets(services), config.dataDir().resolve("ingest.properties"));
        admission = new ServiceAdmission(services, serviceLiveness, checkers, this::undeliverable, this::drop, this::serviceOnline);
        remote = new ServerRemote(security.challenges(), admission, services,
                new ServiceReplies(pending, cancels, files, dataLoop, this::reply, this::client), this::console);
        ServiceQueries queries = new ServiceQueries(services, serviceLiveness, checkers, permitFile, locks, console, this::reply);
        Admission admit = new Admission(Admission.steps(services, permitFile, locks, dataLoop, files, this::reply), forwarder);
        ServerCommands commands = new ServerCommands(new ServerCommands.Parts(permitFile, files, services, queries, locks, sessions,
                workflows, plans, cancels, security.throttle(), state.audit(), state.store(), this::client), threads.fileWork, checkers,
                this::reply, admit::route);
        box = postOffice.open(POST_OFFICE, new ServerTaskManager(commands::run, admit, workflows::reply, waiting, this::client,
                this::reply));
        dispatch = new ClientDispatch(security.logins(), commands.commands()::servedBeforeLogin, waiting, this::deliver,
                this::clientClosed);
        publicVehicles = publicNames == null ? null : new PublicVehicles(
                () -> queries.known().thenApply(ServiceQueries.Known::addresses), console, checkers, publicNames);

        InetAddress bind = config.bindAddress() == null ? null : InetAddress.getByName(config.bindAddress());
        try {
            rmi = RmiDoor.open(bind, config.registryPort(), remote);

            tls = ServerTls.resolve(config.tls(), config.security().plain(), config.dataDir().resolve("tls"));
            listener = ServerSocketChannel.open(); // TLS on the selector threads (org.ripv.server.transport)
            listener.setOption(StandardSocketOptions.SO_REUSEADDR, true);
            try {
                listener.bind(new InetSocketAddress(bind, config.port()), 128);
            } catch (IOException e) {
                throw new IOException("cannot listen for clients on port " + config.port() + " (in use?): " + e.getMessage(), e);
            }
        } catch (IOException | RuntimeException e) {
            release();
            throw e;
        }
        try {
            startLandingPage(bind);
        } catch (IOException | RuntimeException e) {
            release();
            throw e;
        }
        running = true;
        acceptor = new ClientAcceptor(listener, tls.context(), timers, codec, writers, dispatch, security.gate());
        // A reload that removes a user, changes a password or roles reaches every open log-in (issue 33 item 4).
        StaleLogins stale = new StaleLogins(permits.current(), acceptor::clients);
        if (landingPage != null) {
            WebConsole web = landingPage;
            stale.onChange(c -> web.usersChanged(c.ended(), c.roles()));
        }
        permits.onChange(stale);
        long check = config.serviceCheck().toMillis();
        timers.scheduleWithFixedDelay(this::checkServices, check, check, TimeUnit.MILLISECONDS);
        log.info("RIPVServer listening for clients on port {}{}, RMI registry on port {}, data in {}", port(),
                tls.label(), rmi.port(), config.dataDir().toAbsolutePath());
    }

    /** The fingerprint of the server's own certificate, or null (plain, or the operator's key store). */
    public String tlsFingerprint() {
        return tls == null ? null : tls.fingerprint();
    }

    /**
     * Opens the port for services in outbound-only mode (NAT, firewalls) on the bind address;
     * 0 picks a free port. Call after {@link #start}; {@link #stop} closes it.
     *
     * @return the port
     */
    public synchronized int openOutbound(int port) throws IOException {
        if (!running) {
            throw new IllegalStateException("start the server first");
        }
        if (outbound == null) {
            InetAddress bind = config.bindAddress() == null ? null : InetAddress.getByName(config.bindAddress());
            outbound = new OutboundListener(secret, services, admission, this::drop, remote, bind, port);
            log.info("services behind NAT may connect out to port {} (--outbound-only)", outbound.port());
        }
        return outbound.port();
    }

    /** Closes every port, thread and export the server may have opened; safe on a half-started server. */
    private void release() {
        if (outbound != null) {
            outbound.close();
            outbound = null;
        }
        if (landingPage != null) {
            try {
                landingPage.close();
            } catch (Exception e) {
                log.debug("landing page close: {}", e.toString());
            }
        }
        if (acceptor != null) {
            acceptor.close(); // the listener, then every client
        } else if (listener != null) {
            try {
                listener.close();
            } catch (IOException ignored) {
                // closing anyway
            }
        }
        writers.close();
        services.closeAll();
        if (rmi != null) {
            rmi.close();
        }
        if (workflows != null) {
            workflows.close();
        }
        if (plans != null) {
            plans.close();
        }
        if (sessions != null) {
            sessions.close();
        }
        if (state != null) {
            state.close();
        }
        threads.close();
        if (security != null) {
            security.close();
        }
        postOffice.stop();
    }

    /** Starts the landing page on the configured HTTP port (-1: none). */
    private void startLandingPage(InetAddress bind) throws IOException {
        if (config.httpPort() < 0) {
            return;
        }
        // The web console (org.ripv.server.web): its pages are Post Office clients through WebClients.
        WebConsole page = new WebConsole(new WebConsole.Options(new InetSocketAddress(bind, config.httpPort()),
                files.uploadDir(), config.maxUpload(), config.clientJar(), this::describe, port(), security.webAccess(),
                config.security().httpUpload(), tls.context(), new WebClients(() -> acceptor), codec, mapTiles));
        // The upload form stores through the FileStore with ?upload's quota and owners (issue 33 item 5).
        page.withPagesPerUser(config.security().webPages()); // issue 33 item 2
        page.withFormUploads((user, parked) -> {
            PermitFile p = permits.current();
            return files.storeWhole(user, parked, p.user(user).map(p::quota).orElse(0L));
        });
        if (publicVehicles != null) {
            page.withPublicView(publicVehicles);
        }
        try {
            page.start();
        } catch (IOException e) {
            throw new IOException("cannot serve the landing page on port " + config.httpPort() + " (in use? --http-port 0 turns it off): "
                    + e.getMessage(), e);
        }
        landingPage = page;
    }

    /**
     * What the landing page tells any visitor: ports, the TLS fingerprint and service names only;
     * no paths, and no service descriptions (a database's names its JDBC URL).
     */
    private String describe() {
        StringBuilder b = new StringBuilder("RIPVServer on " + Handles.localHost() + "\n");
        b.append("Clients connect to port ").append(port()).append(tls.label())
                .append(tls.fingerprint() == null ? "" : "; certificate " + tls.fingerprint()).append('\n');
        List<ServiceReference> list = services.all();
        b.append(list.size()).append(" service(s) registered");
        list.forEach(r -> b.append("\n  ").append(r.descriptor().name()));
        return b.toString();
    }

    /** The landing page's port, or -1 when it is off. */
    public int httpPort() {
        return landingPage == null ? -1 : landingPage.port();
    }

    /** The live console: watchers, vehicle state, transcripts (tests and benchmarks look inside). */
    public ConsoleHub console() {
        return sessions.console();
    }

    // ---- events that concern several parts: the lobby tells each ----

    /** A client's connection closed: it is forgotten everywhere it left state (only that handler: an id may be reused). */
    private void clientClosed(SocketHandler client) {
        ClientAcceptor a = acceptor;
        if (a != null) {
            a.forget(client);
        }
        String id = client.clientId();
        waiting.forget(id);
        security.gate().closed(id);
        pending.forgetClient(id);
        files.abortAll(id);
        if (sessions.clientClosed(id, locks)) {
            workflows.lockReleased(null);
        }
    }

    private Optional<SocketHandler> client(String clientId) {
        ClientAcceptor a = acceptor;
        return a == null ? Optional.empty() : a.client(clientId);
    }

    /** Puts a request into the Post Office (a client's, or a workflow step's); false when it is full. */
    private boolean deliver(IncomingServerMessage request) {
        return box.deliver(request);
    }

    /** Posts a reply for the outbox assistant to deliver. */
    private void reply(OutgoingServerMessage reply) {
        InternalCalls own = internalCalls;
        if (own != null && own.accept(reply)) {
            return; // the server's own request (org.ripv.server.dataloop)
        }
        box.post(reply);
    }

    /** A request that could not be handed to its service: fail it, and check whether the service lives. */
    private void undeliverable(ServiceReference ref, IncomingServiceMessage r, Exception e) {
        endings.undeliverable(ref, r, e);
        serviceLiveness.soon(ref);
    }

    private void timedOut(PendingRequests.Pending p) {
        endings.timedOut(p, services.find(p.service()).orElse(null));
    }

    private void checkServices() {
        serviceLiveness.checkAll();
        rmi.check();
        permits.reloadIfChanged();
    }

    /** A service went away or registered again: its calls end, then its requests. */
    private void drop(ServiceReference ref, String why) {
        // The calls end first, so a workflow step under way is cut (it resumes on the next call)
        // rather than failed by the request ending below.
        String name = ref.descriptor().name();
        List<ConsoleEntry> gone = sessions.console().serviceGone(name, why);
        workflows.onConsole(name, gone);
        plans.onConsole(gone);
        endings.drop(ref, why);
    }

    /**
     * A service that just registered listed its MailBoxes: a new instance cannot carry on a call
     * from before it started, so those calls end; the queued workflows of calls still open run now;
     * download folders from before they were per address move to each MailBox's own.
     */
    private void serviceOnline(String name, long started, List<String> boxes) {
        workflows.onConsole(name, sessions.console().serviceStarted(name, started, boxes));
        workflows.serviceOnline(boxes);
        files.adoptAll(boxes);
    }

    /**
     * A console entry the server itself originates (a workflow's progress line and end, a cancel,
     * a plan change): for watchers, the transcript and notifications, and for the plans that follow changes.
     */
    private void publishServerEntry(ConsoleEntry entry) {
        sessions.console().serverEntry(entry);
        if (plans != null) {
            plans.onConsole(List.of(entry));
        }
    }

    /**
     * Console entries a service published for its MailBoxes (the live console). Only entries for
     * the calling service's own MailBoxes are taken.
     */
    private void console(ServiceReference ref, List<ConsoleEntry> entries) {
        sessions.console().publish(ref.descriptor().name(), entries);
        workflows.onConsole(ref.descriptor().name(), entries);
        plans.onConsole(entries);
        // Answer only once they are stored: the service offers what a server did not take to the
        // next one (restarted, or a standby), so a server that dies now loses no transcript line.
        sessions.console().sync();
    }

    /** The client port (useful with port 0). */
    public int port() {
        return listener.socket().getLocalPort();
    }

    public int registryPort() {
        return rmi.port();
    }

    public Path secretFile() {
        return config.dataDir().resolve("service.secret");
    }

    public FileStore fileStore() {
        return files;
    }

    /** The data loop: what it relayed (tests). */
    public DataLoop dataLoop() {
        return dataLoop;
    }

    /** How many services are registered now. */
    public int serviceCount() {
        return services.size();
    }

    /** Reloads the permit file now (the server also notices changes by itself). */
    public void reloadPermits() throws IOException {
        permits.reload();
    }

    /** Stops listening, disconnects clients, withdraws from RMI. Idempotent. */
    public synchronized void stop() {
        if (!running) {
            return;
        }
        running = false;
        release();
        log.info("RIPVServer stopped");
    }

    @Override
    public void close() {
        stop();
    }
}
