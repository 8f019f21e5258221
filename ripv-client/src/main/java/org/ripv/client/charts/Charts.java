package org.ripv.client.charts;

import java.io.IOException;
import org.jfree.chart.JFreeChart;
import org.ripv.charts.ChartRenderer;
import org.ripv.messages.ChartData;

/**
 * The DAV quadrant's chart for a {@link ChartData}, drawn by RIPV's one chart renderer
 * ({@link ChartRenderer}) exactly as the built-in worker draws its JPEG (docs/datavis.md), and
 * written as PNG or SVG for the ranges its axes show now. Plain JFreeChart objects, no Swing:
 * works headless.
 */
public final class Charts {
    private Charts() {}

    /** The chart for this data, pannable, with tooltips giving each point's values. */
    public static JFreeChart chart(ChartData data) {
        return ChartRenderer.chart(data);
    }

    /**
     * For a track: the axes' ranges so that a kilometre is as long east-west as north-south in a
     * plot area of {@code width} x {@code height} pixels; other kinds: automatic ranges.
     */
    public static void fit(JFreeChart chart, ChartData data, double width, double height) {
        ChartRenderer.fitTrack(chart, data.kind(), width, height);
    }

    /** The chart as a PNG of {@code width} x {@code height} pixels. */
    public static byte[] png(JFreeChart chart, int width, int height) throws IOException {
        return ChartRenderer.png(chart, width, height);
    }

    /** The chart as an SVG document of {@code width} x {@code height}, as zoomed now. */
    public static byte[] svg(JFreeChart chart, int width, int height) {
        return ChartRenderer.svg(chart, width, height);
    }
}
