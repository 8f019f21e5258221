package org.ripv.services.datavis;


/**
 * What the drawing styles of {@code % plot:} (docs/datavis.md) do to a data file's numbers before
 * they are drawn: {@code time} and {@code depth} have x in epoch seconds, drawn on a UTC date axis
 * in milliseconds. How each style looks ({@link org.ripv.messages.ChartData.Kind}, from
 * {@link ChartDataBuilder#kindOf}) is the one chart renderer's, {@link org.ripv.charts.ChartRenderer}.
 */
final class PlotStyles {
    private PlotStyles() {}

    /** What x is multiplied by before drawing: epoch seconds become a date axis's milliseconds. */
    static double xScale(PlotLabels labels) {
        String s = labels.style();
        return "time".equals(s) || "depth".equals(s) ? 1000 : 1;
    }
}
