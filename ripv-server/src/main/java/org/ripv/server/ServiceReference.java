package org.ripv.server;

import java.rmi.RemoteException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.naming.ServiceName;
import org.ripv.rmi.GenericRMIInterface;

/**
 * The server's handle on one registered service (thesis: ServiceReference): its descriptor,
 * its remote stub and session token, and one sender thread, so that requests reach the service
 * in the order the RIPV Post Office released them while a slow call to one service never holds
 * up the others. Requests that queue up while a call is under way go together in the next call.
 */
final class ServiceReference {
    /** The most requests sent in one RMI call. */
    static final int MAX_BATCH = 256;

    private final ServiceDescriptor descriptor;
    private final GenericRMIInterface stub;
    private final String token;
    private final LinkedBlockingQueue<IncomingServiceMessage> queue = new LinkedBlockingQueue<>();
    private final Thread sender;
    private final Failure onFailure;
    /** Liveness: failed checks in a row, and whether a check is under way. */
    final java.util.concurrent.atomic.AtomicInteger failedChecks = new java.util.concurrent.atomic.AtomicInteger();
    final java.util.concurrent.atomic.AtomicBoolean checking = new java.util.concurrent.atomic.AtomicBoolean();
    private volatile boolean closed;

    /** Hears of a request that could not be delivered. */
    interface Failure {
        void failed(ServiceReference ref, IncomingServiceMessage request, Exception cause);
    }

    ServiceReference(ServiceDescriptor descriptor, GenericRMIInterface stub, String token, Failure onFailure) {
        this.descriptor = descriptor;
        this.onFailure = onFailure;
        ServiceName.parse(descriptor.name()); // refuses a malformed name before any thread starts
        this.stub = stub;
        this.token = token;
        this.sender = new Thread(this::sendLoop, "ripv-service-ref-" + descriptor.name());
        sender.setDaemon(true);
        sender.start();
    }

    ServiceDescriptor descriptor() {
        return descriptor;
    }

    String token() {
        return token;
    }

    /** Queues a request for the sender thread. */
    void forward(IncomingServiceMessage request) {
        if (closed) {
            onFailure.failed(this, request, new RemoteException(descriptor.name() + " is no longer registered"));
            return;
        }
        queue.add(request);
    }

    private void sendLoop() {
        List<IncomingServiceMessage> batch = new ArrayList<>();
        while (!closed) {
            try {
                batch.add(queue.take());
            } catch (InterruptedException e) {
                break;
            }
            queue.drainTo(batch, MAX_BATCH - 1);
            try {
                if (batch.size() == 1) {
                    stub.serviceRequest(token, batch.get(0));
                } else {
                    stub.serviceRequests(token, List.copyOf(batch));
                }
            } catch (RemoteException | RuntimeException e) {
                batch.forEach(r -> onFailure.failed(this, r, e));
            }
            batch.clear();
        }
        List<IncomingServiceMessage> left = new ArrayList<>();
        queue.drainTo(left);
        left.forEach(r -> onFailure.failed(this, r, new RemoteException(descriptor.name() + " is no longer registered")));
    }

    /** Asks the service to drop a request that has not started; true when it will never run. */
    boolean withdraw(org.ripv.messages.Header h) throws RemoteException {
        if (queue.removeIf(r -> r.header().messageId() == h.messageId()
                && r.header().origin().clientId().equals(h.origin().clientId()))) {
            return true;
        }
        return stub.withdraw(token, h.mailboxAddress(), h.origin().clientId(), h.messageId());
    }

    /** Asks the service to stop a request that is running; true when its handler took the cancel. */
    boolean cancel(org.ripv.messages.Header h) throws RemoteException {
        return stub.cancel(token, h.mailboxAddress(), h.origin().clientId(), h.messageId());
    }

    List<MailboxStatus> mailboxes() throws RemoteException {
        return stub.mailboxes(token);
    }

    void close() {
        closed = true;
        sender.interrupt();
    }

    @Override
    public String toString() {
        return descriptor.name() + " (SID " + descriptor.sid() + ")";
    }
}
