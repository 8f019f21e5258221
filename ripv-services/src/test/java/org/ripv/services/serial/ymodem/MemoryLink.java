package org.ripv.services.serial.ymodem;

import java.io.EOFException;
import java.io.IOException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.Condition;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.BiFunction;

/**
 * One end of an in-memory duplex link. {@link #pair()} makes two connected ends; a
 * {@link #faults} function can drop, alter or repeat any single write on its way out, which
 * is how the YMODEM tests lose, corrupt and duplicate blocks and answers.
 */
final class MemoryLink implements ByteLink {

    /** One direction: a growable byte queue. */
    static final class Pipe {
        private final ReentrantLock lock = new ReentrantLock();
        private final Condition data = lock.newCondition();
        private byte[] buf = new byte[64 * 1024];
        private int head;
        private int tail;
        private boolean closed;

        void put(byte[] b, int off, int len) throws IOException {
            lock.lock();
            try {
                if (closed) {
                    throw new EOFException("pipe closed");
                }
                if (tail + len > buf.length) {
                    byte[] bigger = new byte[Math.max(buf.length * 2, tail - head + len + 1024)];
                    System.arraycopy(buf, head, bigger, 0, tail - head);
                    tail -= head;
                    head = 0;
                    buf = bigger;
                }
                System.arraycopy(b, off, buf, tail, len);
                tail += len;
                data.signalAll();
            } finally {
                lock.unlock();
            }
        }

        int take(byte[] b, int off, int len, long timeoutMillis) throws IOException {
            lock.lock();
            try {
                long nanos = TimeUnit.MILLISECONDS.toNanos(timeoutMillis);
                while (head == tail && !closed && nanos > 0) {
                    nanos = data.awaitNanos(nanos);
                }
                if (head == tail) {
                    if (closed) {
                        throw new EOFException("pipe closed");
                    }
                    return 0;
                }
                int n = Math.min(len, tail - head);
                System.arraycopy(buf, head, b, off, n);
                head += n;
                if (head == tail) {
                    head = tail = 0;
                }
                return n;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new java.io.InterruptedIOException();
            } finally {
                lock.unlock();
            }
        }

        void close() {
            lock.lock();
            try {
                closed = true;
                data.signalAll();
            } finally {
                lock.unlock();
            }
        }
    }

    private final Pipe in;
    private final Pipe out;
    private int writes;
    /** Given the write's index (from 0) and its bytes, what actually goes out (null: nothing). */
    volatile BiFunction<Integer, byte[], byte[]> faults = (i, b) -> b;

    private MemoryLink(Pipe in, Pipe out) {
        this.in = in;
        this.out = out;
    }

    static MemoryLink[] pair() {
        Pipe ab = new Pipe();
        Pipe ba = new Pipe();
        return new MemoryLink[] {new MemoryLink(ba, ab), new MemoryLink(ab, ba)};
    }

    @Override
    public int read(byte[] buffer, int offset, int len, long timeoutMillis) throws IOException {
        return in.take(buffer, offset, len, timeoutMillis);
    }

    @Override
    public synchronized void write(byte[] buffer, int offset, int len) throws IOException {
        byte[] b = java.util.Arrays.copyOfRange(buffer, offset, offset + len);
        byte[] sent = faults.apply(writes++, b);
        if (sent != null && sent.length > 0) {
            out.put(sent, 0, sent.length);
        }
    }

    void close() {
        in.close();
        out.close();
    }
}
