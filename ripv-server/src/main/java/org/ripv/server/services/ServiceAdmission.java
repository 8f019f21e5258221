package org.ripv.server.services;

import java.rmi.RemoteException;
import java.rmi.ServerError;
import java.rmi.ServerException;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.BiConsumer;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.naming.NameTaken;
import org.ripv.naming.ServiceName;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.server.session.ConsoleHub;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Admits a service whose secret has been checked: calls it back first (a service the server
 * cannot reach is refused at once, with the address tried and what to set, instead of being
 * listed and stalling every request), then lists it — unless a newer registration of the same
 * service got there first, which a late one (from an attempt the service gave up on) must never
 * replace, or another running service holds the name: a second process of one name is refused
 * ({@link NameTaken}) while the first answers its heartbeat, and takes over only once it does not.
 */
public final class ServiceAdmission {
    private static final Logger log = LoggerFactory.getLogger(ServiceAdmission.class);
    private static final SecureRandom RANDOM = new SecureRandom();
    /** How long the call-back at registration may take. */
    public static final Duration CALLBACK_DEADLINE =
            Duration.ofMillis(Long.getLong("ripv.service.callbackMillis", 5_000));

    /** What the server does once a service's MailBoxes are known after it registered. */
    @FunctionalInterface
    public interface Arrival {
        /**
         * @param name    the service's full name
         * @param started when the service instance started (its descriptor says)
         * @param boxes   the MailBoxes it lists that no other service claims
         */
        void online(String name, long started, List<String> boxes);
    }

    private final ServiceRegistry registry;
    private final ServiceLiveness liveness;
    private final Executor checkers;
    private final ServiceReference.Failure undeliverable;
    private final BiConsumer<ServiceReference, String> drop;
    private final Arrival arrival;

    /**
     * @param checkers      where the call-back and the MailBox listing run
     * @param undeliverable told of a request whose call to its service failed
     * @param drop          told of a registration replaced by a new one of the same service
     * @param arrival       told of the MailBoxes a newly registered service lists
     */
    public ServiceAdmission(ServiceRegistry registry, ServiceLiveness liveness, Executor checkers,
                            ServiceReference.Failure undeliverable, BiConsumer<ServiceReference, String> drop, Arrival arrival) {
        this.registry = registry;
        this.liveness = liveness;
        this.checkers = checkers;
        this.undeliverable = undeliverable;
        this.drop = drop;
        this.arrival = arrival;
    }

    /**
     * Calls the service back, then registers it.
     *
     * @return the session token
     * @throws IllegalStateException when the service cannot be reached or a newer registration won
     */
    public String admit(ServiceDescriptor d, GenericRMIInterface service) {
        byte[] t = new byte[24];
        RANDOM.nextBytes(t);
        return admit(d, service, HexFormat.of().formatHex(t));
    }

    /** As {@link #admit(ServiceDescriptor, GenericRMIInterface)} with the session token both sides derived. */
    public String admit(ServiceDescriptor d, GenericRMIInterface service, String token) {
        if (d == null || service == null) {
            throw new IllegalArgumentException("a registration needs a descriptor and the service's stub");
        }
        ServiceName.parse(d.name());
        try {
            callBack(d, service, checkers);
        } catch (IllegalStateException e) {
            liveness.refused(d.name(), "cannot call it back at " + ServiceReference.addressOf(service));
            throw e;
        }
        refuseIfHeld(d);
        ServiceReference ref = new ServiceReference(d, service, token, undeliverable, d.registration());
        // a newer registration of this service in force stays
        ServiceRegistry.Replacement r = registry.put(ref,
                (old, young) -> d.registration() != 0 && old.order() > d.registration() ? old : young);
        ServiceReference now = r.now();
        if (now != ref) {
            ref.close();
            log.warn("refused a late registration of {} (attempt of {}; the one in force began at {})", d.name(),
                    d.registration(), now.order());
            throw new IllegalStateException("superseded: a newer registration of " + d.name() + " is in force");
        }
        if (r.replaced() != null) {
            drop.accept(r.replaced(), "registered again");
        }
        liveness.registered(d.name());
        log.info("{} registered from {} ({})", ref, ref.address(), d.description());
        reconcileCalls(ref, d.started());
        return ref.token();
    }

    /**
     * Refuses {@code d} when another instance of a service (another start time) holds its name and
     * still answers; one that does not answer is taken over. The same instance registering again
     * (a heartbeat the server did not know, a restarted server) is not held back.
     */
    private void refuseIfHeld(ServiceDescriptor d) {
        ServiceReference old = registry.find(d.name()).orElse(null);
        if (old == null || d.started() == 0 || old.descriptor().started() == 0 || old.descriptor().started() == d.started()) {
            return;
        }
        try {
            callBack(old.descriptor(), old.stub(), checkers);
        } catch (IllegalStateException gone) {
            log.warn("{}: the service registered at {} no longer answers; the new registration takes over the name",
                    d.name(), old.address());
            return;
        }
        String why = NameTaken.refusal(d.name(), old.address(), old.order(), old.descriptor().started());
        log.warn("refused a second service named {}: {}", d.name(), why);
        liveness.refused(d.name(), "its name is held by the running service at " + old.address());
        throw new IllegalStateException(why);
    }

    /**
     * Squares the calls the server has open with the service that just registered, in the
     * background (the registration does not wait for the service's MailBox list): a new instance
     * cannot carry on a call from before it started (the service and the server restarted
     * together, say), so those calls are lost; the queued workflows of calls still open (a
     * server started again, or a standby that took over, while the service kept running) run now.
     */
    private void reconcileCalls(ServiceReference ref, long started) {
        String name = ref.descriptor().name();
        ref.mailboxes(checkers, CALLBACK_DEADLINE).thenAccept(list -> {
            List<String> boxes = ConsoleHub.claimed(name, list.stream().map(MailboxStatus::address).toList());
            arrival.online(name, started, boxes);
        }).exceptionally(e -> {
            log.info("could not list the MailBoxes of {} to square its calls with it: {}", name, e.toString());
            return null;
        });
    }

    /**
     * Proves the server can call the service: its heartbeat answers (any answer from the service
     * itself will do), within {@link #CALLBACK_DEADLINE} — well inside the service's own wait for
     * the registration to return.
     */
    static void callBack(ServiceDescriptor d, GenericRMIInterface service, Executor pool) {
        String address = ServiceReference.addressOf(service);
        CompletableFuture<Boolean> probe = CompletableFuture.supplyAsync(() -> {
            try {
                return service.heartbeat("probe");
            } catch (RemoteException e) {
                throw new CompletionException(e);
            }
        }, pool);
        try {
            probe.get(CALLBACK_DEADLINE.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            probe.cancel(true);
            throw refused(d, address, "timed out after " + CALLBACK_DEADLINE.toMillis() + " ms");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw refused(d, address, "interrupted");
        } catch (ExecutionException e) {
            Throwable t = e.getCause();
            if (t instanceof ServerException || t instanceof ServerError || t instanceof UnsupportedOperationException
                    || t instanceof SecurityException) {
                return; // the service answered, if only to refuse: it is reachable
            }
            throw refused(d, address, ServiceReference.why(t, address));
        }
    }

    private static IllegalStateException refused(ServiceDescriptor d, String address, String why) {
        log.warn("refused the registration of {}: cannot call it back at {}: {}", d.name(), address, why);
        return new IllegalStateException(refusal(d.name(), address, why));
    }

    /** What the service prints: the address tried and what to set. */
    public static String refusal(String name, String address, String why) {
        String port = address.contains(":") ? address.substring(address.lastIndexOf(':') + 1) : "its export port";
        return "the server could not call " + name + " back at " + address + " (" + why + "). The server must reach the"
                + " service there: set --host to a name or address of this host that the server can reach, fix the port"
                + " with --export-port and open or forward that TCP port (now " + port + ") to this host; or use"
                + " --outbound-only so that the service only connects out to the server (NAT, firewalls)";
    }
}
