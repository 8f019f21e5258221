package org.ripv.server.requests;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.ripv.messages.Header;

/**
 * The requests forwarded to services and not yet answered. It is what makes every request end
 * in exactly one final reply: a request that hears nothing (not even PROGRESS) for the timeout,
 * or whose service goes away, is failed here; a reply that arrives after that is dropped.
 * Deadlines are checked by one sweep a few times a second rather than one timer per request,
 * which costs nothing per request on the hot path.
 */
public final class PendingRequests {
    /** One forwarded request; its deadline moves on with each PROGRESS reply. */
    public static final class Pending {
        private final Header header;
        private final String service;
        private volatile long deadlineNanos;

        Pending(Header header, String service, long deadlineNanos) {
            this.header = header;
            this.service = service;
            this.deadlineNanos = deadlineNanos;
        }

        public Header header() {
            return header;
        }

        public String service() {
            return service;
        }
    }

    private final Map<String, Pending> pending = new ConcurrentHashMap<>();
    private final long timeoutNanos;
    private final Consumer<Pending> onTimeout;

    public PendingRequests(ScheduledExecutorService timers, Duration timeout, Consumer<Pending> onTimeout) {
        this.timeoutNanos = timeout.toNanos();
        this.onTimeout = onTimeout;
        long sweep = Math.max(20, Math.min(250, timeout.toMillis() / 10));
        timers.scheduleWithFixedDelay(this::sweep, sweep, sweep, TimeUnit.MILLISECONDS);
    }

    public static String key(Header h) {
        return h.requestKey();
    }

    /** Starts tracking a request; false when one with the same id is already pending. */
    public boolean add(Header h, String service) {
        return pending.putIfAbsent(key(h), new Pending(h, service, System.nanoTime() + timeoutNanos)) == null;
    }

    /** A PROGRESS reply arrived from {@code service}: restart the request's clock. Null if not pending there. */
    public Pending touch(Header h, String service) {
        Pending p = pending.get(key(h));
        if (p == null || !p.service().equals(service)) {
            return null;
        }
        p.deadlineNanos = System.nanoTime() + timeoutNanos;
        return p;
    }

    /**
     * The final reply arrived from {@code service}: stop tracking. Null when the request was not
     * pending at that service (late, or a reply from a service it was never sent to).
     */
    public Pending complete(Header h, String service) {
        String k = key(h);
        Pending p = pending.get(k);
        if (p == null || !p.service().equals(service) || !pending.remove(k, p)) {
            return null;
        }
        return p;
    }

    /** The pending request a client sent with this message id, or null. */
    public Pending get(String clientId, long messageId) {
        return pending.get(clientId + "#" + messageId);
    }

    /** Every pending request with this message id, whoever sent it. */
    public List<Pending> withMessageId(long messageId) {
        return pending.values().stream().filter(p -> p.header().messageId() == messageId).toList();
    }

    /** Fails every request whose deadline has passed. */
    private void sweep() {
        long now = System.nanoTime();
        for (Map.Entry<String, Pending> e : pending.entrySet()) {
            Pending p = e.getValue();
            if (now - p.deadlineNanos >= 0 && pending.remove(e.getKey(), p)) {
                onTimeout.accept(p);
            }
        }
    }

    /** Removes and returns every request pending at a service. */
    List<Pending> failService(String service) {
        List<Pending> out = new ArrayList<>();
        for (Map.Entry<String, Pending> e : pending.entrySet()) {
            Pending p = e.getValue();
            if (p.service().equals(service) && pending.remove(e.getKey(), p)) {
                out.add(p);
            }
        }
        return out;
    }

    /** Forgets the requests of a client that went away (their replies will be dropped anyway). */
    public void forgetClient(String clientId) {
        pending.values().removeIf(p -> p.header().origin().clientId().equals(clientId));
    }
}
