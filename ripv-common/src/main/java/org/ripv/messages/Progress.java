package org.ripv.messages;

/** How far a long command has got: bytes (or items) done of total, and the rate per second. */
public record Progress(String what, long done, long total, double ratePerSecond) implements Result {
    /** Percent done, or -1 when the total is unknown. */
    public int percent() {
        return total <= 0 ? -1 : (int) Math.min(100, done * 100 / total);
    }
}
