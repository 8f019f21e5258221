package org.ripv.dac;

import java.util.ArrayList;
import java.util.List;

/**
 * Splits a pressure series into dives and climbs at its turning points, as pyglider's
 * {@code get_profiles} does: the pressure smoothed by a running mean ({@code filterLength}
 * samples, numpy's {@code convolve(..., 'same')}), a turning point where the smoothed first
 * difference changes sign, and a stretch between two turning points kept as a profile when it
 * has at least {@code minSamples} samples and spans more than {@code minDepthSpan} dbar.
 *
 * <p>One difference: pyglider splits a whole deployment, whose surfacings are turning points in
 * the series; a call's files hold one segment, which starts and ends at the surface, so the
 * series' first and last samples count as turning points too — once the pressure has turned at
 * least once. A series that never turns (a dive cut off before its bottom) gives no profile and
 * is refused.
 */
public final class ProfileSplitter {
    /** A profile: samples {@code from} to {@code to} inclusive; direction +1 a dive (pressure rising), −1 a climb. */
    public record Range(int from, int to, int direction) {
        public int size() {
            return to - from + 1;
        }
    }

    private final double minDepthSpan;
    private final int minSamples;
    private final int filterLength;

    public static final double DEFAULT_MIN_DEPTH_SPAN = 10;
    public static final int DEFAULT_MIN_SAMPLES = 14;
    public static final int DEFAULT_FILTER = 7;

    /** pyglider's defaults: 10 dbar, 14 samples, a 7-sample filter. */
    public static ProfileSplitter defaults() {
        return new ProfileSplitter(DEFAULT_MIN_DEPTH_SPAN, DEFAULT_MIN_SAMPLES, DEFAULT_FILTER);
    }

    public ProfileSplitter(double minDepthSpan, int minSamples, int filterLength) {
        if (!(minDepthSpan >= 0) || minSamples < 2 || filterLength < 1) {
            throw new IllegalArgumentException("a profile needs a depth span >= 0 dbar, at least 2 samples and a filter of at least 1 sample;"
                    + " got " + minDepthSpan + " dbar, " + minSamples + " samples, filter " + filterLength);
        }
        this.minDepthSpan = minDepthSpan;
        this.minSamples = minSamples;
        this.filterLength = filterLength;
    }

    /** The profiles of a pressure series (dbar, no NaN), in order; each sample in at most one. */
    public List<Range> split(double[] p, String where) throws DacException {
        int n = p.length;
        double[] s = smooth(p);
        List<Integer> turns = new ArrayList<>();
        turns.add(0);
        // pyglider's test is d[i] * d[i+1] < 0; a flat top (a zero difference) would hide a turn
        // from it, so the sign compared is that of the last difference that was not zero.
        // Within half a filter of either end the running mean sees numpy's zero padding, which
        // bends any series towards 0: a "turn" there is the filter's, not the glider's.
        int edge = filterLength / 2 + 1;
        double lastSign = 0;
        for (int i = edge; i + 1 < n - edge; i++) {
            double sign = Math.signum(s[i + 1] - s[i]);
            if (sign == 0) {
                continue;
            }
            if (lastSign != 0 && sign != lastSign && i > 0) {
                turns.add(i);
            }
            lastSign = sign;
        }
        if (turns.size() == 1) {
            throw new DacException(where + ": the pressure never turns (" + n + " samples, " + String.format(java.util.Locale.ROOT,
                    "%.1f to %.1f dbar", p[0], p[n - 1]) + "): no dive or climb to make a profile of");
        }
        turns.add(n - 1);
        List<Range> out = new ArrayList<>();
        for (int k = 0; k + 1 < turns.size(); k++) {
            int a = turns.get(k);
            int b = turns.get(k + 1);
            boolean last = k + 2 == turns.size();
            int to = last ? b : b - 1;
            double span = p[b] - p[a];
            if (b - a >= minSamples && Math.abs(span) > minDepthSpan) {
                out.add(new Range(a, to, span > 0 ? 1 : -1));
            }
        }
        return out;
    }

    /** numpy.convolve(p, ones(L)/L, 'same'): a centred running mean with zeros beyond the ends. */
    double[] smooth(double[] p) {
        int n = p.length;
        int l = filterLength;
        double[] out = new double[n];
        int shift = (l - 1) / 2;
        for (int i = 0; i < n; i++) {
            double sum = 0;
            for (int k = 0; k < l; k++) {
                int j = i + shift - k;
                if (j >= 0 && j < n) {
                    sum += p[j];
                }
            }
            out[i] = sum / l;
        }
        return out;
    }
}
