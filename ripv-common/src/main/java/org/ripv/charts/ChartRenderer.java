package org.ripv.charts;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.TimeZone;
import javax.imageio.IIOImage;
import javax.imageio.ImageIO;
import javax.imageio.ImageWriteParam;
import javax.imageio.ImageWriter;
import javax.imageio.stream.ImageOutputStream;
import org.jfree.chart.ChartUtils;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.annotations.XYPointerAnnotation;
import org.jfree.chart.annotations.XYShapeAnnotation;
import org.jfree.chart.axis.DateAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.labels.StandardXYToolTipGenerator;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.text.TextUtils;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.xy.DefaultXYDataset;
import org.jfree.data.xy.XYDataset;
import org.jfree.svg.SVGGraphics2D;
import org.ripv.messages.ChartData;

/**
 * RIPV's one chart renderer: a plot's series drawn by JFreeChart the same way wherever it is
 * drawn — the DataVisServer's built-in worker (its JPEG), the client's interactive DAV chart, and
 * the PNG and SVG files the GUI and the CLI export. By {@link ChartData.Kind}: a UTC date axis for
 * time, depth growing downwards, a track in MATLAB's blue with round markers at the aspect right
 * for its latitude ({@link #fitTrack}) and its newest fix in red: labelled in the legend of a chart
 * to move about in ({@link #chart}), beside the fix in a picture ({@link #picture}).
 *
 * <p>Texts come from data files and are hostile: control characters are dropped before they
 * reach a picture (an SVG is XML, which has no place for them; JFreeSVG escapes the rest).
 */
public final class ChartRenderer {
    /** A track's colour: MATLAB's and Octave's first line colour, as ripvOut.m draws it. */
    public static final Color TRACK = new Color(0, 114, 189);
    /** The newest fix's colour: the one red on a map. */
    public static final Color NEWEST = Color.RED;
    /** The legend key of the newest fix when its mark has no label of its own. */
    public static final String NEWEST_FIX = "newest fix";
    private static final float JPEG_QUALITY = 0.9f;

    static {
        // JFreeChart draws rotated text (the y axis' label) as glyph outlines by default, a
        // workaround for old JDKs; drawn as text, an SVG keeps it as text (searchable, selectable).
        TextUtils.setUseDrawRotatedStringWorkaround(false);
    }

    private ChartRenderer() {}

    /**
     * What to draw.
     *
     * @param kind    how (axes, direction, track)
     * @param title   the chart's title ("" for none)
     * @param xLabel  the x axis' label
     * @param yLabel  the y axis' label
     * @param names   the series' legend names, in dataset order (made distinct here)
     * @param xy      per series {x[], y[]}; x in epoch milliseconds for a time axis, NaN y a gap
     * @param newest  a track's newest fix, or null
     * @param legend  whether to show a legend (a {@link #chart} with a newest fix always has one)
     */
    public record Plot(ChartData.Kind kind, String title, String xLabel, String yLabel, List<String> names,
                       List<double[][]> xy, ChartData.Mark newest, boolean legend) {}

    /** The chart of a plot's data as a client receives it; a legend when it has several series or a newest fix. */
    public static JFreeChart chart(ChartData data) {
        List<String> names = data.series().stream().map(s -> s.name().isEmpty() ? "series" : s.name()).toList();
        List<double[][]> xy = data.series().stream().map(s -> new double[][] {s.x(), s.y()}).toList();
        return chart(new Plot(data.kind(), data.title(), data.xLabel(), data.yLabel(), names, xy, data.newest(),
                data.series().size() > 1));
    }

    /**
     * The chart of a plot to look at and move about in: pannable, with tooltips giving each
     * point's values, a track's newest fix a red dot labelled in the legend (a label beside it
     * would run off a zoomed plot).
     */
    public static JFreeChart chart(Plot p) {
        return chart(p, true);
    }

    /**
     * The chart of a plot as a picture of {@code width} x {@code height} (the worker's JPEG): a
     * track fitted to the picture's plot area ({@link #fitPicture}) with its newest fix circled
     * in red and labelled beside it, pointing away from the track's centre.
     */
    public static JFreeChart picture(Plot p, int width, int height) {
        JFreeChart chart = chart(p, false);
        fitPicture(chart, p.kind(), width, height);
        ChartData.Mark newest = p.newest();
        if (p.kind() == ChartData.Kind.TRACK && newest != null && Double.isFinite(newest.x()) && Double.isFinite(newest.y())) {
            label(chart.getXYPlot(), newest, Math.max(50, width - 110), Math.max(50, height - 110));
        }
        return chart;
    }

    private static void label(XYPlot plot, ChartData.Mark newest, double plotW, double plotH) {
        double x = newest.x();
        double y = newest.y();
        double spanX = plot.getDomainAxis().getRange().getLength();
        double spanY = plot.getRangeAxis().getRange().getLength();
        double cx = plot.getDomainAxis().getRange().getCentralValue();
        double rx = 5 * spanX / plotW; // a circle of 5 pixels' radius
        double ry = 5 * spanY / plotH;
        plot.addAnnotation(new XYShapeAnnotation(new Ellipse2D.Double(x - rx, y - ry, 2 * rx, 2 * ry),
                new BasicStroke(2f), NEWEST, NEWEST));
        String text = clean(newest.label());
        XYPointerAnnotation label = new XYPointerAnnotation(text.isBlank() ? NEWEST_FIX : text, x, y,
                x > cx ? Math.PI * 0.75 : Math.PI * 0.25);
        label.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
        label.setPaint(NEWEST.darker());
        label.setArrowPaint(NEWEST.darker());
        label.setTextAnchor(x > cx ? TextAnchor.BOTTOM_RIGHT : TextAnchor.BOTTOM_LEFT);
        plot.addAnnotation(label);
    }

    private static JFreeChart chart(Plot p, boolean newestInLegend) {
        DefaultXYDataset dataset = new DefaultXYDataset();
        Set<String> keys = new HashSet<>();
        for (int s = 0; s < p.names().size(); s++) {
            String name = clean(p.names().get(s));
            String key = name;
            for (int n = 2; !keys.add(key); n++) {
                key = name + " (" + n + ")"; // JFreeChart's series keys must differ
            }
            dataset.addSeries(key, p.xy().get(s));
        }
        int series = dataset.getSeriesCount();
        ChartData.Mark newest = newestInLegend ? p.newest() : null;
        if (newest != null) {
            // The legend labels it in full ("newest fix 2013-09-05 13:47:21 UTC (gps)"): a label
            // beside the point would run off the plot whatever side it took.
            String label = clean(newest.label());
            String key = label.isBlank() || keys.contains(label) ? NEWEST_FIX : label;
            dataset.addSeries(key, new double[][] {{newest.x()}, {newest.y()}});
        }
        XYPlot plot = new XYPlot(dataset, xAxis(p.kind(), clean(p.xLabel())), yAxis(p.kind(), clean(p.yLabel())),
                renderer(p.kind(), series, newest != null));
        plot.setBackgroundPaint(Color.WHITE);
        plot.setDomainGridlinePaint(Color.LIGHT_GRAY);
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        if (p.kind() == ChartData.Kind.TRACK) {
            plot.setDomainGridlineStroke(new BasicStroke(0.6f)); // a graticule
            plot.setRangeGridlineStroke(new BasicStroke(0.6f));
        }
        plot.setDomainPannable(true);
        plot.setRangePannable(true);
        String title = clean(p.title());
        JFreeChart chart = new JFreeChart(title.isEmpty() ? null : title, JFreeChart.DEFAULT_TITLE_FONT, plot,
                p.legend() || newest != null);
        chart.setBackgroundPaint(Color.WHITE);
        chart.setAntiAlias(true);
        return chart;
    }

    private static ValueAxis xAxis(ChartData.Kind kind, String label) {
        if (kind.timeAxis()) {
            DateAxis d = new DateAxis(label);
            d.setTimeZone(TimeZone.getTimeZone("UTC"));
            return d;
        }
        NumberAxis n = new NumberAxis(label);
        n.setAutoRangeIncludesZero(false);
        return n;
    }

    private static ValueAxis yAxis(ChartData.Kind kind, String label) {
        NumberAxis y = new NumberAxis(label);
        y.setAutoRangeIncludesZero(false);
        y.setInverted(kind.yInverted());
        return y;
    }

    /** Lines in JFreeChart's own colours (a track in blue, with markers); the newest fix last, a red dot. */
    private static XYLineAndShapeRenderer renderer(ChartData.Kind kind, int series, boolean newest) {
        boolean track = kind == ChartData.Kind.TRACK;
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(true, track);
        r.setDrawSeriesLineAsPath(true); // one path a series: tens of thousands of points repaint fast; NaN still breaks it
        for (int s = 0; s < series; s++) {
            r.setSeriesStroke(s, new BasicStroke(1.2f));
            if (track) {
                r.setSeriesShape(s, new Ellipse2D.Double(-2, -2, 4, 4));
            }
        }
        if (track && series > 0) {
            r.setSeriesPaint(0, TRACK); // not JFreeChart's first red: the newest fix is the red on a map
        }
        if (newest) {
            r.setSeriesLinesVisible(series, false);
            r.setSeriesShapesVisible(series, true);
            r.setSeriesShape(series, new Ellipse2D.Double(-6, -6, 12, 12));
            r.setSeriesPaint(series, NEWEST);
        }
        r.setDefaultToolTipGenerator(new StandardXYToolTipGenerator());
        return r;
    }

    /**
     * For a track: sets the axes' ranges around every point so that a kilometre is as long
     * east-west as north-south in a plot area of {@code width} x {@code height} pixels (one
     * degree of longitude is cos(latitude) of one of latitude). Other kinds: automatic ranges.
     */
    public static void fitTrack(JFreeChart chart, ChartData.Kind kind, double width, double height) {
        XYPlot plot = chart.getXYPlot();
        if (kind != ChartData.Kind.TRACK) {
            plot.getDomainAxis().setAutoRange(true);
            plot.getRangeAxis().setAutoRange(true);
            return;
        }
        XYDataset data = plot.getDataset();
        double minX = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int s = 0; s < data.getSeriesCount(); s++) {
            for (int i = 0; i < data.getItemCount(s); i++) {
                double x = data.getXValue(s, i);
                double y = data.getYValue(s, i);
                if (Double.isFinite(x) && Double.isFinite(y)) {
                    minX = Math.min(minX, x);
                    maxX = Math.max(maxX, x);
                    minY = Math.min(minY, y);
                    maxY = Math.max(maxY, y);
                }
            }
        }
        if (minX > maxX || width <= 0 || height <= 0) {
            return; // nothing to draw
        }
        double k = Math.max(0.01, Math.cos(Math.toRadians((minY + maxY) / 2)));
        double spanX = Math.max(maxX - minX, 1e-4) * 1.2;
        double spanY = Math.max(maxY - minY, 1e-4) * 1.2;
        if (spanX * k / spanY > width / height) {
            spanY = spanX * k * height / width;
        } else {
            spanX = spanY * width / height / k;
        }
        double cx = (minX + maxX) / 2;
        double cy = (minY + maxY) / 2;
        plot.getDomainAxis().setRange(cx - spanX / 2, cx + spanX / 2);
        plot.getRangeAxis().setRange(cy - spanY / 2, cy + spanY / 2);
    }

    /**
     * {@link #fitTrack} for a picture of {@code width} x {@code height} pixels whose plot area is
     * the picture less its axes, title and legend (about 110 pixels each way): the worker's JPEG
     * and the CLI's SVG, drawn without a panel to measure.
     */
    public static void fitPicture(JFreeChart chart, ChartData.Kind kind, int width, int height) {
        fitTrack(chart, kind, Math.max(50, width - 110), Math.max(50, height - 110));
    }

    /** The chart as a PNG of {@code width} x {@code height} pixels. */
    public static byte[] png(JFreeChart chart, int width, int height) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream(64 * 1024);
        ChartUtils.writeChartAsPNG(out, chart, width, height);
        return out.toByteArray();
    }

    /** The chart as a JPEG of {@code width} x {@code height} pixels (the worker's picture). */
    public static byte[] jpeg(JFreeChart chart, int width, int height) throws IOException {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            chart.draw(g, new Rectangle2D.Double(0, 0, width, height));
        } finally {
            g.dispose();
        }
        ImageWriter writer = ImageIO.getImageWritersByFormatName("jpeg").next();
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(64 * 1024);
        try (ImageOutputStream out = ImageIO.createImageOutputStream(bytes)) {
            writer.setOutput(out);
            ImageWriteParam p = writer.getDefaultWriteParam();
            p.setCompressionMode(ImageWriteParam.MODE_EXPLICIT);
            p.setCompressionQuality(JPEG_QUALITY);
            writer.write(null, new IIOImage(image, null, null), p);
        } finally {
            writer.dispose();
        }
        return bytes.toByteArray();
    }

    /**
     * The chart as an SVG document of {@code width} x {@code height} (JFreeSVG), for the ranges
     * its axes show now — a zoomed chart is exported as zoomed. UTF-8.
     */
    public static byte[] svg(JFreeChart chart, int width, int height) {
        SVGGraphics2D g = new SVGGraphics2D(width, height);
        chart.draw(g, new Rectangle2D.Double(0, 0, width, height));
        // no DOCTYPE (JFreeSVG's document names SVG 1.1's DTD): a reader never needs to fetch it
        return ("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + g.getSVGElement() + "\n").getBytes(StandardCharsets.UTF_8);
    }

    /** Text for a picture: control characters and lone surrogates dropped, white space kept as spaces. */
    static String clean(String s) {
        if (s == null) {
            return "";
        }
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (Character.isHighSurrogate(c) && i + 1 < s.length() && Character.isLowSurrogate(s.charAt(i + 1))) {
                b.append(c).append(s.charAt(++i));
            } else if (c == '\t' || c == '\n' || c == '\r') {
                b.append(' ');
            } else if (!Character.isISOControl(c) && !Character.isSurrogate(c) && c != '\uFFFE' && c != '\uFFFF') {
                b.append(c);
            }
        }
        return b.toString();
    }
}
