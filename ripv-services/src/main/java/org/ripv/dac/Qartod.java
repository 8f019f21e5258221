package org.ripv.dac;

import java.util.Arrays;
import java.util.List;

/**
 * The QARTOD tests the DAC asks for, as ioos_qc's {@code qartod} module computes them — same
 * edges, same NaN handling, same flags (1 pass, 2 not evaluated, 3 suspect, 4 fail, 9 missing):
 * a port of behaviour checked flag for flag against ioos_qc's output
 * ({@code QartodTest}, /work/shared/data/dac/qartod-vectors.json). Values are one profile's, in
 * time order; NaN is a missing value. Times are seconds since 1970.
 */
public final class Qartod {
    public static final byte GOOD = 1;
    public static final byte UNKNOWN = 2;
    public static final byte SUSPECT = 3;
    public static final byte FAIL = 4;
    public static final byte MISSING = 9;

    private Qartod() {
    }

    /** Outside the suspect span: 3; outside the fail span: 4 (spans sorted; a suspect span must lie within the fail span). */
    public static byte[] grossRange(double[] v, double[] failSpan, double[] suspectSpan) {
        double[] fail = sorted(failSpan);
        byte[] f = new byte[v.length];
        double[] sus = suspectSpan == null ? null : sorted(suspectSpan);
        if (sus != null && (sus[0] < fail[0] || sus[1] > fail[1])) {
            throw new IllegalArgumentException("gross_range_test: the suspect_span " + Arrays.toString(sus)
                    + " must fall within the fail_span " + Arrays.toString(fail));
        }
        for (int i = 0; i < v.length; i++) {
            double x = v[i];
            if (Double.isNaN(x)) {
                f[i] = MISSING;
            } else if (x < fail[0] || x > fail[1]) {
                f[i] = FAIL;
            } else if (sus != null && (x < sus[0] || x > sus[1])) {
                f[i] = SUSPECT;
            } else {
                f[i] = GOOD;
            }
        }
        return f;
    }

    /**
     * A value against its neighbours. {@code average}: |vᵢ − (vᵢ₋₁ + vᵢ₊₁)/2|; {@code differential}:
     * a value above (or below) both neighbours by more than the threshold, the smaller of the two
     * steps. First and last values, and a value beside a missing one, are not evaluated.
     */
    public static byte[] spike(double[] v, double suspect, double fail, String method) {
        boolean average = method == null || method.equals("average");
        if (!average && !method.equals("differential")) {
            throw new IllegalArgumentException("spike_test: method must be average or differential, not '" + method + "'");
        }
        int n = v.length;
        byte[] f = new byte[n];
        for (int i = 0; i < n; i++) {
            if (Double.isNaN(v[i])) {
                f[i] = MISSING;
                continue;
            }
            if (i == 0 || i == n - 1 || Double.isNaN(v[i - 1]) || Double.isNaN(v[i + 1])) {
                f[i] = UNKNOWN;
                continue;
            }
            double d;
            if (average) {
                d = Math.abs(v[i] - (v[i - 1] + v[i + 1]) / 2);
            } else {
                double before = v[i] - v[i - 1];
                double after = v[i] - v[i + 1];
                d = Math.signum(before) == Math.signum(after) && before != 0 ? Math.min(Math.abs(before), Math.abs(after)) : 0;
            }
            f[i] = d > fail ? FAIL : d > suspect ? SUSPECT : GOOD;
        }
        return f;
    }

    /** |vᵢ − vᵢ₋₁| / (tᵢ − tᵢ₋₁) above the threshold (units per second): 3. The time step is in whole seconds, as ioos_qc casts it. */
    public static byte[] rateOfChange(double[] v, double[] t, double threshold) {
        byte[] f = new byte[v.length];
        for (int i = 0; i < v.length; i++) {
            if (Double.isNaN(v[i])) {
                f[i] = MISSING;
                continue;
            }
            f[i] = GOOD;
            if (i > 0) {
                double dt = wholeSeconds(t[i] - t[i - 1]);
                double roc = Math.abs((v[i] - v[i - 1]) / dt);
                if (roc > threshold) {
                    f[i] = SUSPECT;
                }
            }
        }
        return f;
    }

    /**
     * A value whose window back over the threshold's number of samples (threshold seconds over the
     * median time step, in whole seconds) spans less than the tolerance: suspect, then fail. Fewer
     * than three values: all pass, as in ioos_qc.
     */
    public static byte[] flatLine(double[] v, double[] t, double suspectSeconds, double failSeconds, double tolerance) {
        int n = v.length;
        byte[] f = new byte[n];
        Arrays.fill(f, GOOD);
        if (n < 3) {
            return f;
        }
        double[] steps = new double[n - 1];
        for (int i = 1; i < n; i++) {
            steps[i - 1] = t[i] - t[i - 1];
        }
        double interval = wholeSeconds(median(steps));
        flag(v, f, (int) ((long) suspectSeconds / interval), tolerance, SUSPECT);
        flag(v, f, (int) ((long) failSeconds / interval), tolerance, FAIL);
        for (int i = 0; i < n; i++) {
            if (Double.isNaN(v[i])) {
                f[i] = MISSING;
            }
        }
        return f;
    }

    private static void flag(double[] v, byte[] f, int count, double tolerance, byte flag) {
        if (count < 0) {
            return;
        }
        for (int i = count; i < v.length; i++) {
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int j = i - count; j <= i; j++) {
                if (!Double.isNaN(v[j])) {
                    min = Math.min(min, v[j]);
                    max = Math.max(max, v[j]);
                }
            }
            if (min <= max && Math.abs(max - min) < tolerance) {
                f[i] = flag;
            }
        }
    }

    /**
     * The aggregate (QARTOD's primary flag), as ioos_qc's {@code qartod_compare}: the most severe
     * flag any test gave, in the order missing, not evaluated, pass, suspect, fail.
     */
    public static byte[] aggregate(List<byte[]> results, int n) {
        byte[] out = new byte[n];
        for (int i = 0; i < n; i++) {
            int best = 0;
            for (byte[] r : results) {
                best = Math.max(best, severity(r[i]));
            }
            out[i] = BY_SEVERITY[best];
        }
        return out;
    }

    /** Flags from the least severe to the most, as qartod_compare ranks them. */
    private static final byte[] BY_SEVERITY = {MISSING, UNKNOWN, GOOD, SUSPECT, FAIL};

    /** A flag's place in {@link #BY_SEVERITY}; 0 (as missing) for a value that is no flag. */
    private static int severity(byte flag) {
        return switch (flag) {
            case UNKNOWN -> 1;
            case GOOD -> 2;
            case SUSPECT -> 3;
            case FAIL -> 4;
            default -> 0;
        };
    }

    private static double wholeSeconds(double seconds) {
        return seconds < 0 ? Math.ceil(seconds) : Math.floor(seconds);
    }

    private static double median(double[] a) {
        double[] s = a.clone();
        Arrays.sort(s);
        int m = s.length / 2;
        return s.length % 2 == 1 ? s[m] : (s[m - 1] + s[m]) / 2;
    }

    private static double[] sorted(double[] span) {
        if (span == null || span.length != 2) {
            throw new IllegalArgumentException("a span is two numbers, not " + Arrays.toString(span));
        }
        return new double[] {Math.min(span[0], span[1]), Math.max(span[0], span[1])};
    }
}
