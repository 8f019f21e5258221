package org.ripv.messages;

import java.util.Locale;

/** How far a long command has got: bytes (or items) done of total, and the rate per second. */
public record Progress(String what, long done, long total, double ratePerSecond) implements Result {
    /** Percent done, or -1 when the total is unknown. */
    public int percent() {
        return total <= 0 ? -1 : (int) Math.min(100, done * 100 / total);
    }

    /** Seconds left at the current rate, or -1 when the total or the rate is unknown. */
    public long etaSeconds() {
        if (total <= 0 || ratePerSecond <= 0) {
            return -1;
        }
        return (long) Math.ceil(Math.max(0, total - done) / ratePerSecond);
    }

    /** The time left as {@code 1:12} (or {@code 1:02:03}); empty when unknown. */
    public String etaText() {
        long s = etaSeconds();
        return s < 0 ? "" : clock(s);
    }

    /** The rate as {@code 11.2 kB/s}, {@code 830 B/s}; empty when unknown. */
    public String rateText() {
        if (ratePerSecond <= 0) {
            return "";
        }
        if (ratePerSecond >= 1_000_000) {
            return String.format(Locale.ROOT, "%.1f MB/s", ratePerSecond / 1e6);
        }
        return ratePerSecond >= 1000 ? String.format(Locale.ROOT, "%.1f kB/s", ratePerSecond / 1e3)
                : String.format(Locale.ROOT, "%.0f B/s", ratePerSecond);
    }

    /** {@code 40 % ETA 1:12} (what is known of it), as ?status and the CLI show a transfer. */
    public String shortText() {
        StringBuilder b = new StringBuilder();
        if (percent() >= 0) {
            b.append(percent()).append(" %");
        }
        if (etaSeconds() >= 0) {
            b.append(b.isEmpty() ? "" : " ").append("ETA ").append(etaText());
        }
        return b.toString();
    }

    /** Seconds as {@code M:SS} or {@code H:MM:SS}. */
    public static String clock(long seconds) {
        long h = seconds / 3600;
        long m = seconds / 60 % 60;
        long s = seconds % 60;
        return h > 0 ? String.format(Locale.ROOT, "%d:%02d:%02d", h, m, s) : String.format(Locale.ROOT, "%d:%02d", m, s);
    }
}
