package org.ripv.services.bench;

import java.io.IOException;
import java.io.OutputStream;
import java.util.concurrent.locks.LockSupport;

/**
 * The sending side of a serial line of a given baud rate (10 bits a byte: 8 data bits, a start
 * and a stop bit): each byte leaves when the line would have finished clocking it out, never
 * sooner. One clock per direction, owned by the thread that writes it; shared by the relays that
 * put a real line rate between two ends ({@link YmodemBaudRelay}, and the Iridium-like relay of
 * ripv-it's ZMODEM bench).
 */
public final class LineClock {
    private final long nanosPerByte;
    /** When the line has clocked out everything written so far ({@link System#nanoTime}). */
    private long freeAt;

    public LineClock(int baud) {
        this.nanosPerByte = 10_000_000_000L / baud;
    }

    /** Nothing is sent before {@code nanos}: a line that fell silent starts again from then, a busy one is not hurried. */
    public void idleUntil(long nanos) {
        freeAt = Math.max(freeAt, nanos);
    }

    /** Writes {@code len} bytes at the line's rate, flushing each piece as its time comes. */
    public void send(OutputStream out, byte[] bytes, int offset, int len) throws IOException {
        int sent = 0;
        while (sent < len) {
            // the next byte reaches the far end once the line has clocked it out
            long due = freeAt + nanosPerByte;
            long now = System.nanoTime();
            if (due > now) {
                LockSupport.parkNanos(due - now);
                now = System.nanoTime();
            }
            // every byte whose time has come goes out in one write (parking overshoots)
            int k = (int) Math.max(1, Math.min(len - sent, (now - freeAt) / nanosPerByte));
            out.write(bytes, offset + sent, k);
            out.flush();
            sent += k;
            freeAt += k * nanosPerByte;
        }
    }
}
