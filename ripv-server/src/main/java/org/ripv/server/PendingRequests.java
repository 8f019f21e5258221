package org.ripv.server;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.ripv.messages.Header;

/**
 * The requests forwarded to services and not yet answered. It is what makes every request end
 * in exactly one final reply: a request that hears nothing (not even PROGRESS) for the timeout,
 * or whose service goes away, is failed here; a reply that arrives after that is dropped.
 */
final class PendingRequests {
    /** One forwarded request. */
    record Pending(Header header, String service, ScheduledFuture<?> timer) {}

    private final Map<String, Pending> pending = new ConcurrentHashMap<>();
    private final ScheduledExecutorService timers;
    private final Duration timeout;
    private final Consumer<Pending> onTimeout;

    PendingRequests(ScheduledExecutorService timers, Duration timeout, Consumer<Pending> onTimeout) {
        this.timers = timers;
        this.timeout = timeout;
        this.onTimeout = onTimeout;
    }

    static String key(Header h) {
        return h.origin().clientId() + "#" + h.messageId();
    }

    /** Starts tracking a request; false when one with the same id is already pending. */
    boolean add(Header h, String service) {
        String k = key(h);
        Pending p = new Pending(h, service, schedule(k));
        if (pending.putIfAbsent(k, p) != null) {
            p.timer().cancel(false);
            return false;
        }
        return true;
    }

    private ScheduledFuture<?> schedule(String k) {
        return timers.schedule(() -> {
            Pending p = pending.remove(k);
            if (p != null) {
                onTimeout.accept(p);
            }
        }, timeout.toMillis(), TimeUnit.MILLISECONDS);
    }

    /** A PROGRESS reply arrived from {@code service}: restart the request's clock. Null if not pending there. */
    Pending touch(Header h, String service) {
        String k = key(h);
        Pending p = pending.get(k);
        if (p == null || !p.service().equals(service)) {
            return null;
        }
        Pending renewed = new Pending(p.header(), p.service(), schedule(k));
        if (pending.replace(k, p, renewed)) {
            p.timer().cancel(false);
            return renewed;
        }
        renewed.timer().cancel(false);
        return pending.get(k);
    }

    /**
     * The final reply arrived from {@code service}: stop tracking. Null when the request was not
     * pending at that service (late, or a reply from a service it was never sent to).
     */
    Pending complete(Header h, String service) {
        String k = key(h);
        Pending p = pending.get(k);
        if (p == null || !p.service().equals(service) || !pending.remove(k, p)) {
            return null;
        }
        p.timer().cancel(false);
        return p;
    }

    /** Removes and returns every request pending at a service. */
    List<Pending> failService(String service) {
        List<Pending> out = new ArrayList<>();
        for (Pending p : pending.values()) {
            if (p.service().equals(service) && pending.remove(key(p.header()), p)) {
                p.timer().cancel(false);
                out.add(p);
            }
        }
        return out;
    }

    /** Forgets the requests of a client that went away (their replies will be dropped anyway). */
    void forgetClient(String clientId) {
        pending.values().removeIf(p -> {
            if (p.header().origin().clientId().equals(clientId)) {
                p.timer().cancel(false);
                return true;
            }
            return false;
        });
    }

    int size() {
        return pending.size();
    }
}
