package org.ripv.client.charts;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.geom.Ellipse2D;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.HashSet;
import java.util.Set;
import java.util.TimeZone;
import org.jfree.chart.ChartUtils;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.DateAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.labels.StandardXYToolTipGenerator;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.data.Range;
import org.jfree.data.xy.DefaultXYDataset;
import org.ripv.export.SvgChart;
import org.ripv.messages.ChartData;

/**
 * Builds the interactive chart for a {@link ChartData} the way the built-in worker draws its JPEG
 * (docs/datavis.md): a UTC date axis for time, depth downwards, a track at the aspect right for
 * its latitude with the newest fix marked in red and labelled in the legend; and writes it as PNG
 * (JFreeChart) or SVG ({@link SvgChart}, from the data). Plain JFreeChart objects, no Swing: works headless.
 */
public final class Charts {
    /** The key of the newest fix's one-point series (drawn last, in red) when its mark has no label of its own. */
    public static final String NEWEST = "newest fix";

    private Charts() {}

    /** The chart for this data, pannable, with tooltips giving each point's values. */
    public static JFreeChart chart(ChartData data) {
        DefaultXYDataset dataset = new DefaultXYDataset();
        Set<String> keys = new HashSet<>();
        for (ChartData.Series s : data.series()) {
            String key = s.name().isEmpty() ? "series" : s.name();
            for (int n = 2; !keys.add(key); n++) {
                key = s.name() + " (" + n + ")"; // JFreeChart's series keys must differ
            }
            dataset.addSeries(key, new double[][] {s.x(), s.y()});
        }
        ChartData.Mark newest = data.newest();
        if (newest != null) {
            // The legend labels it in full ("newest fix 2013-09-05 13:47:21 UTC (gps)"): a label
            // beside the point would run off the plot whatever side it took.
            String key = newest.label().isBlank() || keys.contains(newest.label()) ? NEWEST : newest.label();
            dataset.addSeries(key, new double[][] {{newest.x()}, {newest.y()}});
        }
        ValueAxis x;
        if (data.kind().timeAxis()) {
            DateAxis d = new DateAxis(data.xLabel());
            d.setTimeZone(TimeZone.getTimeZone("UTC"));
            x = d;
        } else {
            NumberAxis n = new NumberAxis(data.xLabel());
            n.setAutoRangeIncludesZero(false);
            x = n;
        }
        NumberAxis y = new NumberAxis(data.yLabel());
        y.setAutoRangeIncludesZero(false);
        y.setInverted(data.kind().yInverted());
        boolean track = data.kind() == ChartData.Kind.TRACK;
        XYLineAndShapeRenderer r = new XYLineAndShapeRenderer(true, track);
        r.setDrawSeriesLineAsPath(true); // one path a series: tens of thousands of points repaint fast; NaN still breaks it
        for (int s = 0; s < data.series().size(); s++) {
            r.setSeriesStroke(s, new BasicStroke(1.2f));
            r.setSeriesPaint(s, new Color(SvgChart.colour(s))); // the SVG's palette
            if (track) {
                r.setSeriesShape(s, new Ellipse2D.Double(-2, -2, 4, 4));
            }
        }
        if (newest != null) {
            int s = dataset.getSeriesCount() - 1;
            r.setSeriesLinesVisible(s, false);
            r.setSeriesShapesVisible(s, true);
            r.setSeriesShape(s, new Ellipse2D.Double(-6, -6, 12, 12));
            r.setSeriesPaint(s, new Color(SvgChart.NEWEST_COLOUR));
        }
        r.setDefaultToolTipGenerator(new StandardXYToolTipGenerator());
        XYPlot plot = new XYPlot(dataset, x, y, r);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setDomainGridlinePaint(Color.LIGHT_GRAY);
        plot.setRangeGridlinePaint(Color.LIGHT_GRAY);
        plot.setDomainPannable(true);
        plot.setRangePannable(true);
        boolean legend = data.series().size() > 1 || newest != null;
        JFreeChart chart = new JFreeChart(data.title().isEmpty() ? null : data.title(), JFreeChart.DEFAULT_TITLE_FONT, plot,
                legend);
        chart.setBackgroundPaint(Color.WHITE);
        chart.setAntiAlias(true);
        return chart;
    }

    /**
     * For a track: sets the axes' ranges around every point so that a kilometre is as long
     * east-west as north-south in a plot area of {@code width} x {@code height} pixels (one
     * degree of longitude is cos(latitude) of one of latitude). Other kinds: automatic ranges.
     */
    public static void fit(JFreeChart chart, ChartData data, double width, double height) {
        XYPlot plot = chart.getXYPlot();
        if (data.kind() != ChartData.Kind.TRACK) {
            plot.getDomainAxis().setAutoRange(true);
            plot.getRangeAxis().setAutoRange(true);
            return;
        }
        double minX = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (ChartData.Series s : data.series()) {
            for (int i = 0; i < s.size(); i++) {
                double px = s.x()[i];
                double py = s.y()[i];
                if (Double.isFinite(px) && Double.isFinite(py)) {
                    minX = Math.min(minX, px);
                    maxX = Math.max(maxX, px);
                    minY = Math.min(minY, py);
                    maxY = Math.max(maxY, py);
                }
            }
        }
        if (minX > maxX || width <= 0 || height <= 0) {
            return;
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

    /** The chart as a PNG of {@code width} x {@code height} pixels. */
    public static byte[] png(JFreeChart chart, int width, int height) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream(64 * 1024);
        ChartUtils.writeChartAsPNG(out, chart, width, height);
        return out.toByteArray();
    }

    /**
     * The chart as an SVG document of {@code width} x {@code height}, written from its data
     * ({@link SvgChart}) for the ranges its axes show now (the zoom included).
     */
    public static byte[] svg(JFreeChart chart, ChartData data, int width, int height) {
        XYPlot plot = chart.getXYPlot();
        Range x = plot.getDomainAxis().getRange();
        Range y = plot.getRangeAxis().getRange();
        SvgChart.View view = new SvgChart.View(x.getLowerBound(), x.getUpperBound(), y.getLowerBound(), y.getUpperBound(),
                width, height);
        return SvgChart.svg(data, view).getBytes(StandardCharsets.UTF_8);
    }
}
