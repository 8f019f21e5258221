package org.ripv.server.services;

import java.lang.reflect.Proxy;
import java.net.SocketTimeoutException;
import java.rmi.ConnectException;
import java.rmi.RemoteException;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executor;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.messages.Header;
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
 *
 * <p>It also knows which requests have not reached the service yet (so that a timeout can say
 * "never delivered" truthfully), and the service's health as the last call or check found it.
 */
public final class ServiceReference {
    /** The most requests sent in one RMI call. */
    static final int MAX_BATCH = 256;
    private static final Pattern ENDPOINT = Pattern.compile("endpoint:\\[([^,\\]]+)");

    private final ServiceDescriptor descriptor;
    private final GenericRMIInterface stub;
    private final String token;
    private final LinkedBlockingQueue<IncomingServiceMessage> queue = new LinkedBlockingQueue<>();
    /** Requests queued or in a call that has not returned: not (yet) delivered. */
    private final Set<String> undelivered = ConcurrentHashMap.newKeySet();
    private final Thread sender;
    private final Failure onFailure;
    private final String address;
    /** The registration's order among this service's registrations ({@code RegistrationOrder}). */
    private final long order;
    /** Liveness: failed checks in a row, and whether a check is under way. */
    final AtomicInteger failedChecks = new AtomicInteger();
    final AtomicBoolean checking = new AtomicBoolean();
    /** The MailBox query under way, which every asker shares (one call per service at a time). */
    private final AtomicReference<CompletableFuture<List<MailboxStatus>>> query = new AtomicReference<>();
    private volatile String problem = "";
    /** When the sender's call under way began (0: none): a call stuck for long marks a path that is gone. */
    private volatile long callingSince;
    /** A call stuck this long (past any connect deadline) means the requests behind it should not wait. */
    private static final long STUCK_NANOS = TimeUnit.MILLISECONDS.toNanos(
            Long.getLong("ripv.service.stuckMillis", 3_000));
    private volatile Instant problemSince;
    private volatile boolean closed;

    /** Hears of a request that could not be delivered. */
    public interface Failure {
        void failed(ServiceReference ref, IncomingServiceMessage request, Exception cause);
    }

    public ServiceReference(ServiceDescriptor descriptor, GenericRMIInterface stub, String token, Failure onFailure, long order) {
        this.descriptor = descriptor;
        this.onFailure = onFailure;
        ServiceName.parse(descriptor.name()); // refuses a malformed name before any thread starts
        this.stub = stub;
        this.token = token;
        this.order = order;
        this.address = addressOf(stub);
        this.sender = new Thread(this::sendLoop, "ripv-service-ref-" + descriptor.name());
        sender.setDaemon(true);
        sender.start();
    }

    /** Where the server calls the service: HOST:PORT from the stub, or how the calls travel. */
    public static String addressOf(Object stub) {
        String s = String.valueOf(stub);
        Matcher m = ENDPOINT.matcher(s);
        if (m.find()) {
            return m.group(1);
        }
        return stub instanceof Proxy && !s.contains("RemoteObjectInvocationHandler") ? s : "?";
    }

    public ServiceDescriptor descriptor() {
        return descriptor;
    }

    public String token() {
        return token;
    }

    /** HOST:PORT the server calls the service at (what the service registered with). */
    public String address() {
        return address;
    }

    public long order() {
        return order;
    }

    public GenericRMIInterface stub() {
        return stub;
    }

    /**
     * Queues a request for the sender thread — unless the service is known not to answer and the
     * call under way to it is stuck: then it fails at once rather than wait behind that call.
     */
    public void forward(IncomingServiceMessage request) {
        if (closed) {
            onFailure.failed(this, request, new RemoteException(descriptor.name() + " is no longer registered"));
            return;
        }
        if (stuck()) {
            onFailure.failed(this, request, new ConnectException(problem));
            return;
        }
        undelivered.add(request.header().requestKey());
        queue.add(request);
    }

    /** True while the request has not reached the service (queued here, or in a call under way). */
    public boolean undelivered(Header h) {
        return undelivered.contains(h.requestKey());
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
            callingSince = System.nanoTime() | 1;
            try {
                if (batch.size() == 1) {
                    stub.serviceRequest(token, batch.get(0));
                } else {
                    stub.serviceRequests(token, List.copyOf(batch));
                }
                callingSince = 0;
                batch.forEach(r -> undelivered.remove(r.header().requestKey()));
                healthy();
            } catch (RemoteException | RuntimeException e) {
                callingSince = 0;
                batch.forEach(r -> undelivered.remove(r.header().requestKey()));
                trouble(e);
                batch.forEach(r -> onFailure.failed(this, r, e));
            }
            batch.clear();
        }
        List<IncomingServiceMessage> left = new ArrayList<>();
        queue.drainTo(left);
        left.forEach(r -> undelivered.remove(r.header().requestKey()));
        left.forEach(r -> onFailure.failed(this, r, new RemoteException(descriptor.name() + " is no longer registered")));
    }

    /** Takes a request that is still waiting here out of the queue; true when it was there. */
    public boolean unqueue(Header h) {
        boolean removed = queue.removeIf(r -> r.header().messageId() == h.messageId()
                && r.header().origin().clientId().equals(h.origin().clientId()));
        if (removed) {
            undelivered.remove(h.requestKey());
        }
        return removed;
    }

    /** Asks the service to drop a request that has not started; true when it will never run. */
    public boolean withdraw(Header h) throws RemoteException {
        if (unqueue(h)) {
            return true;
        }
        return stub.withdraw(token, h.mailboxAddress(), h.origin().clientId(), h.messageId());
    }

    /** Asks the service to stop a request that is running; true when its handler took the cancel. */
    public boolean cancel(Header h) throws RemoteException {
        return stub.cancel(token, h.mailboxAddress(), h.origin().clientId(), h.messageId());
    }

    /** Tells the service a page of a request's table went out to its client: the next may come. */
    public boolean more(Header h) throws RemoteException {
        return stub.more(token, h.mailboxAddress(), h.origin().clientId(), h.messageId());
    }

    /** Asks for the MailBoxes now, on the caller's thread. */
    List<MailboxStatus> mailboxes() throws RemoteException {
        return stub.mailboxes(token);
    }

    /**
     * The service's MailBoxes, asked on {@code pool}; whoever asks while a query is under way
     * shares it, so a service that hangs ties up one thread, not one per asker.
     */
    CompletableFuture<List<MailboxStatus>> mailboxesAsync(Executor pool) {
        while (true) {
            CompletableFuture<List<MailboxStatus>> now = query.get();
            if (now != null) {
                return now;
            }
            CompletableFuture<List<MailboxStatus>> mine = new CompletableFuture<>();
            if (!query.compareAndSet(null, mine)) {
                continue;
            }
            try {
                pool.execute(() -> {
                    try {
                        List<MailboxStatus> l = stub.mailboxes(token);
                        healthy();
                        mine.complete(l);
                    } catch (RemoteException | RuntimeException e) {
                        trouble(e);
                        mine.completeExceptionally(e);
                    } finally {
                        query.compareAndSet(mine, null);
                    }
                });
            } catch (RuntimeException e) {
                query.compareAndSet(mine, null);
                mine.completeExceptionally(e);
            }
            return mine;
        }
    }

    /** The MailBoxes within {@code deadline}; a {@link java.util.concurrent.TimeoutException} cause when late. */
    public CompletableFuture<List<MailboxStatus>> mailboxes(Executor pool, Duration deadline) {
        return mailboxesAsync(pool).copy().orTimeout(deadline.toMillis(), TimeUnit.MILLISECONDS);
    }

    /** The last call went through. */
    void healthy() {
        if (!problem.isEmpty()) {
            problem = "";
            problemSince = null;
        }
    }

    /** The last call or check failed: remember why, in words for {@code ?services}. */
    void trouble(Throwable e) {
        trouble("could not reach " + address + ": " + why(e, address));
    }

    public void trouble(String why) {
        if (problemSince == null) {
            problemSince = Instant.now();
        }
        problem = why;
        if (stuck()) {
            // The requests queued behind a call that hangs on a service that does not answer:
            // tell their clients now, truthfully (they never left), instead of after that call.
            List<IncomingServiceMessage> waiting = new ArrayList<>();
            queue.drainTo(waiting);
            for (IncomingServiceMessage r : waiting) {
                undelivered.remove(r.header().requestKey());
                onFailure.failed(this, r, new ConnectException(why));
            }
        }
    }

    /** Known not to answer, with a call to it under way for longer than any connect may take. */
    private boolean stuck() {
        long since = callingSince;
        return !problem.isEmpty() && since != 0 && System.nanoTime() - since > STUCK_NANOS;
    }

    /** Empty when the last call went through; else what went wrong. */
    public String problem() {
        return problem;
    }

    public Instant problemSince() {
        return problemSince;
    }

    /** A failed call in words: the innermost cause's message without the address (callers add it). */
    public static String why(Throwable e, String address) {
        Throwable t = e;
        while (t.getCause() != null && t.getCause() != t) {
            t = t.getCause();
        }
        if (t instanceof TimeoutException) {
            return "no answer within the deadline";
        }
        String m = t.getMessage() == null ? t.getClass().getSimpleName() : t.getMessage();
        int at = m.indexOf("could not reach ");
        if (at >= 0 && m.indexOf(": ", at) > 0) {
            return m.substring(m.indexOf(": ", at) + 2); // "timed out after 3000 ms" from DeadlineSocketFactory
        }
        if (t instanceof SocketTimeoutException) {
            return "no answer: " + m;
        }
        return m;
    }

    public void close() {
        closed = true;
        sender.interrupt();
    }

    boolean closed() {
        return closed;
    }

    @Override
    public String toString() {
        return descriptor.name() + " (SID " + descriptor.sid() + ")";
    }
}
