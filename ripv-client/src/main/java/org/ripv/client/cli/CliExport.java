package org.ripv.client.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.jfree.chart.JFreeChart;
import org.ripv.charts.ChartRenderer;
import org.ripv.export.ChartExport;
import org.ripv.export.TableExport;
import org.ripv.messages.ChartData;
import org.ripv.messages.ImageResult;
import org.ripv.messages.Result;
import org.ripv.messages.TableResult;

/** The CLI's {@code export}: the last query result or plot's data received, written to a local file. */
final class CliExport {
    private TableResult lastTable;
    /** A plot's data, when it came after the last table (export writes whichever came last). */
    private ChartData lastChart;

    /** Keeps a reply's table or plot data for a later {@code export}. */
    void remember(Result result) {
        if (result instanceof TableResult t) {
            lastTable = t;
            lastChart = null;
        } else if (result instanceof ImageResult img && img.chart() != null) {
            lastChart = img.chart();
        }
    }

    /**
     * {@code export csv|json FILE}: the last table received, or a plot's data when one came after
     * it, to a local file ({@link org.ripv.export.TableExport}, {@link org.ripv.export.ChartExport});
     * {@code export svg FILE}: that plot as a picture of all its data ({@link ChartRenderer}, 900 x 560).
     *
     * @return what was written where
     * @throws IllegalArgumentException a bad line, or nothing to export (said why)
     */
    String export(String args) throws IOException {
        String[] a = args.isEmpty() ? new String[0] : args.split("\\s+", 2);
        if (a.length != 2 || !(a[0].equalsIgnoreCase("csv") || a[0].equalsIgnoreCase("json") || a[0].equalsIgnoreCase("svg"))) {
            throw new IllegalArgumentException("usage: export csv|json|svg LOCALFILE (writes the last query result or plot's data;"
                    + " svg: the plot)");
        }
        if (a[0].equalsIgnoreCase("svg")) {
            if (lastChart == null) {
                throw new IllegalArgumentException("no plot to export as SVG: the last reply was not a plot with data (a vis: plot"
                        + " of the built-in worker)");
            }
            Path file = Path.of(a[1]);
            JFreeChart chart = ChartRenderer.chart(lastChart);
            ChartRenderer.fitPicture(chart, lastChart.kind(), 900, 560);
            Files.write(file, ChartRenderer.svg(chart, 900, 560));
            return "exported the plot (" + lastChart.series().size() + " series, " + lastChart.points() + " points) as svg to " + file;
        }
        if (lastChart != null) {
            boolean csv = a[0].equalsIgnoreCase("csv");
            Path file = Path.of(a[1]);
            Files.writeString(file, csv ? ChartExport.csv(lastChart) : ChartExport.json(lastChart),
                    StandardCharsets.UTF_8);
            return "exported the plot's data (" + lastChart.series().size() + " series, " + lastChart.points() + " points) as "
                    + a[0].toLowerCase(Locale.ROOT) + " to " + file;
        }
        if (lastTable == null) {
            throw new IllegalArgumentException("no query result to export yet: run a SELECT first");
        }
        String text = a[0].equalsIgnoreCase("csv") ? TableExport.csv(lastTable)
                : TableExport.json(lastTable);
        Path file = Path.of(a[1]);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return "exported " + lastTable.rows().size() + " rows as " + a[0].toLowerCase(Locale.ROOT) + " to " + file;
    }
}
