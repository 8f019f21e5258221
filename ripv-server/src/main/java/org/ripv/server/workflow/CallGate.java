package org.ripv.server.workflow;

import java.util.Date;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.LongSupplier;
import org.ripv.messages.VehicleEvent;

/**
 * One call as a runner sees it: whether it has ended, and a place to wait at a step boundary
 * until something changes (the lock is released, the call ends, the queue changes).
 */
final class CallGate {
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private volatile VehicleEvent ended;

    /** How the call ended (LINK_LOST also for a stopping server), or null while it goes on. */
    VehicleEvent ended() {
        return ended;
    }

    /** The call ended: everyone waiting wakes. */
    void end(VehicleEvent why) {
        lock.lock();
        try {
            ended = why == null ? VehicleEvent.LINK_LOST : why;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Something a waiting runner cares about changed. */
    void wake() {
        lock.lock();
        try {
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** What a boundary checks before it waits: null to wait, or its answer. */
    @FunctionalInterface
    interface Check<T> {
        T now();
    }

    /**
     * Checks, and while the check says wait, sleeps until woken or {@code untilMillis()} (epoch ms).
     * Returns the check's answer, or {@code interrupted} when the thread is interrupted.
     */
    <T> T await(Check<T> check, LongSupplier untilMillis, T interrupted) {
        lock.lock();
        try {
            while (true) {
                T answer = check.now();
                if (answer != null) {
                    return answer;
                }
                try {
                    changed.awaitUntil(new Date(untilMillis.getAsLong()));
                } catch (InterruptedException ie) {
                    Thread.currentThread().interrupt();
                    return interrupted;
                }
            }
        } finally {
            lock.unlock();
        }
    }
}
