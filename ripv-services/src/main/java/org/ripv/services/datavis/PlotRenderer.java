package org.ripv.services.datavis;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.jfree.chart.JFreeChart;
import org.ripv.charts.ChartRenderer;
import org.ripv.messages.ChartData;
import org.slf4j.LoggerFactory;

/**
 * The built-in worker's drawing: a data file to a plot drawn by RIPV's one chart renderer
 * ({@link ChartRenderer}, JFreeChart) as JPEG bytes, in the look of its {@code % plot:} style.
 *
 * <p>Memory stays bounded whatever the file's length: the file is read twice as a stream
 * (once to count, once to draw), and a file of more than {@link #EXACT_LIMIT} rows is reduced per
 * series to the first, lowest, highest and last point of each of {@code 2 x width} row buckets
 * (the "M4" reduction), which draws the same pixels as every point would. Gaps (NaN, Inf, empty
 * fields, blank lines) break the line.
 */
public final class PlotRenderer {
    /** Files up to this many rows are drawn point by point. */
    public static final int EXACT_LIMIT = 20_000;

    private PlotRenderer() {}

    /**
     * What was drawn.
     *
     * @param jpeg   the picture
     * @param rows   the file's rows
     * @param series how many series
     * @param points how many points went to the chart (after any reduction), all series
     */
    public record Rendered(byte[] jpeg, long rows, int series, long points) {}

    /** Draws a data file (canonical or as an operator wrote it) as a JPEG. */
    public static Rendered render(Path dataFile) throws IOException, DataFormatException {
        DataFile.Summary summary;
        try (BufferedReader in = Files.newBufferedReader(dataFile, StandardCharsets.UTF_8)) {
            summary = DataFile.check(in, (v, t) -> { }); // counting needs no numbers
        }
        PlotLabels labels = summary.labels();
        int width = labels.widthOrDefault();
        int height = labels.heightOrDefault();
        int columns = summary.columns();
        int series = Math.max(1, columns - 1);
        Collector collector = summary.rows() <= EXACT_LIMIT
                ? new Exact(series, (int) summary.rows())
                : new M4(series, 2 * width, summary.rows());
        long[] index = {0};
        double[] last = {Double.NaN, Double.NaN};
        double xScale = PlotStyles.xScale(labels); // seconds to the milliseconds of a date axis
        try (BufferedReader in = Files.newBufferedReader(dataFile, StandardCharsets.UTF_8)) {
            DataFile.parse(in, (v, t) -> {
                long i = index[0]++;
                double x = (columns == 1 ? i + 1 : v[0]) * xScale;
                for (int s = 0; s < series; s++) {
                    double y = columns == 1 ? v[0] : v[s + 1];
                    boolean ok = finite(x) && finite(y);
                    collector.add(s, i, ok ? x : Double.NaN, ok ? y : Double.NaN);
                    if (ok) {
                        last[0] = x;
                        last[1] = y;
                    }
                }
            });
        }
        List<String> given = labels.legend() == null ? List.of() : labels.legend();
        List<String> names = new ArrayList<>(series);
        List<double[][]> xy = new ArrayList<>(series);
        long points = 0;
        for (int s = 0; s < series; s++) {
            names.add(s < given.size() && !given.get(s).isEmpty() ? given.get(s) : "column " + (s + 2));
            double[][] one = collector.series(s);
            points += one[0].length;
            xy.add(one);
        }
        ChartData.Kind kind = ChartDataBuilder.kindOf(labels.style());
        ChartData.Mark newest = kind == ChartData.Kind.TRACK && finite(last[0]) && finite(last[1])
                ? new ChartData.Mark(last[0], last[1], labels.mark() == null ? ChartRenderer.NEWEST_FIX : labels.mark())
                : null;
        JFreeChart chart = ChartRenderer.picture(new ChartRenderer.Plot(kind, nz(labels.title()), nz(labels.xLabel()),
                nz(labels.yLabel()), names, xy, newest, labels.legend() != null || series > 1), width, height);
        return new Rendered(ChartRenderer.jpeg(chart, width, height), summary.rows(), series, points);
    }

    /**
     * Draws a small chart in memory, so the JVM loads JFreeChart, Java2D, the fonts and the JPEG
     * encoder before the first real plot (about 2 s on a slow machine).
     */
    public static void warmUp() {
        try {
            JFreeChart chart = ChartRenderer.chart(new ChartRenderer.Plot(ChartData.Kind.XY, "warm-up", "x", "y",
                    List.of("warm-up"), List.<double[][]>of(new double[][] {{0, 1, 2}, {0, 1, Double.NaN}}), null, true));
            ChartRenderer.jpeg(chart, 200, 150);
        } catch (IOException | RuntimeException e) {
            LoggerFactory.getLogger(PlotRenderer.class).debug("warm-up plot failed: {}", e.toString());
        }
    }

    private static boolean finite(double d) {
        return !Double.isNaN(d) && !Double.isInfinite(d);
    }

    private static String nz(String s) {
        return s == null ? "" : s;
    }

    /** Receives (row, x, y) per series in row order; NaN y is a gap. */
    private interface Collector {
        void add(int series, long row, double x, double y);

        double[][] series(int s);
    }

    /** Every point, for small files. */
    private static final class Exact implements Collector {
        private final double[][] xs;
        private final double[][] ys;

        Exact(int series, int rows) {
            xs = new double[series][rows];
            ys = new double[series][rows];
        }

        @Override
        public void add(int s, long row, double x, double y) {
            xs[s][(int) row] = x;
            ys[s][(int) row] = y;
        }

        @Override
        public double[][] series(int s) {
            return new double[][] {xs[s], ys[s]};
        }
    }

    /**
     * Per series and bucket of consecutive rows: the first, last, lowest and highest point, and
     * where the first gap was. Memory: 13 numbers per bucket per series, whatever the file's length.
     */
    private static final class M4 implements Collector {
        private final int buckets;
        private final long rows;
        private final Kept first;
        private final Kept last;
        private final Kept min;
        private final Kept max;
        private final long[][] gapI;

        M4(int series, int buckets, long rows) {
            this.buckets = buckets;
            this.rows = rows;
            first = new Kept(series, buckets);
            last = new Kept(series, buckets);
            min = new Kept(series, buckets);
            max = new Kept(series, buckets);
            gapI = Kept.unset(series, buckets);
        }

        @Override
        public void add(int s, long row, double x, double y) {
            int b = (int) (row * buckets / rows);
            if (Double.isNaN(y)) {
                if (gapI[s][b] < 0) {
                    gapI[s][b] = row;
                }
                return;
            }
            if (!first.has(s, b)) {
                first.keep(s, b, row, x, y);
                min.keep(s, b, row, x, y);
                max.keep(s, b, row, x, y);
            }
            if (y < min.y[s][b]) {
                min.keep(s, b, row, x, y);
            }
            if (y > max.y[s][b]) {
                max.keep(s, b, row, x, y);
            }
            last.keep(s, b, row, x, y);
        }

        @Override
        public double[][] series(int s) {
            double[] xs = new double[buckets * 5];
            double[] ys = new double[buckets * 5];
            int n = 0;
            long[] idx = new long[4];
            double[] px = new double[4];
            double[] py = new double[4];
            for (int b = 0; b < buckets; b++) {
                int k = 0;
                if (first.has(s, b)) {
                    k = first.insertInto(idx, px, py, k, s, b);
                    k = min.insertInto(idx, px, py, k, s, b);
                    k = max.insertInto(idx, px, py, k, s, b);
                    k = last.insertInto(idx, px, py, k, s, b);
                }
                long gap = gapI[s][b];
                boolean gapDone = gap < 0;
                for (int j = 0; j < k; j++) {
                    if (!gapDone && idx[j] > gap) {
                        xs[n] = px[j];
                        ys[n++] = Double.NaN; // the break comes before this point
                        gapDone = true;
                    }
                    xs[n] = px[j];
                    ys[n++] = py[j];
                }
                if (!gapDone) {
                    xs[n] = n > 0 ? xs[n - 1] : 0;
                    ys[n++] = Double.NaN;
                }
            }
            return new double[][] {Arrays.copyOf(xs, n), Arrays.copyOf(ys, n)};
        }
    }

    /** One of the points an M4 bucket keeps (its first, last, lowest or highest), per series and bucket: row, x, y. */
    private static final class Kept {
        private final long[][] row;
        private final double[][] x;
        private final double[][] y;

        Kept(int series, int buckets) {
            row = unset(series, buckets);
            x = new double[series][buckets];
            y = new double[series][buckets];
        }

        /** Rows per series and bucket, -1 where none is kept yet. */
        static long[][] unset(int series, int buckets) {
            long[][] a = new long[series][buckets];
            for (long[] r : a) {
                Arrays.fill(r, -1);
            }
            return a;
        }

        boolean has(int s, int b) {
            return row[s][b] >= 0;
        }

        void keep(int s, int b, long r, double px, double py) {
            row[s][b] = r;
            x[s][b] = px;
            y[s][b] = py;
        }

        /** Adds this bucket's point to the row-ordered {@code k} points ({@link BucketPoints#insert}). */
        int insertInto(long[] rows, double[] px, double[] py, int k, int s, int b) {
            return BucketPoints.insert(rows, px, py, k, row[s][b], x[s][b], y[s][b]);
        }
    }
}
