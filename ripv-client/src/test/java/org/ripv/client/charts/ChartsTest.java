package org.ripv.client.charts;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.Point;
import java.awt.geom.Point2D;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.DateAxis;
import org.jfree.chart.plot.XYPlot;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.messages.ChartData;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;

/** The DAV panel's interactive chart, headless: what it draws, the value under the cursor, and the files it saves. */
class ChartsTest {
    static final String VIS = "<DataVisServer>::<h>";
    static final ChartData DEPTH = new ChartData(ChartData.Kind.DEPTH, "depth of cp_388", "time (UTC)", "depth (m)",
            List.of(new ChartData.Series("m_depth", "m", new double[] {1452700000_000.0, 1452700060_000.0, 1452700120_000.0,
                    1452700180_000.0}, new double[] {0, 12.5, Double.NaN, 30})), null, 4, false);
    static final ChartData TRACK = new ChartData(ChartData.Kind.TRACK, "track of unit_363", "longitude (degrees east)",
            "latitude (degrees north)", List.of(new ChartData.Series("positions", "", new double[] {-145.1, -145.0, -144.9},
                    new double[] {50.1, 50.15, 50.2})), new ChartData.Mark(-144.9, 50.2, "newest fix 2013-09-05 13:45 UTC"), 3,
            false);

    final LinkedBlockingQueue<Runnable> ui = new LinkedBlockingQueue<>();
    ClientModel model;
    GuiManager manager;
    long ids;

    @TempDir
    Path tmp;

    @BeforeEach
    void setUp() {
        model = new ClientModel();
        manager = new GuiManager(model, ui::add, (h, p) -> {
            throw new IOException("no network here");
        }, GuiManager.Timings.DEFAULT);
        dispatch(Ids.FID_SERVICES, "", new ServiceList(List.of(new ServiceDescriptor(VIS, Ids.SID_DATAVIS, "", "DAV",
                List.of("vis:")))));
    }

    @AfterEach
    void tearDown() {
        manager.close();
    }

    void drain() {
        for (Runnable r = ui.poll(); r != null; r = ui.poll()) {
            r.run();
        }
    }

    void dispatch(String sid, String mailbox, Result result) {
        manager.dispatch(new OutgoingServerMessage(new Header(++ids, new IdBadge("123456", "a"), List.of(), "", mailbox,
                "vis:x", Priority.NORMAL, null), new Footer(sid, Status.OK, ErrorCode.NONE, List.of(), "plotted", result)));
        drain();
    }

    static byte[] jpeg() throws IOException {
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(80, 60, java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        javax.imageio.ImageIO.write(img, "jpg", out);
        return out.toByteArray();
    }

    @Test
    void aDepthChartHasAUtcDateAxisAndDepthDownwards() {
        JFreeChart c = Charts.chart(DEPTH);
        XYPlot plot = c.getXYPlot();
        assertThat(plot.getDomainAxis()).isInstanceOf(DateAxis.class);
        assertThat(((DateAxis) plot.getDomainAxis()).getTimeZone().getID()).isEqualTo("UTC");
        assertThat(plot.getRangeAxis().isInverted()).isTrue();
        assertThat(plot.isDomainPannable()).isTrue();
        assertThat(c.getTitle().getText()).isEqualTo("depth of cp_388");
        assertThat(plot.getDataset().getItemCount(0)).isEqualTo(4);
    }

    @Test
    void aTrackIsDrawnAtTheAspectOfItsLatitudeWithTheNewestFixMarked() {
        JFreeChart c = Charts.chart(TRACK);
        XYPlot plot = c.getXYPlot();
        assertThat(plot.getDataset().getSeriesCount()).isEqualTo(2);
        assertThat(plot.getDataset().getSeriesKey(1)).as("labelled in the legend").isEqualTo("newest fix 2013-09-05 13:45 UTC");
        assertThat(c.getLegend()).isNotNull();
        Charts.fit(c, TRACK, 600, 400);
        double spanX = plot.getDomainAxis().getRange().getLength();
        double spanY = plot.getRangeAxis().getRange().getLength();
        // 600 px wide per spanX degrees of longitude, 400 px per spanY of latitude: at 50.15° N a
        // degree of longitude is cos(50.15°) of one of latitude, so px per km must agree.
        double pxPerKmX = 600 / (spanX * Math.cos(Math.toRadians(50.15)));
        double pxPerKmY = 400 / spanY;
        assertThat(pxPerKmX / pxPerKmY).isBetween(0.999, 1.001);
    }

    @Test
    void aGapBreaksTheLine() {
        ChartData gap = new ChartData(ChartData.Kind.XY, "", "x", "y", List.of(new ChartData.Series("s", "", new double[] {0, 1, 2, 3, 4},
                new double[] {1, 1, Double.NaN, 1, 1}), new ChartData.Series("t", "", new double[] {0, 4}, new double[] {0, 2})),
                null, 5, false);
        JFreeChart c = Charts.chart(gap);
        c.getXYPlot().setDomainGridlinesVisible(false); // only the series' pixels
        c.getXYPlot().setRangeGridlinesVisible(false);
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(400, 300, java.awt.image.BufferedImage.TYPE_INT_RGB);
        org.jfree.chart.ChartRenderingInfo info = new org.jfree.chart.ChartRenderingInfo();
        java.awt.Graphics2D g = img.createGraphics();
        c.draw(g, new java.awt.geom.Rectangle2D.Double(0, 0, 400, 300), info);
        g.dispose();
        java.awt.geom.Rectangle2D area = info.getPlotInfo().getDataArea();
        XYPlot plot = c.getXYPlot();
        int y = (int) Math.round(plot.getRangeAxis().valueToJava2D(1, area, plot.getRangeAxisEdge()));
        int drawn = (int) Math.round(plot.getDomainAxis().valueToJava2D(0.5, area, plot.getDomainAxisEdge()));
        int gapX = (int) Math.round(plot.getDomainAxis().valueToJava2D(1.6, area, plot.getDomainAxisEdge()));
        assertThat(img.getRGB(drawn, y) & 0xffffff).as("the line between two points").isNotEqualTo(0xffffff);
        assertThat(img.getRGB(gapX, y) & 0xffffff).as("nothing across the gap").isEqualTo(0xffffff);
    }

    @Test
    void theReadoutNamesTheNearestPointInItsUnitsAndSkipsGaps() {
        Readout r = Readout.nearest(DEPTH, 1452700061_000.0, 12.0, 1000, 0.5, 12);
        assertThat(r.text()).isEqualTo("m_depth: 12.5 m at 2016-01-13 15:47:40 UTC");
        assertThat(Readout.nearest(DEPTH, 1452700120_000.0, 20, 1000, 0.5, 12)).as("a gap, and nothing near").isNull();
        Readout t = Readout.nearest(TRACK, -144.9001, 50.2001, 0.001, 0.001, 12);
        assertThat(t.text()).isEqualTo("positions: 50.20000° N, 144.90000° W");
    }

    @Test
    void aPlotWithDataShowsTheChartAndOneWithoutTheJpeg() throws Exception {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(VIS), manager);
        dispatch(Ids.SID_DATAVIS, VIS + "TTY1", new ImageResult("depth-cp_388.jpg", jpeg(), DEPTH));
        p.updateAll(model);
        PlotPanel plot = p.plot();
        assertThat(plot.showsChart()).isTrue();
        assertThat(plot.data()).isSameAs(DEPTH);

        // The mouse over a point: laid out at a real size, the readout names it.
        plot.setSize(700, 450);
        plot.doLayout();
        layout(plot);
        plot.chartPanel().paint(new java.awt.image.BufferedImage(700, 450,
                java.awt.image.BufferedImage.TYPE_INT_RGB).createGraphics()); // computes the data area
        Point2D at = plot.screenPoint(1452700060_000.0, 12.5);
        assertThat(plot.readoutAt(new Point((int) at.getX() + 3, (int) at.getY() - 2)).text())
                .isEqualTo("m_depth: 12.5 m at 2016-01-13 15:47:40 UTC");

        // Keyboard zoom and reset.
        double span = plot.chart().getXYPlot().getDomainAxis().getRange().getLength();
        plot.zoom(0.5);
        assertThat(plot.chart().getXYPlot().getDomainAxis().getRange().getLength()).isLessThan(span * 0.6);
        plot.resetZoom();
        assertThat(plot.chart().getXYPlot().getDomainAxis().getRange().getLength()).isCloseTo(span,
                org.assertj.core.api.Assertions.within(span * 1e-6));

        // Every format; the JPEG exactly as it arrived.
        // SVG drawn by the one chart renderer (JFreeSVG) for the axes' ranges now ...
        String svgText = new String(plot.bytes(PlotPanel.Format.SVG), StandardCharsets.UTF_8);
        assertThat(svgText).startsWith("<?xml").contains("<svg").contains("http://www.w3.org/2000/svg")
                .contains("depth of cp_388").contains("depth (m)").contains("<path");
        // ... and zoomed to the first two points, as zoomed: other time ticks.
        XYPlot xy = plot.chart().getXYPlot();
        xy.getDomainAxis().setRange(1452700000_000.0 - 5_000, 1452700070_000.0);
        xy.getRangeAxis().setRange(-1, 14);
        String zoomed = new String(plot.bytes(PlotPanel.Format.SVG), StandardCharsets.UTF_8);
        assertThat(zoomed).contains("<svg").isNotEqualTo(svgText);
        plot.resetZoom();
        // JFreeChart's own right-click "Save as" offers SVG too (ours: JFreeSVG is not shipped).
        assertThat(java.util.Arrays.stream(plot.chartPanel().getPopupMenu().getComponents())
                .filter(c -> c instanceof javax.swing.JMenu).flatMap(c -> java.util.Arrays.stream(((javax.swing.JMenu) c)
                        .getMenuComponents())).anyMatch(c -> "chartMenu-svg".equals(c.getName()))).isTrue();
        byte[] png = plot.bytes(PlotPanel.Format.PNG);
        assertThat(png).startsWith(0x89, 'P', 'N', 'G');
        assertThat(javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(png)).getWidth()).isEqualTo(Math.max(400, plot.chartPanel().getWidth()));
        assertThat(new String(plot.bytes(PlotPanel.Format.CSV), StandardCharsets.UTF_8)).startsWith("series,unit,x,time_utc,y\r\n");
        assertThat(new String(plot.bytes(PlotPanel.Format.JSON), StandardCharsets.UTF_8)).contains("\"y\":[0,12.5,null,30]");
        assertThat(plot.bytes(PlotPanel.Format.JPEG)).isEqualTo(model.service(VIS).picture().result().jpeg());
        Path svg = tmp.resolve("depth.svg");
        plot.export(PlotPanel.Format.SVG, svg);
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (!Files.exists(svg) && System.nanoTime() < deadline) {
            Thread.sleep(20);
            drain();
        }
        assertThat(Files.readString(svg)).startsWith("<?xml").contains("<svg");

        // Octave sends no data: the JPEG, as before.
        dispatch(Ids.SID_DATAVIS, VIS + "TTY1", new ImageResult("octave.jpg", jpeg()));
        p.updateAll(model);
        assertThat(plot.showsChart()).isFalse();
        assertThat(plot.image().image()).isNotNull();
    }

    private static void layout(java.awt.Container c) {
        c.doLayout();
        for (java.awt.Component k : c.getComponents()) {
            if (k instanceof java.awt.Container inner) {
                layout(inner);
            }
        }
    }
}
