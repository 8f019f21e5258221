package org.ripv.retry;

import java.time.Duration;

/**
 * The wait between tries of something that keeps failing: {@code first}, then twice as long each
 * time, never more than {@code max}; {@link #reset} after a success starts again at
 * {@code first}. Not thread-safe: one retry loop owns one.
 *
 * <pre>{@code
 * Backoff backoff = new Backoff(Duration.ofMillis(500), Duration.ofSeconds(10));
 * while (!connected()) {
 *     Thread.sleep(backoff.nextMillis());   // 500, 1000, 2000 ... 10000, 10000
 * }
 * }</pre>
 */
public final class Backoff {
    private final long firstMillis;
    private final long maxMillis;
    private long next;

    public Backoff(Duration first, Duration max) {
        if (first.isNegative() || first.isZero() || max.compareTo(first) < 0) {
            throw new IllegalArgumentException("a back-off starts above 0 and grows to at least where it starts, not "
                    + first + " to " + max);
        }
        this.firstMillis = first.toMillis();
        this.maxMillis = max.toMillis();
        this.next = firstMillis;
    }

    /** The wait before the next try, in milliseconds; the one after it is twice as long, up to the most. */
    public long nextMillis() {
        long wait = next;
        next = Math.min(next * 2, maxMillis);
        return wait;
    }

    /** A try worked: the next failure waits {@code first} again. */
    public void reset() {
        next = firstMillis;
    }
}
