package org.ripv.export;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.ripv.messages.ChartData;

/**
 * A plot ({@link ChartData}) as an SVG 1.1 document, written from the data itself: the same
 * chart the GUI's DAV quadrant draws (title, axes with round tick values and labels with units,
 * grid, one polyline a series broken at gaps, the palette of the client's charts, a track's
 * newest fix marked and labelled with its time, depth growing downwards, a legend), for the
 * ranges and size of a {@link View} — the panel's current zoom, or {@link View#fit} for all data.
 *
 * <p>Every text comes from data files and is treated as hostile: XML-escaped, control characters
 * dropped. Lines are clipped to the plot area; pieces of line wholly outside it are left out, so a
 * zoomed view does not carry the whole series.
 */
public final class SvgChart {
    /** Series colours, in order (red is kept for the newest fix); the client's charts use the same. */
    private static final int[] PALETTE = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f,
        0xbcbd22, 0x17becf};
    /** The newest fix's colour. */
    public static final int NEWEST_COLOUR = 0xff0000;

    private static final int TICK_FONT = 11;
    private static final int LABEL_FONT = 12;
    private static final int TITLE_FONT = 14;
    private static final double CHAR = 0.62; // average glyph width of a sans-serif font, in font sizes
    private static final double MAX_PIXEL = 1e6; // coordinates beyond this are clamped (extreme zoom)
    private SvgChart() {}

    /** The colour (0xRRGGBB) of series number {@code index}. */
    public static int colour(int index) {
        return PALETTE[Math.floorMod(index, PALETTE.length)];
    }

    /**
     * What to draw: the axes' ranges (x in epoch milliseconds for a time axis) and the picture's
     * size in pixels. A track is drawn at the aspect right for its latitude: the range that is too
     * short for the plot area is widened about its centre (never narrowed).
     *
     * @param xMin   left end of the x axis
     * @param xMax   right end of the x axis
     * @param yMin   low end of the y axis (at the top when the chart's y grows downwards)
     * @param yMax   high end of the y axis
     * @param width  the picture's width, 200 to 20,000
     * @param height the picture's height, 150 to 20,000
     */
    public record View(double xMin, double xMax, double yMin, double yMax, int width, int height) {
        public View {
            if (!(Double.isFinite(xMin) && Double.isFinite(xMax) && xMin < xMax)) {
                throw new IllegalArgumentException("bad x range " + xMin + " .. " + xMax);
            }
            if (!(Double.isFinite(yMin) && Double.isFinite(yMax) && yMin < yMax)) {
                throw new IllegalArgumentException("bad y range " + yMin + " .. " + yMax);
            }
            if (width < 200 || width > 20_000 || height < 150 || height > 20_000) {
                throw new IllegalArgumentException("size " + width + " x " + height + "; 200 x 150 to 20000 x 20000");
            }
        }

        /**
         * Every point of the data with a 5 % margin each side (as JFreeChart's automatic range);
         * a track around its points with a 10 % margin.
         */
        public static View fit(ChartData data, int width, int height) {
            double[] b = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY};
            for (ChartData.Series s : data.series()) {
                for (int i = 0; i < s.size(); i++) {
                    include(b, s.x()[i], s.y()[i]);
                }
            }
            if (data.newest() != null) {
                include(b, data.newest().x(), data.newest().y());
            }
            if (b[0] > b[1]) {
                return new View(0, 1, 0, 1, width, height);
            }
            double margin = data.kind() == ChartData.Kind.TRACK ? 0.1 : 0.05;
            double[] x = padded(b[0], b[1], margin, data.kind().timeAxis() ? 60_000 : 1e-4);
            double[] y = padded(b[2], b[3], margin, 1e-4);
            return new View(x[0], x[1], y[0], y[1], width, height);
        }

        private static void include(double[] b, double x, double y) {
            if (Double.isFinite(x) && Double.isFinite(y)) {
                b[0] = Math.min(b[0], x);
                b[1] = Math.max(b[1], x);
                b[2] = Math.min(b[2], y);
                b[3] = Math.max(b[3], y);
            }
        }

        private static double[] padded(double lo, double hi, double margin, double minSpan) {
            double span = hi - lo;
            if (span < minSpan || span < Math.abs(hi) * 1e-9) {
                double half = Math.max(minSpan, Math.abs(hi) * 1e-6) / 2;
                return new double[] {lo - half, hi + half};
            }
            return new double[] {lo - span * margin, hi + span * margin};
        }
    }

    /** The chart as an SVG document (UTF-8 once encoded; write it with {@code StandardCharsets.UTF_8}). */
    public static String svg(ChartData data, View view) {
        return new Writer(data, view).write();
    }

    /** One rendering: the layout worked out from the data, then the elements in drawing order. */
    private static final class Writer {
        private final ChartData data;
        private final int width;
        private final int height;
        private final StringBuilder out;
        private double xMin;
        private double xMax;
        private double yMin;
        private double yMax;
        private double left;
        private double top;
        private double pw;
        private double ph;

        Writer(ChartData data, View v) {
            this.data = data;
            this.width = v.width();
            this.height = v.height();
            this.xMin = v.xMin();
            this.xMax = v.xMax();
            this.yMin = v.yMin();
            this.yMax = v.yMax();
            this.out = new StringBuilder(4096 + (int) Math.min(64_000_000, data.points() * 16));
        }

        String write() {
            List<LegendItem> legend = legendItems();
            List<List<LegendItem>> rows = legendRows(legend);
            top = data.title().isEmpty() ? 14 : 36;
            double legendHeight = rows.isEmpty() ? 0 : rows.size() * 17 + 8;
            double bottom = 24 + (data.xLabel().isEmpty() ? 0 : 18) + legendHeight + 8;
            ph = Math.max(40, height - top - bottom);
            double[] yTicks = AxisTicks.numbers(yMin, yMax, Math.max(2, (int) (ph / 45)));
            int yDecimals = AxisTicks.decimals(yTicks);
            double tickWidth = 0;
            for (double t : yTicks) {
                tickWidth = Math.max(tickWidth, textWidth(AxisTicks.label(t, yDecimals), TICK_FONT));
            }
            left = 12 + (data.yLabel().isEmpty() ? 0 : 20) + tickWidth + 8;
            pw = Math.max(40, width - left - 24);
            if (data.kind() == ChartData.Kind.TRACK) {
                aspect();
                yTicks = AxisTicks.numbers(yMin, yMax, Math.max(2, (int) (ph / 45)));
                yDecimals = AxisTicks.decimals(yTicks);
            }
            head();
            grid(yTicks, yDecimals);
            series();
            newest();
            plotFrame();
            legend(rows, top + ph + 24 + (data.xLabel().isEmpty() ? 0 : 18) + 8);
            out.append("</svg>\n");
            return out.toString();
        }

        /** A track's ranges widened so a kilometre is as long east-west as north-south. */
        private void aspect() {
            double k = Math.max(0.01, Math.cos(Math.toRadians(Math.max(-89.9, Math.min(89.9, (yMin + yMax) / 2)))));
            double spanX = xMax - xMin;
            double spanY = yMax - yMin;
            if (spanX * k / spanY > pw / ph) {
                double grow = (spanX * k * ph / pw - spanY) / 2;
                yMin -= grow;
                yMax += grow;
            } else {
                double grow = (spanY * pw / ph / k - spanX) / 2;
                xMin -= grow;
                xMax += grow;
            }
        }

        private void head() {
            out.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
            out.append("<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"").append(width)
                    .append("\" height=\"").append(height).append("\" viewBox=\"0 0 ").append(width).append(' ')
                    .append(height).append("\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n");
            if (!data.title().isEmpty()) {
                out.append("<title>").append(escape(data.title())).append("</title>\n");
            }
            out.append("<defs>\n<clipPath id=\"plot-area\"><rect x=\"").append(fmt(left)).append("\" y=\"")
                    .append(fmt(top)).append("\" width=\"").append(fmt(pw)).append("\" height=\"").append(fmt(ph))
                    .append("\"/></clipPath>\n");
            if (data.kind() == ChartData.Kind.TRACK) {
                for (int s = 0; s < data.series().size(); s++) {
                    out.append("<marker id=\"dot-").append(s).append("\" markerUnits=\"userSpaceOnUse\" markerWidth=\"6\""
                            + " markerHeight=\"6\" refX=\"3\" refY=\"3\" overflow=\"visible\"><circle cx=\"3\" cy=\"3\" r=\"2\""
                            + " fill=\"").append(hex(colour(s))).append("\"/></marker>\n");
                }
            }
            out.append("</defs>\n");
            out.append("<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
            if (!data.title().isEmpty()) {
                out.append("<text class=\"title\" x=\"").append(fmt(width / 2.0)).append("\" y=\"24\" text-anchor=\"middle\""
                        + " font-size=\"").append(TITLE_FONT).append("\" font-weight=\"bold\">").append(escape(data.title()))
                        .append("</text>\n");
            }
            out.append("<rect class=\"plot-background\" x=\"").append(fmt(left)).append("\" y=\"").append(fmt(top))
                    .append("\" width=\"").append(fmt(pw)).append("\" height=\"").append(fmt(ph)).append("\" fill=\"#ffffff\"/>\n");
        }

        private void grid(double[] yTicks, int yDecimals) {
            boolean time = data.kind().timeAxis();
            int target = Math.max(2, (int) (pw / (time ? 110 : 80)));
            double[] xTicks = time ? AxisTicks.times(xMin, xMax, target) : AxisTicks.numbers(xMin, xMax, target);
            String pattern = time ? AxisTicks.timePattern(xTicks) : "";
            DateTimeFormatter timeFormat = time ? DateTimeFormatter.ofPattern(pattern, Locale.ROOT).withZone(ZoneOffset.UTC) : null;
            int xDecimals = AxisTicks.decimals(xTicks);
            out.append("<g class=\"grid\" stroke=\"#d3d3d3\" stroke-width=\"0.8\">\n");
            for (double t : xTicks) {
                double x = px(t);
                out.append("<line x1=\"").append(fmt(x)).append("\" y1=\"").append(fmt(top)).append("\" x2=\"").append(fmt(x))
                        .append("\" y2=\"").append(fmt(top + ph)).append("\"/>\n");
            }
            for (double t : yTicks) {
                double y = py(t);
                out.append("<line x1=\"").append(fmt(left)).append("\" y1=\"").append(fmt(y)).append("\" x2=\"")
                        .append(fmt(left + pw)).append("\" y2=\"").append(fmt(y)).append("\"/>\n");
            }
            out.append("</g>\n");
            out.append("<g class=\"x-ticks\" font-size=\"").append(TICK_FONT).append("\" text-anchor=\"middle\" fill=\"#333333\">\n");
            for (double t : xTicks) {
                String label = time ? timeFormat.format(Instant.ofEpochMilli((long) t)) : AxisTicks.label(t, xDecimals);
                out.append("<text x=\"").append(fmt(px(t))).append("\" y=\"").append(fmt(top + ph + 15)).append("\">")
                        .append(escape(label)).append("</text>\n");
            }
            out.append("</g>\n");
            out.append("<g class=\"y-ticks\" font-size=\"").append(TICK_FONT).append("\" text-anchor=\"end\" fill=\"#333333\">\n");
            for (double t : yTicks) {
                out.append("<text x=\"").append(fmt(left - 6)).append("\" y=\"").append(fmt(py(t) + 4)).append("\">")
                        .append(escape(AxisTicks.label(t, yDecimals))).append("</text>\n");
            }
            out.append("</g>\n");
            String xLabel = data.xLabel();
            if (time && xTicks.length > 0 && !pattern.contains("dd")) {
                // Ticks give only the time of day: the axis says which day.
                String first = DateTimeFormatter.ISO_LOCAL_DATE.withZone(ZoneOffset.UTC).format(Instant.ofEpochMilli((long) xMin));
                String last = DateTimeFormatter.ISO_LOCAL_DATE.withZone(ZoneOffset.UTC).format(Instant.ofEpochMilli((long) xMax));
                xLabel = (xLabel.isEmpty() ? "time (UTC)" : xLabel) + ", " + (first.equals(last) ? first : first + " to " + last);
            }
            if (!xLabel.isEmpty()) {
                out.append("<text class=\"x-label\" x=\"").append(fmt(left + pw / 2)).append("\" y=\"").append(fmt(top + ph + 34))
                        .append("\" text-anchor=\"middle\" font-size=\"").append(LABEL_FONT).append("\">").append(escape(xLabel))
                        .append("</text>\n");
            }
            if (!data.yLabel().isEmpty()) {
                double x = 12 + LABEL_FONT;
                double y = top + ph / 2;
                out.append("<text class=\"y-label\" x=\"").append(fmt(x)).append("\" y=\"").append(fmt(y))
                        .append("\" transform=\"rotate(-90 ").append(fmt(x)).append(' ').append(fmt(y))
                        .append(")\" text-anchor=\"middle\" font-size=\"").append(LABEL_FONT).append("\">")
                        .append(escape(data.yLabel())).append("</text>\n");
            }
        }

        /** One polyline per run of points without a gap, the pieces outside the plot area left out. */
        private void series() {
            out.append("<g class=\"plot\" clip-path=\"url(#plot-area)\" fill=\"none\" stroke-width=\"1.2\""
                    + " stroke-linecap=\"round\" stroke-linejoin=\"round\">\n");
            boolean track = data.kind() == ChartData.Kind.TRACK;
            for (int s = 0; s < data.series().size(); s++) {
                ChartData.Series series = data.series().get(s);
                out.append("<g class=\"series\" stroke=\"").append(hex(colour(s))).append('"');
                if (track) {
                    out.append(" marker-start=\"url(#dot-").append(s).append(")\" marker-mid=\"url(#dot-").append(s)
                            .append(")\" marker-end=\"url(#dot-").append(s).append(")\"");
                }
                out.append(">\n");
                polylines(series.x(), series.y());
                out.append("</g>\n");
            }
            out.append("</g>\n");
        }

        private void polylines(double[] xs, double[] ys) {
            int n = xs.length;
            int open = -1; // start of the polyline being written, -1 when none
            for (int i = 0; i < n; i++) {
                if (!(Double.isFinite(xs[i]) && Double.isFinite(ys[i]))) {
                    open = close(open);
                    continue;
                }
                double x = px(xs[i]);
                double y = py(ys[i]);
                boolean nextGood = i + 1 < n && Double.isFinite(xs[i + 1]) && Double.isFinite(ys[i + 1]);
                if (!nextGood) {
                    if (open >= 0) {
                        point(x, y); // the piece that led here was visible
                    } else if (i == 0 || !(Double.isFinite(xs[i - 1]) && Double.isFinite(ys[i - 1]))) {
                        if (inside(x, y, x, y)) { // a point alone: a dot
                            open = start(x, y);
                            point(x, y);
                        }
                    }
                    open = close(open);
                    continue;
                }
                double x2 = px(xs[i + 1]);
                double y2 = py(ys[i + 1]);
                if (inside(x, y, x2, y2)) {
                    if (open < 0) {
                        open = start(x, y);
                    } else {
                        point(x, y);
                    }
                } else if (open >= 0) {
                    point(x, y);
                    open = close(open);
                }
            }
            close(open);
        }

        private int start(double x, double y) {
            int at = out.length();
            out.append("<polyline points=\"");
            coord(x);
            out.append(',');
            coord(y);
            return at;
        }

        private void point(double x, double y) {
            out.append(' ');
            coord(x);
            out.append(',');
            coord(y);
        }

        private int close(int open) {
            if (open >= 0) {
                out.append("\"/>\n");
            }
            return -1;
        }

        /** Whether the box around two points meets the plot area (with a margin for the line's width and marks). */
        private boolean inside(double x1, double y1, double x2, double y2) {
            double m = 4;
            return Math.max(x1, x2) >= left - m && Math.min(x1, x2) <= left + pw + m && Math.max(y1, y2) >= top - m
                    && Math.min(y1, y2) <= top + ph + m;
        }

        private void newest() {
            ChartData.Mark mark = data.newest();
            if (mark == null || !Double.isFinite(mark.x()) || !Double.isFinite(mark.y())) {
                return;
            }
            double x = px(mark.x());
            double y = py(mark.y());
            if (!inside(x, y, x, y)) {
                return; // zoomed away from it: the legend still names it
            }
            out.append("<g class=\"newest\" clip-path=\"url(#plot-area)\">\n<circle cx=\"").append(fmt(x)).append("\" cy=\"")
                    .append(fmt(y)).append("\" r=\"6\" fill=\"").append(hex(NEWEST_COLOUR)).append("\"/>\n");
            String label = markLabel(mark);
            double w = textWidth(label, TICK_FONT);
            // Of the four places beside the dot, the one inside the plot covering the fewest points.
            double bestX = 0;
            double bestY = 0;
            boolean rightOf = true;
            long best = Long.MAX_VALUE;
            for (int place = 0; place < 4; place++) {
                boolean right = place % 2 == 0;
                double bx = right ? x + 8 : x - 8 - w - 4;
                double by = place < 2 ? y - 8 - TICK_FONT - 4 : y + 8;
                long cost = covered(bx, by, w + 4, TICK_FONT + 4);
                if (bx < left || bx + w + 4 > left + pw || by < top || by + TICK_FONT + 4 > top + ph) {
                    cost += 1_000_000; // cut by the plot's edge
                }
                if (cost < best) {
                    best = cost;
                    bestX = bx;
                    bestY = by;
                    rightOf = right;
                }
            }
            double bx = bestX;
            double tx = rightOf ? bx + 2 : bx + w + 2;
            double ty = bestY + TICK_FONT;
            out.append("<rect x=\"").append(fmt(bx)).append("\" y=\"").append(fmt(ty - TICK_FONT)).append("\" width=\"")
                    .append(fmt(w + 4)).append("\" height=\"").append(TICK_FONT + 4)
                    .append("\" fill=\"#ffffff\" fill-opacity=\"0.8\"/>\n");
            out.append("<text class=\"newest-label\" x=\"").append(fmt(tx)).append("\" y=\"").append(fmt(ty))
                    .append("\" font-size=\"").append(TICK_FONT).append("\" text-anchor=\"").append(rightOf ? "start" : "end")
                    .append("\" fill=\"#b00000\">").append(escape(label)).append("</text>\n</g>\n");
        }

        /** Points of the chart drawn within a box (pixels), to keep the newest fix's label off the line. */
        private long covered(double bx, double by, double bw, double bh) {
            long n = 0;
            for (ChartData.Series series : data.series()) {
                for (int i = 0; i < series.size(); i++) {
                    double x = px(series.x()[i]);
                    double y = py(series.y()[i]);
                    if (x >= bx && x <= bx + bw && y >= by && y <= by + bh) {
                        n++;
                    }
                }
            }
            return n;
        }

        private void plotFrame() {
            out.append("<rect class=\"plot-frame\" x=\"").append(fmt(left)).append("\" y=\"").append(fmt(top)).append("\" width=\"")
                    .append(fmt(pw)).append("\" height=\"").append(fmt(ph)).append("\" fill=\"none\" stroke=\"#808080\"/>\n");
        }

        private record LegendItem(String text, int colour, boolean dot, boolean line) {}

        /** As the client's chart: a legend when there is more than one series or a newest fix. */
        private List<LegendItem> legendItems() {
            List<LegendItem> items = new ArrayList<>();
            if (data.series().size() <= 1 && data.newest() == null) {
                return items;
            }
            boolean track = data.kind() == ChartData.Kind.TRACK;
            for (int s = 0; s < data.series().size(); s++) {
                ChartData.Series series = data.series().get(s);
                String name = series.name().isEmpty() ? "series" : series.name();
                String unit = series.unit();
                if (!unit.isEmpty() && !name.endsWith("(" + unit + ")")) {
                    name += " (" + unit + ")";
                }
                items.add(new LegendItem(name, colour(s), track, true));
            }
            if (data.newest() != null) {
                items.add(new LegendItem(markLabel(data.newest()), NEWEST_COLOUR, true, false));
            }
            return items;
        }

        /** The items in rows across the picture; rows beyond a third of its height become "and N more". */
        private List<List<LegendItem>> legendRows(List<LegendItem> items) {
            List<List<LegendItem>> rows = new ArrayList<>();
            int maxRows = Math.max(1, height / 3 / 17);
            double room = width - 24;
            List<LegendItem> row = new ArrayList<>();
            double used = 0;
            for (int i = 0; i < items.size(); i++) {
                double w = itemWidth(items.get(i));
                if (!row.isEmpty() && used + w > room) {
                    rows.add(row);
                    row = new ArrayList<>();
                    used = 0;
                    if (rows.size() == maxRows) {
                        List<LegendItem> last = rows.get(rows.size() - 1);
                        last.add(new LegendItem("and " + (items.size() - i) + " more", 0x333333, false, false));
                        return rows;
                    }
                }
                row.add(items.get(i));
                used += w;
            }
            if (!row.isEmpty()) {
                rows.add(row);
            }
            return rows;
        }

        private static double itemWidth(LegendItem item) {
            return 30 + Math.min(textWidth(item.text(), TICK_FONT), 400) + 16;
        }

        private void legend(List<List<LegendItem>> rows, double y0) {
            if (rows.isEmpty()) {
                return;
            }
            out.append("<g class=\"legend\" font-size=\"").append(TICK_FONT).append("\">\n");
            double y = y0 + 12;
            for (List<LegendItem> row : rows) {
                double total = 0;
                for (LegendItem item : row) {
                    total += itemWidth(item);
                }
                double x = Math.max(12, (width - total) / 2);
                for (LegendItem item : row) {
                    String c = hex(item.colour());
                    if (item.line()) {
                        out.append("<line x1=\"").append(fmt(x)).append("\" y1=\"").append(fmt(y - 4)).append("\" x2=\"")
                                .append(fmt(x + 24)).append("\" y2=\"").append(fmt(y - 4)).append("\" stroke=\"").append(c)
                                .append("\" stroke-width=\"1.5\"/>\n");
                    }
                    if (item.dot()) {
                        out.append("<circle cx=\"").append(fmt(x + 12)).append("\" cy=\"").append(fmt(y - 4)).append("\" r=\"")
                                .append(item.line() ? "2.5" : "5").append("\" fill=\"").append(c).append("\"/>\n");
                    }
                    out.append("<text x=\"").append(fmt(x + 30)).append("\" y=\"").append(fmt(y)).append("\">")
                            .append(escape(item.text())).append("</text>\n");
                    x += itemWidth(item);
                }
                y += 17;
            }
            out.append("</g>\n");
        }

        private double px(double x) {
            return clamp(left + (x - xMin) / (xMax - xMin) * pw);
        }

        private double py(double y) {
            double f = (y - yMin) / (yMax - yMin);
            return clamp(data.kind().yInverted() ? top + f * ph : top + ph - f * ph);
        }

        private static double clamp(double v) {
            return Math.max(-MAX_PIXEL, Math.min(MAX_PIXEL, v));
        }

        /** A coordinate to a tenth of a pixel, written without String.format (a chart has up to 200,000 points). */
        private void coord(double v) {
            long r = Math.round(v * 10);
            if (r < 0) {
                out.append('-');
                r = -r;
            }
            out.append(r / 10);
            if (r % 10 != 0) {
                out.append('.').append(r % 10);
            }
        }

        private static String fmt(double v) {
            long r = Math.round(v * 10);
            return r % 10 == 0 ? Long.toString(r / 10) : Double.toString(r / 10.0);
        }
    }

    private static String markLabel(ChartData.Mark mark) {
        return mark.label().isBlank() ? "newest fix" : mark.label();
    }

    private static double textWidth(String s, int fontSize) {
        return s.length() * fontSize * CHAR;
    }

    private static String hex(int rgb) {
        return String.format(Locale.ROOT, "#%06x", rgb & 0xffffff);
    }

    /**
     * Text for an SVG text node or attribute: &amp;, &lt;, &gt; and quotes escaped, control
     * characters (C0 — tab and line breaks become spaces — DEL, C1), lone surrogates and the
     * non-characters U+FFFE/U+FFFF dropped, so no data can end the element or break the XML.
     */
    static String escape(String s) {
        StringBuilder b = new StringBuilder(s.length() + 16);
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '&' -> b.append("&amp;");
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '"' -> b.append("&quot;");
                case '\'' -> b.append("&apos;");
                case '\t', '\n', '\r' -> b.append(' ');
                default -> {
                    if (c < 0x20 || (c >= 0x7f && c <= 0x9f) || c == 0xfffe || c == 0xffff) {
                        continue;
                    }
                    if (Character.isHighSurrogate(c) && i + 1 < s.length() && Character.isLowSurrogate(s.charAt(i + 1))) {
                        b.append(c).append(s.charAt(++i));
                    } else if (!Character.isSurrogate(c)) {
                        b.append(c);
                    }
                }
            }
        }
        return b.toString();
    }
}
