package org.ripv.server.clients;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.session.ConsoleHub;

/**
 * Operator locks that run out ({@code ?lock MAILBOX SECONDS}): when one ends by itself, it is
 * taken out of the lock table and watchers get LOCK_RELEASED, as when its holder unlocks or
 * disconnects (docs/sessions.md). One timer per locked MailBox, replaced when the lock is.
 */
public final class LockExpiries {
    private final ScheduledExecutorService timers;
    private final Map<String, OperatorLock> locks;
    private final ConsoleHub console;
    private final Consumer<String> released;
    private final Map<String, Timer> pending = new ConcurrentHashMap<>();

    private record Timer(OperatorLock lock, ScheduledFuture<?> future) {}

    /** @param released told the MailBox whose lock ran out (paused workflows look again) */
    LockExpiries(ScheduledExecutorService timers, Map<String, OperatorLock> locks, ConsoleHub console,
                 Consumer<String> released) {
        this.timers = timers;
        this.locks = locks;
        this.console = console;
        this.released = released;
    }

    /** An operator took (or renewed) the lock on a MailBox: it is released at its end unless it changes first. */
    void taken(String mailbox, OperatorLock lock) {
        long delay = Math.max(0, lock.untilMillis() - System.currentTimeMillis()) + 1;
        ScheduledFuture<?> f = timers.schedule(() -> expire(mailbox, lock), delay, TimeUnit.MILLISECONDS);
        Timer old = pending.put(mailbox, new Timer(lock, f));
        if (old != null) {
            old.future().cancel(false);
        }
    }

    private void expire(String mailbox, OperatorLock lock) {
        pending.computeIfPresent(mailbox, (k, t) -> t.lock() == lock ? null : t);
        // Only this very lock: one unlocked, renewed or taken over since is no longer ours to end.
        if (locks.remove(mailbox, lock)) {
            console.serverEvent(mailbox, VehicleEvent.LOCK_RELEASED, lock.user(), "its time ran out");
            released.accept(mailbox);
        }
    }

    /** The server stops: no lock needs ending any more. */
    void close() {
        pending.values().forEach(t -> t.future().cancel(false));
        pending.clear();
    }
}
