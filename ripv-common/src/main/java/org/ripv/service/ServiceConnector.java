package org.ripv.service;

import java.rmi.NotBoundException;
import java.rmi.RemoteException;
import java.rmi.registry.Registry;
import java.rmi.server.RMIServerSocketFactory;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.naming.NameTaken;
import org.ripv.outbound.CallChannel;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.rmi.RmiSupport;
import org.ripv.security.ServiceProof;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps a {@link RIPVService} registered with a RIPVServer over RMI: exports the service, looks
 * the server up, registers by challenge–response over the secret ({@link ServiceProof}; the
 * secret itself never crosses the wire, and an impostor in the registry gets none of it), checks in every heartbeat, and registers again
 * whenever the server has gone away and come back — no restart by hand. Given several servers
 * (an active one and its standbys, {@link ServiceOptions#servers}), it tries them in turn and
 * registers with whichever answers: a standby listens on nothing until it takes over.
 */
public final class ServiceConnector implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(ServiceConnector.class);

    private final RIPVService service;
    private final ServiceOptions options;
    private final ServiceSession session = new ServiceSession();
    private final ServiceRemote remote;
    private final GenericRMIInterface stub;
    private final ScheduledExecutorService timer;
    private volatile boolean warnedAway;
    private volatile boolean warnedImpostor;
    private static final AtomicLong STAMPS = new AtomicLong();
    private volatile Consumer<String> printer = m -> { };
    private volatile String lastNotice;
    private volatile CallChannel channel;
    private final CompletableFuture<String> fatal = new CompletableFuture<>();
    /** Registrations in a row that a retry cannot mend (only the timer thread counts them). */
    private int unmendable;
    /** Which of {@code options.servers()} this service uses (or tries) now. */
    private volatile int current;

    private ServiceConnector(RIPVService service, ServiceOptions options, RMIServerSocketFactory sockets)
            throws RemoteException {
        this.service = service;
        this.options = options;
        this.remote = new ServiceRemote(service, session);
        // Outbound-only: nothing listens here; the server's calls come back over our own connection.
        this.stub = options.outbound() ? null : RmiSupport.export(remote, options.exportPort(), sockets);
        this.timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "ripv-connector-" + service.name());
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Starts the service (if it is not yet), then registers it, retrying in the background until
     * the server answers. Use {@link #awaitRegistered} to wait for the first registration.
     */
    public static ServiceConnector connect(RIPVService service, ServiceOptions options) throws Exception {
        return connect(service, options, null);
    }

    /**
     * As {@link #connect(RIPVService, ServiceOptions)}, with the service's RMI object listening
     * through {@code sockets} (null: RMI's default, all addresses).
     */
    public static ServiceConnector connect(RIPVService service, ServiceOptions options,
                                           RMIServerSocketFactory sockets) throws Exception {
        RmiSupport.configure(10_000, 30_000);
        service.start();
        ServiceConnector c = new ServiceConnector(service, options, sockets);
        service.replyTo(c.session.sink());
        service.peersVia(c.session::peer);
        c.timer.execute(c::tick);
        c.timer.scheduleWithFixedDelay(c::tick, options.heartbeat().toMillis(), options.heartbeat().toMillis(),
                TimeUnit.MILLISECONDS);
        return c;
    }

    /** Waits until the service is registered; false when the time ran out. */
    public boolean awaitRegistered(Duration timeout) throws InterruptedException {
        return session.awaitRegistered(timeout);
    }

    /**
     * Blocks until the connector has given up for good (the server refused the secret), and
     * returns why. A launcher calls this after {@link #connect} to serve until then.
     */
    public String awaitFailure() throws InterruptedException {
        try {
            return fatal.get();
        } catch (ExecutionException e) {
            return e.getCause().toString();
        }
    }

    public boolean isRegistered() {
        return session.isRegistered();
    }

    private void tick() {
        try {
            String t = session.token();
            if (t != null && session.server().heartbeat(t)) {
                return;
            }
            if (t != null) {
                log.info("{}: the server no longer knows this service; registering again", service.name());
                lost();
            }
            registerAny();
        } catch (RemoteException | NotBoundException e) {
            if (session.isRegistered()) {
                log.warn("{}: lost the server at {} ({}); will register again when it{} is back", service.name(),
                        where(), e.getClass().getSimpleName(), options.servers().size() > 1 ? " or another of " + options.servers() : "");
                lost();
                failOver();
            } else if (WrongRegistryPort.notARegistry(e)) {
                unmendable(WrongRegistryPort.explain(host(), registryPort()));
            } else if (!warnedAway) {
                warnedAway = true;
                log.warn("{}: no RIPVServer at {} yet ({}); retrying every {} ms", service.name(),
                        options.servers().size() > 1 ? "any of " + options.servers() : where(), e.getMessage(),
                        options.heartbeat().toMillis());
            }
        } catch (Impostor e) {
            // Someone else holds the name, or the secret is not the server's: say so loudly, and keep
            // trying until the real server is back, or give up when the launcher says so.
            if (unmendable(e.getMessage())) {
                return;
            }
            if (!warnedImpostor) {
                warnedImpostor = true;
                log.error("{}: POSSIBLE IMPOSTOR: {}; sent it no secret and nothing derived from it; retrying every {} ms",
                        service.name(), e.getMessage(), options.heartbeat().toMillis());
            }
            lost();
        } catch (IllegalStateException e) {
            if (NameTaken.is(e.getMessage()) && options.giveUpAfter() > 0) {
                // another running service holds the name: stop rather than contend for it (--retry-forever waits for it to go)
                log.error("{}: the server refused the registration: {}", service.name(), e.getMessage());
                fatal.complete("the server at " + where() + " refused the registration: " + e.getMessage());
                timer.shutdown();
                return;
            }
            // Refused but fixable (the server cannot call back, or a newer attempt won): say so, keep trying.
            notice(e.getMessage());
        } catch (SecurityException e) {
            if (ServiceProof.saysRetry(e.getMessage())) {
                // "register again", "retry": the server is there and will take us; a refusal of this
                // kind never ends the service (issue 23, item 1: a challenge flood made it exit).
                notice(e.getMessage());
                lost();
                return;
            }
            // Retrying cannot fix a wrong secret: stop and let the launcher say so.
            log.error("{}: the server refused registration: {}", service.name(), e.getMessage());
            fatal.complete("the server at " + where() + " refused the registration: " + e.getMessage());
            timer.shutdown();
        } catch (RuntimeException e) {
            log.error("{}: heartbeat failed", service.name(), e);
        }
    }

    /**
     * Counts a registration a retry cannot mend; true when that was the last try ({@link
     * ServiceOptions#giveUpAfter}): the connector has given up with {@code why}.
     */
    private boolean unmendable(String why) {
        int n = ++unmendable;
        int max = options.giveUpAfter();
        if (max > 0 && n >= max) {
            log.error("{}: {}; giving up after {} tries", service.name(), why, n);
            fatal.complete(why + " (gave up after " + n + " tries; --retry-forever keeps trying)");
            timer.shutdown();
            return true;
        }
        notice(why + (max > 0 ? " (try " + n + " of " + max + ")" : ""));
        return false;
    }

    /** After losing the server: try the others at once rather than a heartbeat later (a standby taking over). */
    private void failOver() {
        if (options.servers().size() == 1) {
            return;
        }
        try {
            registerAny();
        } catch (RemoteException | NotBoundException e) {
            log.debug("{}: no server answers yet: {}", service.name(), e.toString());
        }
    }

    /** The server in use now, as HOST:PORT (the outbound port in outbound-only mode). */
    private String where() {
        return host() + ":" + (options.outbound() ? options.outboundPort() : registryPort());
    }

    private String host() {
        return options.servers().get(current).host();
    }

    private int registryPort() {
        return options.servers().get(current).port();
    }

    /**
     * Registers with the server in use, else with each other one in turn; the first that answers
     * becomes the server in use. Only "nobody there" moves on: a refusal comes from a live server.
     */
    private void registerAny() throws RemoteException, NotBoundException {
        int n = options.servers().size();
        int from = current;
        Exception first = null;
        for (int i = 0; i < n; i++) {
            int at = (from + i) % n;
            current = at;
            try {
                register();
                if (at != from) {
                    log.info("{}: {} did not answer ({}); now registered with {}{}", service.name(), options.servers().get(from)
                            .host(), first == null ? "?" : first.getMessage(), where(), options.servers().position(at));
                }
                return;
            } catch (RemoteException | NotBoundException e) {
                if (first == null) {
                    first = e;
                }
            }
        }
        current = from;
        if (first instanceof RemoteException r) {
            throw r;
        }
        throw (NotBoundException) first;
    }

    /** Where refusals the service can fix are printed besides the log (a launcher's standard error). */
    public void onNotice(Consumer<String> printer) {
        this.printer = printer == null ? m -> { } : printer;
        String last = lastNotice;
        if (last != null) {
            this.printer.accept("Error: registration refused: " + last);
        }
    }

    private void notice(String message) {
        if (!message.equals(lastNotice)) {
            lastNotice = message;
            log.error("{}: registration refused: {}; retrying every {} ms", service.name(), message, options.heartbeat().toMillis());
            printer.accept("Error: registration refused: " + message + " (retrying every " + options.heartbeat().toMillis() + " ms)");
        }
    }

    /** This process's registration attempts, strictly increasing (see ServiceDescriptor#registration). */
    private static long nextStamp() {
        return STAMPS.updateAndGet(last -> Math.max(last + 1, System.currentTimeMillis()));
    }

    private void lost() {
        session.lost();
    }

    private void register() throws RemoteException, NotBoundException {
        GenericRMIInterface s;
        if (options.outbound()) {
            s = openChannel();
        } else {
            Registry registry = RmiSupport.registry(host(), registryPort());
            s = (GenericRMIInterface) registry.lookup(GenericRMIInterface.BINDING);
        }
        ServiceDescriptor d = service.descriptor().withRegistration(nextStamp());
        String secret = options.secret();
        String mine = ServiceProof.nonce();
        String[] answer = null;
        if (!options.outbound()) {
            // The server proves it holds the secret before anything derived from it goes out.
            answer = answer(s.challenge(mine));
            if (answer == null || !ServiceProof.same(answer[1], ServiceProof.serverProof(secret, mine, answer[0]))) {
                throw new Impostor("the server at " + host() + ":" + registryPort() + " cannot prove it holds the service secret:"
                        + " this service's secret is wrong (--secret-file must be that server's DATA/service.secret),"
                        + " or the object bound as '" + GenericRMIInterface.BINDING + "' in its registry is an impostor");
            }
        }
        String t = null;
        session.registering();
        try {
            if (options.outbound()) {
                // Over an outbound connection the handshake has proven the secret both ways: it is never sent.
                t = s.register(d, stub, "");
            } else {
                String confirmation = s.register(d, stub,
                        answer[0] + " " + mine + " " + ServiceProof.serviceProof(secret, mine, answer[0], d.name(), stub));
                if (!ServiceProof.same(confirmation, ServiceProof.serverProof(secret, answer[0], mine))) {
                    throw new Impostor("the server at " + host() + ":" + registryPort()
                            + " accepted the registration without proving it holds the service secret");
                }
                t = ServiceProof.token(secret, mine, answer[0]);
            }
        } finally {
            session.registered(s, t);
        }
        warnedAway = false;
        warnedImpostor = false;
        unmendable = 0;
        lastNotice = null;
        log.info("{} registered with the RIPVServer at {}{}{}", d.name(), where(), options.servers().position(current),
                options.outbound() ? " (outbound only)" : "");
    }

    /**
     * Opens the outbound connection: TCP to the server's outbound port within the connect
     * deadline, the HMAC handshake, then calls both ways over it. Losing it means losing the
     * server: the next heartbeat connects and registers again.
     */
    private GenericRMIInterface openChannel() throws RemoteException {
        CallChannel old = channel;
        if (old != null) {
            old.close();
        }
        String where = host() + ":" + options.outboundPort();
        CallChannel c = OutboundDial.open(host(), options.outboundPort(), options.secret(), service.descriptor().name(), remote);
        c.closed().thenAccept(why -> {
            if (session.isRegistered() && session.server() == c.remote() && !fatal.isDone()) {
                log.warn("{}: the outbound connection to {} closed ({}); connecting again", service.name(), where, why);
                lost();
            }
        });
        channel = c;
        return c.remote();
    }

    private static String[] answer(String a) {
        String[] w = a == null ? new String[0] : a.split(" ");
        return w.length == 2 && ServiceProof.isNonce(w[0]) ? w : null;
    }

    /** The object in the registry is not the RIPVServer: nothing was sent to it but a nonce. */
    private static final class Impostor extends RuntimeException {
        private static final long serialVersionUID = 1L;

        Impostor(String message) {
            super(message);
        }
    }

    /** Stops checking in and withdraws the service's RMI object. The service itself keeps running. */
    @Override
    public void close() {
        fatal.complete("closed");
        timer.shutdownNow();
        CallChannel c = channel;
        if (c != null) {
            c.close();
        }
        if (stub != null) {
            RmiSupport.unexport(remote);
        }
        session.lost();
    }
}
