package org.ripv.server;

import java.rmi.RemoteException;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.naming.ServiceName;
import org.ripv.rmi.GenericRMIInterface;

/**
 * The server's handle on one registered service (thesis: ServiceReference): its descriptor,
 * its remote stub and session token, and one sender thread so that requests reach the service
 * in the order the RIPV Post Office released them while a slow call to one service never holds
 * up the others.
 */
final class ServiceReference {
    private final ServiceDescriptor descriptor;
    private final ServiceName name;
    private final GenericRMIInterface stub;
    private final String token;
    private final ExecutorService sender;

    ServiceReference(ServiceDescriptor descriptor, GenericRMIInterface stub, String token) {
        this.descriptor = descriptor;
        this.name = ServiceName.parse(descriptor.name());
        this.stub = stub;
        this.token = token;
        this.sender = new ThreadPoolExecutor(1, 1, 0, TimeUnit.MILLISECONDS, new LinkedBlockingQueue<>(), r -> {
            Thread t = new Thread(r, "ripv-service-ref-" + descriptor.name());
            t.setDaemon(true);
            return t;
        });
    }

    ServiceDescriptor descriptor() {
        return descriptor;
    }

    ServiceName name() {
        return name;
    }

    String token() {
        return token;
    }

    /** Sends a request on the sender thread; {@code onFailure} hears of a call that failed. */
    void forward(IncomingServiceMessage request, BiConsumer<IncomingServiceMessage, Exception> onFailure) {
        sender.execute(() -> {
            try {
                stub.serviceRequest(token, request);
            } catch (RemoteException | RuntimeException e) {
                onFailure.accept(request, e);
            }
        });
    }

    List<MailboxStatus> mailboxes() throws RemoteException {
        return stub.mailboxes(token);
    }

    void close() {
        sender.shutdownNow();
    }

    @Override
    public String toString() {
        return descriptor.name() + " (SID " + descriptor.sid() + ")";
    }
}
