package org.ripv.services.datavis;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.charts.ChartRenderer;
import org.ripv.messages.ChartData;
import org.slf4j.LoggerFactory;

/**
 * Builds the {@link ChartData} a client redraws interactively from the same data file a worker
 * plots (after the service checked it), so the chart and the JPEG show the same numbers.
 *
 * <p>Bounded for the wire: a series of more than {@code limit} points ({@link
 * ChartData#MAX_POINTS_PER_SERIES}, less when there are many series) is reduced while the file is
 * streamed, with memory bounded by the limit: a line plot keeps the first, lowest, highest and last
 * point of each bucket of consecutive rows (it draws the same outline), and a gap in a bucket as a
 * NaN; a track keeps evenly spaced fixes and always the newest one.
 */
final class ChartDataBuilder {
    private static final Pattern UNIT = Pattern.compile("^(.*?)\\s*\\(([^()]*)\\)\\s*$");

    private ChartDataBuilder() {}

    /**
     * The chart of a data file that {@link DataFile#normalize} accepted.
     *
     * @param data    the operator's (or the server's) data file
     * @param checked what {@link DataFile#normalize} found: the labels with the {@code vis:} options
     *                applied, the columns and the rows
     */
    static ChartData build(byte[] data, DataFile.Summary checked) throws IOException, DataFormatException {
        PlotLabels labels = checked.labels();
        ChartData.Kind kind = kindOf(labels.style());
        double xScale = kind.timeAxis() ? 1000 : 1; // epoch seconds to a date axis' milliseconds
        int columns = checked.columns();
        int seriesCount = Math.max(1, columns - 1);
        int limit = Math.min(ChartData.MAX_POINTS_PER_SERIES, ChartData.MAX_POINTS / seriesCount);
        Reducer r = new Reducer(seriesCount, limit, checked.rows(), kind == ChartData.Kind.TRACK);
        long[] index = {0};
        DataFile.parse(DataFile.reader(data), (v, t) -> {
            long i = index[0]++;
            boolean oneColumn = v.length == 1;
            double x = (oneColumn ? i + 1 : v[0]) * xScale;
            for (int s = 0; s < seriesCount; s++) {
                double y = oneColumn ? v[0] : v[s + 1];
                boolean ok = Double.isFinite(x) && Double.isFinite(y);
                r.add(s, i, Double.isFinite(x) ? x : Double.NaN, ok ? y : Double.NaN);
            }
        });
        List<String> legend = labels.legend() == null ? List.of() : labels.legend();
        String yUnit = unitOf(labels.yLabel());
        List<ChartData.Series> series = new ArrayList<>();
        for (int s = 0; s < seriesCount; s++) {
            String given = s < legend.size() ? legend.get(s) : "";
            String name = given.isEmpty() ? "column " + (s + 2) : nameOf(given);
            String unit = unitOf(given).isEmpty() ? yUnit : unitOf(given);
            double[][] xy = r.points(s);
            series.add(new ChartData.Series(name, unit, xy[0], xy[1]));
        }
        ChartData.Mark newest = null;
        if (kind == ChartData.Kind.TRACK && Double.isFinite(r.lastX()) && Double.isFinite(r.lastY())) {
            newest = new ChartData.Mark(r.lastX(), r.lastY(), labels.mark() == null ? ChartRenderer.NEWEST_FIX : labels.mark());
        }
        return new ChartData(kind, labels.title(), labels.xLabel(), labels.yLabel(), series, newest, checked.rows(),
                r.reduced());
    }

    /**
     * The chart for a plot's reply, or null: for workers that draw on their own (Octave, MATLAB)
     * the client shows the JPEG only, and a chart that cannot be built never costs the plot.
     */
    static ChartData forReply(WorkerMode worker, byte[] data, DataFile.Summary checked) {
        if (worker != WorkerMode.BUILTIN) {
            return null;
        }
        try {
            return build(data, checked);
        } catch (IOException | DataFormatException | RuntimeException e) {
            LoggerFactory.getLogger(ChartDataBuilder.class).warn("no chart data for the reply: {}", e.toString());
            return null;
        }
    }

    static ChartData.Kind kindOf(String style) {
        if (style == null) {
            return ChartData.Kind.XY;
        }
        return switch (style) {
            case "time" -> ChartData.Kind.TIME;
            case "depth" -> ChartData.Kind.DEPTH;
            case "profile" -> ChartData.Kind.PROFILE;
            case "track" -> ChartData.Kind.TRACK;
            default -> ChartData.Kind.XY;
        };
    }

    /** "m_depth (m)" → "m"; "temperature" → "". */
    static String unitOf(String label) {
        if (label == null) {
            return "";
        }
        Matcher m = UNIT.matcher(label);
        return m.matches() ? m.group(2).trim() : "";
    }

    /** "m_depth (m)" → "m_depth". */
    static String nameOf(String label) {
        Matcher m = UNIT.matcher(label);
        return m.matches() && !m.group(1).isBlank() ? m.group(1).trim() : label;
    }

    /**
     * Keeps at most {@code limit} points a series while rows stream by. Below the limit every
     * point; above it, per bucket of rows, first/lowest/highest/last in row order with a NaN where
     * the bucket had a gap (line plots), or every k-th fix and the newest (tracks).
     */
    static final class Reducer {
        private final int limit;
        private final long rows;
        private final boolean track;
        private final boolean exact;
        private final double[][] xs;
        private final double[][] ys;
        private final int[] n;
        private final Bucket[] open;
        private final long bucketRows;
        private double lastX = Double.NaN;
        private double lastY = Double.NaN;

        Reducer(int series, int limit, long rows, boolean track) {
            this.limit = limit;
            this.rows = rows;
            this.track = track;
            this.exact = rows <= limit;
            int capacity = (int) Math.min(rows, limit) + 2;
            xs = new double[series][capacity];
            ys = new double[series][capacity];
            n = new int[series];
            open = new Bucket[series];
            // A line plot's bucket gives up to 5 points (4 and a gap): limit/5 buckets.
            bucketRows = exact ? 1 : track ? (rows + limit - 2) / (limit - 1) : (rows * 5 + limit - 1) / limit;
        }

        int series() {
            return xs.length;
        }

        boolean reduced() {
            return !exact;
        }

        double lastX() {
            return lastX;
        }

        double lastY() {
            return lastY;
        }

        void add(int s, long row, double x, double y) {
            if (!Double.isNaN(y)) {
                lastX = x;
                lastY = y;
            }
            if (exact) {
                put(s, x, y);
                return;
            }
            if (track) {
                // Every bucketRows-th row; the newest fix is added at the end (points()).
                if (row % bucketRows == 0) {
                    put(s, x, y);
                }
                return;
            }
            long b = row / bucketRows;
            Bucket k = open[s];
            if (k == null || k.index != b) {
                if (k != null) {
                    k.flush(this, s);
                }
                k = open[s] = new Bucket(b);
            }
            k.add(row, x, y);
        }

        private void put(int s, double x, double y) {
            if (n[s] < xs[s].length) {
                xs[s][n[s]] = x;
                ys[s][n[s]] = y;
                n[s]++;
            }
        }

        double[][] points(int s) {
            if (open[s] != null) {
                open[s].flush(this, s);
                open[s] = null;
            }
            if (track && !exact && Double.isFinite(lastX) && (n[s] == 0 || xs[s][n[s] - 1] != lastX
                    || ys[s][n[s] - 1] != lastY)) {
                if (n[s] >= limit) {
                    n[s] = limit - 1;
                }
                put(s, lastX, lastY);
            }
            int size = Math.min(n[s], limit);
            return new double[][] {Arrays.copyOf(xs[s], size), Arrays.copyOf(ys[s], size)};
        }

        /** One bucket of a line plot: first, lowest, highest, last and the first gap, by row. */
        private static final class Bucket {
            final long index;
            long firstRow = -1;
            long minRow;
            long maxRow;
            long lastRow;
            long gapRow = -1;
            double firstX;
            double firstY;
            double minX;
            double minY;
            double maxX;
            double maxY;
            double lastX;
            double lastY;

            Bucket(long index) {
                this.index = index;
            }

            void add(long row, double x, double y) {
                if (Double.isNaN(y)) {
                    if (gapRow < 0) {
                        gapRow = row;
                    }
                    return;
                }
                if (firstRow < 0) {
                    firstRow = minRow = maxRow = row;
                    firstX = minX = maxX = x;
                    firstY = minY = maxY = y;
                }
                if (y < minY) {
                    minRow = row;
                    minX = x;
                    minY = y;
                }
                if (y > maxY) {
                    maxRow = row;
                    maxX = x;
                    maxY = y;
                }
                lastRow = row;
                lastX = x;
                lastY = y;
            }

            void flush(Reducer r, int s) {
                long[] rowsOf = new long[5];
                double[] px = new double[5];
                double[] py = new double[5];
                int k = 0;
                if (firstRow >= 0) {
                    k = BucketPoints.insert(rowsOf, px, py, k, firstRow, firstX, firstY);
                    k = BucketPoints.insert(rowsOf, px, py, k, minRow, minX, minY);
                    k = BucketPoints.insert(rowsOf, px, py, k, maxRow, maxX, maxY);
                    k = BucketPoints.insert(rowsOf, px, py, k, lastRow, lastX, lastY);
                }
                if (gapRow >= 0) {
                    k = BucketPoints.insert(rowsOf, px, py, k, gapRow, k > 0 ? px[k - 1] : Double.NaN, Double.NaN);
                }
                for (int j = 0; j < k; j++) {
                    r.put(s, px[j], py[j]);
                }
            }
        }
    }
}
