package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.io.InterruptedIOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;

/**
 * The bytes a running command reads: the link's reader copies what the vehicle says into it while
 * it is open (from the moment a command is about to be written until its reply is complete), and
 * the command reads them with a timeout, as it would read the link itself. Bounded: a full pipe
 * holds the reader back, which is what a transfer wants (flow control) and what a plain command
 * never causes (it drains the pipe as fast as the bytes come).
 */
final class ReplyPipe {
    private final ReentrantLock lock = new ReentrantLock();
    private final Condition changed = lock.newCondition();
    private final byte[] ring;
    private int head;
    private int size;
    private boolean open;
    private IOException failure;

    ReplyPipe(int capacity) {
        this.ring = new byte[capacity];
    }

    /** Starts taking bytes, with nothing in it. */
    void open() {
        lock.lock();
        try {
            head = 0;
            size = 0;
            open = true;
        } finally {
            lock.unlock();
        }
    }

    /** Stops taking bytes and forgets the unread ones; a reader blocked in {@link #put} goes on. */
    void close() {
        lock.lock();
        try {
            open = false;
            size = 0;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** The link failed: reads get this error once the bytes before it are read. */
    void fail(IOException e) {
        lock.lock();
        try {
            failure = e;
            changed.signalAll();
        } finally {
            lock.unlock();
        }
    }

    /** Copies bytes in while the pipe is open, waiting while it is full; drops them when closed. */
    void put(byte[] bytes, int offset, int length) throws InterruptedException {
        int done = 0;
        lock.lock();
        try {
            while (done < length) {
                while (open && size == ring.length) {
                    changed.await();
                }
                if (!open) {
                    return;
                }
                int tail = (head + size) % ring.length;
                int n = Math.min(length - done, Math.min(ring.length - size, ring.length - tail));
                System.arraycopy(bytes, offset + done, ring, tail, n);
                size += n;
                done += n;
                changed.signalAll();
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * Reads up to {@code length} bytes, waiting at most {@code timeoutMillis} for the first.
     *
     * @return the count, 0 when nothing came in time
     * @throws EOFException (or another IOException) when the link failed and nothing is left
     */
    int read(byte[] bytes, int offset, int length, long timeoutMillis) throws IOException {
        long left = TimeUnit.MILLISECONDS.toNanos(Math.max(1, timeoutMillis));
        lock.lock();
        try {
            while (size == 0) {
                if (failure != null) {
                    throw failure instanceof EOFException ? new EOFException(failure.getMessage())
                            : new IOException(failure.getMessage(), failure);
                }
                if (left <= 0) {
                    return 0;
                }
                left = changed.awaitNanos(left);
            }
            int n = Math.min(length, Math.min(size, ring.length - head));
            System.arraycopy(ring, head, bytes, offset, n);
            head = (head + n) % ring.length;
            size -= n;
            changed.signalAll();
            return n;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new InterruptedIOException("interrupted while reading the vehicle's reply");
        } finally {
            lock.unlock();
        }
    }
}
