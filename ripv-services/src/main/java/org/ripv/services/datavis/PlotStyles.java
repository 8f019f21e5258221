package org.ripv.services.datavis;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.geom.Ellipse2D;
import java.util.TimeZone;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.annotations.XYPointerAnnotation;
import org.jfree.chart.annotations.XYShapeAnnotation;
import org.jfree.chart.axis.DateAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.ui.TextAnchor;
import org.jfree.data.xy.XYDataset;

/**
 * The drawing styles of {@code % plot:} (docs/datavis.md): {@code time} (x is epoch seconds, on a
 * UTC date axis), {@code depth} (time, depth growing downwards), {@code profile} (a sensor
 * against depth, depth downwards) and {@code track} (x longitude, y latitude in decimal degrees:
 * a graticule at the right aspect for the latitude, the newest fix marked and labelled with
 * {@code % mark:}).
 */
final class PlotStyles {
    /** A track's colour: MATLAB's and Octave's first line colour, as ripvOut.m draws it. */
    static final Color TRACK = new Color(0, 114, 189);

    private PlotStyles() {}

    /** What x is multiplied by before drawing: epoch seconds become a date axis's milliseconds. */
    static double xScale(PlotLabels labels) {
        String s = labels.style();
        return "time".equals(s) || "depth".equals(s) ? 1000 : 1;
    }

    static void apply(JFreeChart chart, PlotLabels labels, XYDataset data, double lastX, double lastY, int width, int height) {
        String style = labels.style() == null ? "xy" : labels.style();
        XYPlot plot = chart.getXYPlot();
        switch (style) {
            case "time", "depth" -> {
                DateAxis time = new DateAxis(plot.getDomainAxis().getLabel());
                time.setTimeZone(TimeZone.getTimeZone("UTC"));
                plot.setDomainAxis(time);
                plot.getRangeAxis().setInverted(style.equals("depth"));
            }
            case "profile" -> plot.getRangeAxis().setInverted(true);
            case "track" -> track(plot, data, lastX, lastY, labels.mark(), width, height);
            default -> { }
        }
    }

    private static void track(XYPlot plot, XYDataset data, double lastX, double lastY, String mark, int width, int height) {
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
        XYLineAndShapeRenderer r = (XYLineAndShapeRenderer) plot.getRenderer();
        r.setDefaultShapesVisible(true);
        for (int s = 0; s < data.getSeriesCount(); s++) {
            r.setSeriesShape(s, new Ellipse2D.Double(-2, -2, 4, 4));
        }
        r.setSeriesPaint(0, TRACK); // not JFreeChart's first red: the newest fix is the red on a map
        plot.setDomainGridlineStroke(new BasicStroke(0.6f));
        plot.setRangeGridlineStroke(new BasicStroke(0.6f));
        if (minX > maxX) {
            return; // nothing to draw
        }
        // One degree of longitude is cos(latitude) of one of latitude: scale the spans so a
        // kilometre is as long east-west as north-south on the picture.
        double k = Math.max(0.01, Math.cos(Math.toRadians((minY + maxY) / 2)));
        double spanX = Math.max(maxX - minX, 1e-4) * 1.2;
        double spanY = Math.max(maxY - minY, 1e-4) * 1.2;
        double plotW = Math.max(50, width - 110);
        double plotH = Math.max(50, height - 110);
        if (spanX * k / spanY > plotW / plotH) {
            spanY = spanX * k * plotH / plotW;
        } else {
            spanX = spanY * plotW / plotH / k;
        }
        double cx = (minX + maxX) / 2;
        double cy = (minY + maxY) / 2;
        NumberAxis x = (NumberAxis) plot.getDomainAxis();
        NumberAxis y = (NumberAxis) plot.getRangeAxis();
        x.setRange(cx - spanX / 2, cx + spanX / 2);
        y.setRange(cy - spanY / 2, cy + spanY / 2);
        if (Double.isFinite(lastX) && Double.isFinite(lastY)) {
            double rx = 5 * spanX / plotW; // a circle of 5 pixels' radius
            double ry = 5 * spanY / plotH;
            plot.addAnnotation(new XYShapeAnnotation(new Ellipse2D.Double(lastX - rx, lastY - ry, 2 * rx, 2 * ry),
                    new BasicStroke(2f), Color.RED, Color.RED));
            XYPointerAnnotation label = new XYPointerAnnotation(mark == null ? "newest fix" : mark, lastX, lastY,
                    lastX > cx ? Math.PI * 0.75 : Math.PI * 0.25);
            label.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 12));
            label.setPaint(Color.RED.darker());
            label.setArrowPaint(Color.RED.darker());
            label.setTextAnchor(lastX > cx ? TextAnchor.BOTTOM_RIGHT : TextAnchor.BOTTOM_LEFT);
            plot.addAnnotation(label);
        }
    }
}
