package org.ripv.server.services;

import java.time.Duration;
import java.time.Instant;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.BiConsumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Notices services that have died or can no longer be reached: each is asked for its MailBoxes
 * every check interval, with a deadline; a failed check marks the service "not answering" with
 * the reason at once (shown by {@code ?services}), and one that fails twice in a row is removed
 * from the service list (its pending requests then fail). The removed are remembered with their
 * reason until they register again. Checks never pile up on a service that hangs.
 */
public final class ServiceLiveness {
    private static final Logger log = LoggerFactory.getLogger(ServiceLiveness.class);
    /** Removes a service that failed this many checks in a row. */
    static final int FAILED_CHECKS_TO_REMOVE = 2;
    /** How long a check waits for a service; also the per-service deadline of {@code ?mailboxes}. */
    public static final Duration QUERY_DEADLINE = Duration.ofMillis(Long.getLong("ripv.service.queryMillis", 2_000));

    /** A service removed for failing its checks (or refused at registration: {@code refused}), and why. */
    public record Lost(String why, Instant when, boolean refused) {}

    private final ServiceRegistry services;
    private final ExecutorService checks;
    private final ExecutorService queries;
    private final ScheduledExecutorService timers;
    private final Duration interval;
    private final Duration deadline;
    private final BiConsumer<ServiceReference, String> drop;
    private final Map<String, Lost> lost = new ConcurrentHashMap<>();

    public ServiceLiveness(ServiceRegistry services, ExecutorService checks, ExecutorService queries,
                    ScheduledExecutorService timers, Duration interval, BiConsumer<ServiceReference, String> drop) {
        this.services = services;
        this.checks = checks;
        this.queries = queries;
        this.timers = timers;
        this.interval = interval;
        // A check must end within one interval (so that two failures take at most two intervals),
        // but never sooner than a loaded service can answer.
        this.deadline = interval.compareTo(QUERY_DEADLINE) < 0 ? QUERY_DEADLINE : interval;
        this.drop = drop;
    }

    /** Checks every registered service (the server's timer calls this each interval). */
    public void checkAll() {
        for (ServiceReference ref : services.all()) {
            soon(ref);
        }
    }

    /** Checks one service off the caller's thread (after a call to it failed). */
    public void soon(ServiceReference ref) {
        if (!checks.isShutdown()) {
            try {
                checks.execute(() -> check(ref));
            } catch (RejectedExecutionException ignored) {
                // stopping
            }
        }
    }

    /** Services removed for failing their checks, by name, until they register again. */
    public Map<String, Lost> lost() {
        return lost;
    }

    /** A registration refused because the server cannot call the service back: {@code ?services} says so. */
    public void refused(String name, String why) {
        if (!services.isListed(name)) {
            lost.put(name, new Lost(why, Instant.now(), true));
        }
    }

    /** A service registered (again): forget that it was lost. */
    public void registered(String name) {
        lost.remove(name);
    }

    private void check(ServiceReference ref) {
        if (ref.closed() || !ref.checking.compareAndSet(false, true)) {
            return; // the last check has not finished; do not pile up more
        }
        try {
            ref.mailboxes(queries, deadline).get();
            ref.failedChecks.set(0);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof TimeoutException) {
                ref.trouble("no answer from " + ref.address() + " within " + deadline.toMillis() + " ms");
            } else if (ref.problem().isEmpty()) {
                ref.trouble(cause);
            }
            failed(ref);
        } catch (RuntimeException e) {
            ref.trouble(e);
            failed(ref);
        } finally {
            ref.checking.set(false);
        }
    }

    private void failed(ServiceReference ref) {
        int failures = ref.failedChecks.incrementAndGet();
        String why = ref.problem();
        if (failures >= FAILED_CHECKS_TO_REMOVE && services.remove(ref)) {
            log.warn("{} is gone: {}; removed it from the service list", ref, why);
            lost.put(ref.descriptor().name(), new Lost(why, Instant.now(), false));
            drop.accept(ref, "went away (" + why + ")");
        } else if (failures < FAILED_CHECKS_TO_REMOVE && !timers.isShutdown()) {
            log.warn("{} is not answering: {}", ref, why);
            // Look again soon, not at once: a passing hiccup should have passed by then.
            timers.schedule(() -> soon(ref), interval.toMillis() / 2 + 1, TimeUnit.MILLISECONDS);
        }
    }
}
