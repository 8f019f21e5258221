package org.ripv.service;

import java.rmi.NotBoundException;
import java.rmi.RemoteException;
import java.rmi.registry.LocateRegistry;
import java.rmi.registry.Registry;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.rmi.RmiSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps a {@link RIPVService} registered with a RIPVServer over RMI: exports the service, looks
 * the server up, registers with the secret, checks in every heartbeat, and registers again
 * whenever the server has gone away and come back — no restart by hand.
 */
public final class ServiceConnector implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(ServiceConnector.class);

    private final RIPVService service;
    private final ServiceOptions options;
    private final Remote remote = new Remote();
    private final GenericRMIInterface stub;
    private final ScheduledExecutorService timer;
    private volatile GenericRMIInterface server;
    private volatile String token;
    private volatile CountDownLatch registered = new CountDownLatch(1);
    private volatile boolean warnedAway;
    /** Guards the window in which the server knows the new token and this side does not yet. */
    private final Object tokenLock = new Object();
    private boolean registering;
    private final java.util.concurrent.CompletableFuture<String> fatal = new java.util.concurrent.CompletableFuture<>();

    private ServiceConnector(RIPVService service, ServiceOptions options) throws RemoteException {
        this.service = service;
        this.options = options;
        this.stub = RmiSupport.export(remote, options.exportPort());
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
        RmiSupport.configure(10_000, 30_000);
        service.start();
        ServiceConnector c = new ServiceConnector(service, options);
        service.replyTo(c.new Sink());
        c.timer.execute(c::tick);
        c.timer.scheduleWithFixedDelay(c::tick, options.heartbeat().toMillis(), options.heartbeat().toMillis(),
                TimeUnit.MILLISECONDS);
        return c;
    }

    /** Waits until the service is registered; false when the time ran out. */
    public boolean awaitRegistered(Duration timeout) throws InterruptedException {
        return registered.await(timeout.toMillis(), TimeUnit.MILLISECONDS);
    }

    /**
     * Blocks until the connector has given up for good (the server refused the secret), and
     * returns why. A launcher calls this after {@link #connect} to serve until then.
     */
    public String awaitFailure() throws InterruptedException {
        try {
            return fatal.get();
        } catch (java.util.concurrent.ExecutionException e) {
            return e.getCause().toString();
        }
    }

    public boolean isRegistered() {
        return token != null;
    }

    private void tick() {
        try {
            String t = token;
            if (t != null && server.heartbeat(t)) {
                return;
            }
            if (t != null) {
                log.info("{}: the server no longer knows this service; registering again", service.name());
                lost();
            }
            register();
        } catch (RemoteException | NotBoundException e) {
            if (token != null) {
                log.warn("{}: lost the server at {}:{} ({}); will register again when it is back", service.name(),
                        options.serverHost(), options.registryPort(), e.getClass().getSimpleName());
                lost();
            } else if (!warnedAway) {
                warnedAway = true;
                log.warn("{}: no RIPVServer at {}:{} yet ({}); retrying every {} s", service.name(), options.serverHost(),
                        options.registryPort(), e.getMessage(), options.heartbeat().toSeconds());
            }
        } catch (SecurityException e) {
            // Retrying cannot fix a wrong secret: stop and let the launcher say so.
            log.error("{}: the server refused registration: {}", service.name(), e.getMessage());
            fatal.complete("the server at " + options.serverHost() + ":" + options.registryPort()
                    + " refused the registration: " + e.getMessage());
            timer.shutdown();
        } catch (RuntimeException e) {
            log.error("{}: heartbeat failed", service.name(), e);
        }
    }

    private void lost() {
        token = null;
        if (registered.getCount() == 0) {
            registered = new CountDownLatch(1);
        }
    }

    private void register() throws RemoteException, NotBoundException {
        Registry registry = LocateRegistry.getRegistry(options.serverHost(), options.registryPort());
        GenericRMIInterface s = (GenericRMIInterface) registry.lookup(GenericRMIInterface.BINDING);
        ServiceDescriptor d = service.descriptor();
        String t;
        synchronized (tokenLock) {
            registering = true;
        }
        try {
            t = s.register(d, stub, options.secret());
        } finally {
            synchronized (tokenLock) {
                registering = false;
                tokenLock.notifyAll();
            }
        }
        server = s;
        synchronized (tokenLock) {
            token = t;
        }
        warnedAway = false;
        registered.countDown();
        log.info("{} registered with the RIPVServer at {}:{}", d.name(), options.serverHost(), options.registryPort());
    }

    /** Sends replies to the server over RMI. */
    private final class Sink implements ReplySink {
        @Override
        public void reply(OutgoingServiceMessage reply) throws Exception {
            server().serviceReply(token(), reply);
        }

        @Override
        public void replies(List<OutgoingServiceMessage> replies) throws Exception {
            server().serviceReplies(token(), replies);
        }

        @Override
        public void console(List<ConsoleEntry> entries) throws Exception {
            server().console(token(), entries);
        }

        private GenericRMIInterface server() throws RemoteException {
            GenericRMIInterface s = server;
            if (s == null || token == null) {
                throw new RemoteException("not registered with a server");
            }
            return s;
        }

        private String token() throws RemoteException {
            String t = token;
            if (t == null) {
                throw new RemoteException("not registered with a server");
            }
            return t;
        }
    }

    /** Stops checking in and withdraws the service's RMI object. The service itself keeps running. */
    @Override
    public void close() {
        fatal.complete("closed");
        timer.shutdownNow();
        RmiSupport.unexport(remote);
        token = null;
    }

    /** The service's side of {@link GenericRMIInterface}. */
    private final class Remote implements GenericRMIInterface {
        private void check(String t) throws RemoteException {
            synchronized (tokenLock) {
                // The server may call as soon as it has registered us, before register() returned here.
                long end = System.nanoTime() + 5_000_000_000L;
                while (registering && (token == null || !token.equals(t)) && System.nanoTime() < end) {
                    try {
                        tokenLock.wait(100);
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        break;
                    }
                }
                if (token == null || !token.equals(t)) {
                    throw new RemoteException("unknown session token: register first");
                }
            }
        }

        @Override
        public void serviceRequest(String t, IncomingServiceMessage request) throws RemoteException {
            check(t);
            service.accept(request);
        }

        @Override
        public void serviceRequests(String t, List<IncomingServiceMessage> requests) throws RemoteException {
            check(t);
            requests.forEach(service::accept);
        }

        @Override
        public boolean withdraw(String t, String mailbox, String clientId, long messageId) throws RemoteException {
            check(t);
            return service.withdraw(mailbox, clientId, messageId);
        }

        @Override
        public boolean cancel(String t, String mailbox, String clientId, long messageId) throws RemoteException {
            check(t);
            return service.cancel(mailbox, clientId, messageId);
        }

        @Override
        public List<MailboxStatus> mailboxes(String t) throws RemoteException {
            check(t);
            return service.mailboxes();
        }

        @Override
        public String register(ServiceDescriptor d, GenericRMIInterface s, String secret) {
            throw new UnsupportedOperationException("a service does not take registrations");
        }

        @Override
        public void serviceReply(String t, OutgoingServiceMessage reply) {
            throw new UnsupportedOperationException("a service does not take replies");
        }

        @Override
        public void serviceReplies(String t, List<OutgoingServiceMessage> replies) {
            throw new UnsupportedOperationException("a service does not take replies");
        }

        @Override
        public boolean heartbeat(String t) {
            throw new UnsupportedOperationException("a service does not take heartbeats");
        }

        @Override
        public void console(String t, List<ConsoleEntry> entries) {
            throw new UnsupportedOperationException("a service does not take console entries");
        }
    }
}
