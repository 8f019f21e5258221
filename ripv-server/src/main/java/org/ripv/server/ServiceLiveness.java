package org.ripv.server;

import java.rmi.RemoteException;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Notices services that have died: each is asked for its MailBoxes every check interval, and one
 * that fails twice in a row is removed from the service list (its pending requests then fail).
 * Checks never pile up on a service that hangs.
 */
final class ServiceLiveness {
    private static final Logger log = LoggerFactory.getLogger(ServiceLiveness.class);
    /** Removes a service that failed this many checks in a row. */
    static final int FAILED_CHECKS_TO_REMOVE = 2;

    private final Map<String, ServiceReference> services;
    private final ExecutorService checks;
    private final ScheduledExecutorService timers;
    private final Duration interval;
    private final BiConsumer<ServiceReference, String> drop;

    ServiceLiveness(Map<String, ServiceReference> services, ExecutorService checks, ScheduledExecutorService timers,
                    Duration interval, BiConsumer<ServiceReference, String> drop) {
        this.services = services;
        this.checks = checks;
        this.timers = timers;
        this.interval = interval;
        this.drop = drop;
    }

    /** Checks every registered service (the server's timer calls this each interval). */
    void checkAll() {
        for (ServiceReference ref : services.values()) {
            soon(ref);
        }
    }

    /** Checks one service off the caller's thread (after a call to it failed). */
    void soon(ServiceReference ref) {
        if (!checks.isShutdown()) {
            checks.execute(() -> check(ref));
        }
    }

    private void check(ServiceReference ref) {
        if (!ref.checking.compareAndSet(false, true)) {
            return; // the last check has not finished; do not pile up more
        }
        try {
            ref.mailboxes();
            ref.failedChecks.set(0);
        } catch (RemoteException | RuntimeException e) {
            int failures = ref.failedChecks.incrementAndGet();
            if (failures >= FAILED_CHECKS_TO_REMOVE && services.remove(ref.descriptor().name(), ref)) {
                log.warn("{} is gone ({}); removed it from the service list", ref, e.getClass().getSimpleName());
                drop.accept(ref, "went away");
            } else if (failures < FAILED_CHECKS_TO_REMOVE && !timers.isShutdown()) {
                // Look again soon, not at once: a passing hiccup should have passed by then.
                timers.schedule(() -> soon(ref), interval.toMillis() / 2 + 1, TimeUnit.MILLISECONDS);
            }
        } finally {
            ref.checking.set(false);
        }
    }
}
