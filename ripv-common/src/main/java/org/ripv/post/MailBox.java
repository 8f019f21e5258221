package org.ripv.post;

import java.util.ArrayDeque;
import java.util.Collection;
import java.util.Objects;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Predicate;
import org.ripv.messages.Message;
import org.ripv.messages.Priority;

/**
 * Storage for the messages of one resource (thesis figure 5.2): three FIFO inboxes — 1 Normal,
 * 2 Priority, 3 Urgent — and one outbox. {@link #takeNext()} always returns the oldest message of
 * the highest non-empty priority, blocking while all three are empty.
 *
 * @param <I> the incoming message type (requests)
 * @param <O> the outgoing message type (replies)
 */
public final class MailBox<I extends Message, O extends Message> {
    private final String address;
    private final int capacity;
    private final MailBoxKey key = new MailBoxKey();

    private final ReentrantLock lock = new ReentrantLock();
    private final Condition notEmpty = lock.newCondition();
    @SuppressWarnings("unchecked")
    private final ArrayDeque<I>[] inboxes = new ArrayDeque[] {new ArrayDeque<>(), new ArrayDeque<>(), new ArrayDeque<>()};
    private int waiting;

    private final LinkedBlockingQueue<O> outbox = new LinkedBlockingQueue<>();

    /**
     * @param address  the MailBox's address (Appendix A), or "RIPV Post Office" on the server
     * @param capacity how many requests may wait in all three inboxes together
     */
    public MailBox(String address, int capacity) {
        this.address = Objects.requireNonNull(address, "address");
        if (capacity < 1) {
            throw new IllegalArgumentException("capacity must be positive: " + capacity);
        }
        this.capacity = capacity;
    }

    public String address() {
        return address;
    }

    public MailBoxKey key() {
        return key;
    }

    /**
     * Files a request in the inbox of its priority.
     *
     * @return false when the inboxes are full (the caller answers with an error)
     */
    public boolean deliver(I message) {
        Priority p = message.header().priority();
        lock.lock();
        try {
            if (waiting >= capacity) {
                return false;
            }
            inboxes[p.level() - 1].addLast(message);
            waiting++;
            notEmpty.signal();
            return true;
        } finally {
            lock.unlock();
        }
    }

    /** Waits for and removes the oldest message of the highest non-empty priority. */
    public I takeNext() throws InterruptedException {
        lock.lockInterruptibly();
        try {
            while (waiting == 0) {
                notEmpty.await();
            }
            return pollLocked();
        } finally {
            lock.unlock();
        }
    }

    /** Like {@link #takeNext()} but gives up after the timeout, returning null. */
    public I pollNext(long timeout, TimeUnit unit) throws InterruptedException {
        long nanos = unit.toNanos(timeout);
        lock.lockInterruptibly();
        try {
            while (waiting == 0) {
                if (nanos <= 0) {
                    return null;
                }
                nanos = notEmpty.awaitNanos(nanos);
            }
            return pollLocked();
        } finally {
            lock.unlock();
        }
    }

    private I pollLocked() {
        for (int i = inboxes.length - 1; i >= 0; i--) {
            I m = inboxes[i].pollFirst();
            if (m != null) {
                waiting--;
                return m;
            }
        }
        throw new AssertionError("waiting=" + waiting + " but all inboxes empty");
    }

    /** How many requests wait in the inbox of a priority. */
    public int waiting(Priority p) {
        lock.lock();
        try {
            return inboxes[p.level() - 1].size();
        } finally {
            lock.unlock();
        }
    }

    /** How many requests wait in all inboxes. */
    public int waiting() {
        lock.lock();
        try {
            return waiting;
        } finally {
            lock.unlock();
        }
    }

    /** Removes the first waiting request that matches; true when one was removed. */
    public boolean remove(Predicate<? super I> which) {
        lock.lock();
        try {
            for (ArrayDeque<I> inbox : inboxes) {
                var it = inbox.iterator();
                while (it.hasNext()) {
                    if (which.test(it.next())) {
                        it.remove();
                        waiting--;
                        return true;
                    }
                }
            }
            return false;
        } finally {
            lock.unlock();
        }
    }

    /** Queues a reply for the outbox assistant. */
    public void post(O reply) {
        outbox.add(Objects.requireNonNull(reply, "reply"));
    }

    /** Waits for and removes the next reply. */
    public O takeReply() throws InterruptedException {
        return outbox.take();
    }

    /** Removes the next reply if there is one, without waiting. */
    public O pollReply() {
        return outbox.poll();
    }

    /** Moves up to {@code max} replies that are already waiting into {@code into}, without blocking. */
    public int drainReplies(Collection<? super O> into, int max) {
        return outbox.drainTo(into, max);
    }

    @Override
    public String toString() {
        return "MailBox[" + address + ", " + waiting() + " waiting" + (key.isHeld() ? ", busy" : "") + "]";
    }
}
