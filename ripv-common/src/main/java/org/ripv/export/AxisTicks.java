package org.ripv.export;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/** Where an axis of {@link SvgChart} has its ticks, and what they say. */
final class AxisTicks {
    private static final long SECOND = 1000;
    private static final long MINUTE = 60 * SECOND;
    private static final long HOUR = 60 * MINUTE;
    private static final long DAY = 24 * HOUR;
    private static final long[] TIME_STEPS = {SECOND, 2 * SECOND, 5 * SECOND, 10 * SECOND, 15 * SECOND, 30 * SECOND,
        MINUTE, 2 * MINUTE, 5 * MINUTE, 10 * MINUTE, 15 * MINUTE, 30 * MINUTE, HOUR, 2 * HOUR, 3 * HOUR, 6 * HOUR,
        12 * HOUR, DAY, 2 * DAY, 7 * DAY};

    private AxisTicks() {}

    /** Round tick values (1, 2, 2.5 or 5 times a power of ten apart), about {@code target} of them. */
    static double[] numbers(double lo, double hi, int target) {
        double raw = (hi - lo) / Math.max(1, target);
        double magnitude = Math.pow(10, Math.floor(Math.log10(raw)));
        double m = raw / magnitude;
        double step = (m <= 1 ? 1 : m <= 2 ? 2 : m <= 2.5 ? 2.5 : m <= 5 ? 5 : 10) * magnitude;
        double first = Math.ceil(lo / step - 1e-9);
        List<Double> ticks = new ArrayList<>();
        for (int i = 0; i < 1000; i++) {
            double t = (first + i) * step;
            if (t > hi + step * 1e-9) {
                break;
            }
            ticks.add(Math.abs(t) < step * 1e-9 ? 0.0 : t);
        }
        return ticks.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** Tick times (epoch milliseconds) at round seconds, minutes, hours or days, about {@code target} of them. */
    static double[] times(double lo, double hi, int target) {
        double raw = (hi - lo) / Math.max(1, target);
        long step = 0;
        for (long s : TIME_STEPS) {
            if (s >= raw) {
                step = s;
                break;
            }
        }
        if (step == 0) { // over a week a tick: a round number of days
            double days = raw / DAY;
            double magnitude = Math.pow(10, Math.floor(Math.log10(days)));
            double m = days / magnitude;
            step = (long) ((m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * magnitude) * DAY;
        }
        if (raw < SECOND) { // under a second a tick: plain numbers of milliseconds
            return numbers(lo, hi, target);
        }
        List<Double> ticks = new ArrayList<>();
        long first = Math.floorDiv((long) Math.ceil(lo), step) * step;
        for (long t = first; t <= hi && ticks.size() < 1000; t += step) {
            if (t >= lo) {
                ticks.add((double) t);
            }
        }
        return ticks.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** Seconds when ticks are closer than a minute; the date when they are a day or more apart or the axis spans days. */
    static String timePattern(double[] ticks) {
        long step = ticks.length > 1 ? (long) (ticks[1] - ticks[0]) : DAY;
        String pattern;
        if (step >= DAY) {
            pattern = "uuuu-MM-dd";
        } else if (step < SECOND) {
            pattern = "HH:mm:ss.SSS";
        } else if (ticks.length > 0 && Math.floorDiv((long) ticks[0], DAY) != Math.floorDiv((long) ticks[ticks.length - 1], DAY)) {
            pattern = step < MINUTE ? "MM-dd HH:mm:ss" : "MM-dd HH:mm";
        } else {
            pattern = step < MINUTE ? "HH:mm:ss" : "HH:mm";
        }
        return pattern;
    }

    /** Decimals enough to tell the ticks apart. */
    static int decimals(double[] ticks) {
        if (ticks.length < 2) {
            return 0;
        }
        double step = Math.abs(ticks[1] - ticks[0]);
        int d = (int) Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
        double scaled = step * Math.pow(10, d);
        if (Math.abs(scaled - Math.rint(scaled)) > 1e-6) {
            d++; // 2.5, 0.25, ...
        }
        return Math.min(d, 12);
    }

    static String label(double v, int decimals) {
        if (v != 0 && (Math.abs(v) >= 1e12 || decimals > 8)) {
            return String.format(Locale.ROOT, "%.4g", v);
        }
        return String.format(Locale.ROOT, "%." + decimals + "f", v + 0.0);
    }
}
