package org.ripv.services.serial;

/**
 * A token bucket over console lines: {@code perSecond} lines a second with a burst of one
 * second's worth. Lines over the rate are counted, for one "N lines skipped" marker.
 */
final class LineRate {
    private final double perSecond;
    private double tokens;
    private long last;
    private long skipped;

    LineRate(int perSecond, long nowNanos) {
        this.perSecond = perSecond;
        this.tokens = perSecond;
        this.last = nowNanos;
    }

    /** True when a line may go out now; else it is counted as skipped. */
    boolean admit(long nowNanos) {
        tokens = Math.min(perSecond, tokens + (nowNanos - last) / 1e9 * perSecond);
        last = nowNanos;
        if (tokens >= 1) {
            tokens -= 1;
            return true;
        }
        skipped++;
        return false;
    }

    /** The lines skipped since the last call. */
    long takeSkipped() {
        long s = skipped;
        skipped = 0;
        return s;
    }

    int perSecond() {
        return (int) perSecond;
    }
}
