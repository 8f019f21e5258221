package org.ripv.server.handout;

import java.lang.reflect.Proxy;
import java.rmi.server.RemoteObject;
import java.rmi.server.RemoteObjectInvocationHandler;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.LongSupplier;
import org.ripv.handout.HandoutCollector;
import org.ripv.handout.HandoutTicket;
import org.ripv.messages.Attachment;
import org.ripv.rmi.GenericRMIInterface;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;

/**
 * Tickets for files a registered service holds, for another registered service to read there. A
 * ticket is made only when both services are on RMI (a service registered outbound-only is out of
 * the others' reach, and its files go through the server as before).
 */
public final class HandoutTickets {
    /** Long enough for an {@code ingest} to wait its turn in a busy DatabaseServer MailBox. */
    public static final Duration VALID = Duration.ofMinutes(15);

    private final ServiceRegistry services;
    private final LongSupplier clock;

    public HandoutTickets(ServiceRegistry services) {
        this(services, System::currentTimeMillis);
    }

    HandoutTickets(ServiceRegistry services, LongSupplier clock) {
        this.services = services;
        this.clock = clock;
    }

    /**
     * The attachment that names {@code files} (as stored: {@code FOLDER/NAME} and their bytes) by
     * tickets for {@code destination} to read at {@code source}; empty when one of the two cannot
     * take part.
     */
    public Optional<Attachment> tickets(String source, String destination, List<Attachment> files) {
        Optional<ServiceReference> holder = services.find(source).filter(r -> directlyReachable(r.stub()));
        if (holder.isEmpty() || services.find(destination).filter(r -> directlyReachable(r.stub())).isEmpty()) {
            return Optional.empty();
        }
        long expires = clock.getAsLong() + VALID.toMillis();
        List<HandoutCollector.Entry> entries = new ArrayList<>();
        for (Attachment f : files) {
            entries.add(new HandoutCollector.Entry(f.name(),
                    HandoutTicket.sign(holder.get().token(), source, destination, f.data(), expires)));
        }
        return Optional.of(HandoutCollector.attachment(entries));
    }

    /**
     * The stub of a registered service, for the service whose session token {@code askerToken}
     * is; null when that one is not registered or is reachable only through the server.
     *
     * @throws SecurityException when the token is no registered service's
     */
    public GenericRMIInterface peer(String askerToken, String service) {
        if (askerToken == null || services.byToken(askerToken).isEmpty()) {
            throw new SecurityException("unknown session token: register first");
        }
        return services.find(service).map(ServiceReference::stub).filter(HandoutTickets::directlyReachable).orElse(null);
    }

    /** True for an RMI stub (which another process can call), false for an outbound-only service's stand-in. */
    static boolean directlyReachable(GenericRMIInterface stub) {
        return stub instanceof RemoteObject
                || stub != null && Proxy.isProxyClass(stub.getClass())
                && Proxy.getInvocationHandler(stub) instanceof RemoteObjectInvocationHandler;
    }
}
