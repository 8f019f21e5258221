package org.ripv.services.simulator;

import java.io.InterruptedIOException;
import java.util.concurrent.DelayQueue;
import java.util.concurrent.Delayed;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;

/**
 * One direction of a slow line: bytes go in, wait out the latency, and come out no faster than
 * the baud rate (10 bits a byte, 8N1). The bytes in flight are bounded, as by a modem's buffer
 * and its flow control, so a writer that outruns the line waits instead of queueing a whole file.
 */
final class PacedPipe {
    /** A piece of the stream and when its last bit has arrived; an empty piece is the end. */
    record Piece(byte[] bytes, long due) implements Delayed {
        boolean end() {
            return bytes.length == 0;
        }

        @Override
        public long getDelay(TimeUnit unit) {
            return unit.convert(due - System.nanoTime(), TimeUnit.NANOSECONDS);
        }

        @Override
        public int compareTo(Delayed o) {
            return Long.compare(due, ((Piece) o).due);
        }
    }

    /** Pieces small enough that pacing is smooth at 2,400 baud (64 bytes are 0.27 s there). */
    private static final int PIECE = 64;

    private final DelayQueue<Piece> queue = new DelayQueue<>();
    private final Semaphore room;
    private final int capacity;
    private final long latencyNanos;
    private final double nanosPerByte;
    private long lastDue;

    /**
     * @param baud    bits a second, 0 for no pacing
     * @param latency how long each byte takes to cross, in nanoseconds
     */
    PacedPipe(int baud, long latency) {
        this.latencyNanos = latency;
        this.nanosPerByte = baud <= 0 ? 0 : 10e9 / baud;
        // enough bytes in flight to keep the line busy across the latency (bandwidth × delay), and a buffer
        double bytesPerSecond = baud <= 0 ? 1e6 : baud / 10.0;
        this.capacity = (int) Math.min(1 << 20, 1024 + bytesPerSecond * latency / 1e9);
        this.room = new Semaphore(capacity);
    }

    /** Queues bytes; waits while the line's buffer is full. */
    void put(byte[] b, int off, int len) throws InterruptedIOException {
        for (int i = 0; i < len; i += PIECE) {
            int n = Math.min(PIECE, len - i);
            try {
                room.acquire(n);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new InterruptedIOException("interrupted while the line was busy");
            }
            byte[] copy = new byte[n];
            System.arraycopy(b, off + i, copy, 0, n);
            synchronized (this) {
                long start = Math.max(System.nanoTime() + latencyNanos, lastDue);
                lastDue = start + (long) (n * nanosPerByte);
                queue.put(new Piece(copy, lastDue));
            }
        }
    }

    /** Marks the end of the stream, after what is queued. */
    synchronized void end() {
        lastDue = Math.max(System.nanoTime() + latencyNanos, lastDue);
        queue.put(new Piece(new byte[0], lastDue));
    }

    /** Lets waiting writers go: the line is gone, and they will find out when they write. */
    void abandon() {
        room.release(capacity);
    }

    /** The next piece that has crossed, or null after {@code timeoutMillis}. */
    Piece poll(long timeoutMillis) throws InterruptedException {
        Piece p = queue.poll(timeoutMillis, TimeUnit.MILLISECONDS);
        if (p != null) {
            room.release(p.bytes().length);
        }
        return p;
    }

    /** The next piece that has crossed, waiting as long as it takes. */
    Piece take() throws InterruptedException {
        Piece p = queue.take();
        room.release(p.bytes().length);
        return p;
    }
}
