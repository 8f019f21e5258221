package org.ripv.client.charts;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import org.ripv.messages.ChartData;

/**
 * The value under the cursor: the chart's point nearest to it on the screen, in words
 * ("m_depth: 12.5 m at 2016-01-13 17:20:11 UTC"). Plain code, testable headless.
 *
 * @param series the series' name
 * @param index  the point's index in it
 * @param x      its x (epoch milliseconds on a time axis)
 * @param y      its y
 * @param text   what the panel shows
 */
public record Readout(String series, int index, double x, double y, String text) {
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm:ss", Locale.ROOT)
            .withZone(ZoneOffset.UTC);

    /**
     * The point nearest to ({@code x}, {@code y}) in data units, distance measured in pixels:
     * {@code xPerPixel} and {@code yPerPixel} are how many data units one pixel is on each axis.
     * Null when no point is within {@code maxPixels}.
     */
    public static Readout nearest(ChartData data, double x, double y, double xPerPixel, double yPerPixel, double maxPixels) {
        if (!(xPerPixel > 0) || !(yPerPixel > 0)) {
            return null;
        }
        double best = maxPixels * maxPixels;
        ChartData.Series bestSeries = null;
        int bestIndex = -1;
        for (ChartData.Series s : data.series()) {
            double[] xs = s.x();
            double[] ys = s.y();
            for (int i = 0; i < xs.length; i++) {
                double dx = (xs[i] - x) / xPerPixel;
                double dy = (ys[i] - y) / yPerPixel;
                double d = dx * dx + dy * dy;
                if (d <= best) { // NaN (a gap) never compares
                    best = d;
                    bestSeries = s;
                    bestIndex = i;
                }
            }
        }
        if (bestSeries == null) {
            return null;
        }
        double px = bestSeries.x()[bestIndex];
        double py = bestSeries.y()[bestIndex];
        return new Readout(bestSeries.name(), bestIndex, px, py, describe(data, bestSeries, px, py));
    }

    static String describe(ChartData data, ChartData.Series s, double x, double y) {
        String unit = s.unit().isEmpty() ? "" : " " + s.unit();
        if (data.kind() == ChartData.Kind.TRACK) {
            return s.name() + ": " + degrees(y, 'N', 'S') + ", " + degrees(x, 'E', 'W');
        }
        String at = data.kind().timeAxis() ? TIME.format(Instant.ofEpochMilli((long) x)) + " UTC" : number(x)
                + (data.xLabel().isEmpty() ? "" : " (" + data.xLabel() + ")");
        return s.name() + ": " + number(y) + unit + " at " + at;
    }

    private static String degrees(double v, char pos, char neg) {
        return String.format(Locale.ROOT, "%.5f° %c", Math.abs(v), v >= 0 ? pos : neg);
    }

    static String number(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e12) {
            return Long.toString((long) v);
        }
        String s = String.format(Locale.ROOT, "%.6g", v);
        if (s.contains(".") && !s.contains("e")) {
            s = s.replaceAll("0+$", "").replaceAll("\\.$", "");
        }
        return s;
    }
}
