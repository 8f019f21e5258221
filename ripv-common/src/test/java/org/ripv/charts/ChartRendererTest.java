package org.ripv.charts;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.DateAxis;
import org.jfree.chart.plot.XYPlot;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ChartData;
import org.w3c.dom.Document;
import org.w3c.dom.NodeList;

/** The one chart renderer: the kinds' axes, a track's aspect and newest fix, and its PNG, JPEG and SVG as valid files. */
class ChartRendererTest {
    private static final String SVG = "http://www.w3.org/2000/svg";
    private static final String HOSTILE = "<script>&\"";
    private static final double T0 = 1452700000_000.0; // 2016-01-13 15:46:40 UTC
    private static final double NaN = Double.NaN;

    private static final ChartData DEPTH = new ChartData(ChartData.Kind.DEPTH, "depth of " + HOSTILE + "\u0007", "time (UTC)",
            "depth (m)", List.of(new ChartData.Series("m_depth", "m", new double[] {T0, T0 + 600_000, T0 + 1_200_000, T0 + 1_800_000},
                    new double[] {0, 5, NaN, 20}), new ChartData.Series(HOSTILE + "\u0007", "m", new double[] {T0, T0 + 1_800_000},
                    new double[] {1, 21})), null, 4, false);

    private static final ChartData TRACK = new ChartData(ChartData.Kind.TRACK, "track of unit_363", "longitude (degrees east)",
            "latitude (degrees north)", List.of(new ChartData.Series("positions", "", new double[] {-144.70, -144.68, -144.66,
                -144.64}, new double[] {50.10, 50.12, 50.13, 50.146})),
            new ChartData.Mark(-144.64, 50.146, "newest fix 2013-09-05 13:45:50 UTC (gps)"), 4, false);

    private static Document parse(byte[] svg) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(true);
        f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        f.setExpandEntityReferences(false);
        return f.newDocumentBuilder().parse(new ByteArrayInputStream(svg));
    }

    private static List<String> texts(Document d) {
        NodeList n = d.getElementsByTagNameNS(SVG, "text");
        List<String> out = new ArrayList<>();
        for (int i = 0; i < n.getLength(); i++) {
            out.add(n.item(i).getTextContent());
        }
        return out;
    }

    @Test
    void aDepthChartHasAUtcTimeAxisDepthDownwardsAndALegendForTwoSeries() {
        JFreeChart c = ChartRenderer.chart(DEPTH);
        XYPlot plot = c.getXYPlot();
        assertThat(plot.getDomainAxis()).isInstanceOf(DateAxis.class);
        assertThat(((DateAxis) plot.getDomainAxis()).getTimeZone().getID()).isEqualTo("UTC");
        assertThat(plot.getRangeAxis().isInverted()).isTrue();
        assertThat(c.getLegend()).isNotNull();
        assertThat(c.getTitle().getText()).as("the bell dropped").isEqualTo("depth of " + HOSTILE);
        assertThat(plot.getDataset().getSeriesKey(1)).isEqualTo(HOSTILE);
    }

    @Test
    void theSvgIsValidXmlWithTheChartsTextsAndNoMarkupFromTheData() throws Exception {
        byte[] svg = ChartRenderer.svg(ChartRenderer.chart(DEPTH), 800, 500);
        String text = new String(svg, StandardCharsets.UTF_8);
        Document d = parse(svg);
        assertThat(d.getDocumentElement().getLocalName()).isEqualTo("svg");
        assertThat(d.getDocumentElement().getNamespaceURI()).isEqualTo(SVG);
        assertThat(Double.parseDouble(d.getDocumentElement().getAttribute("width"))).isEqualTo(800);
        assertThat(Double.parseDouble(d.getDocumentElement().getAttribute("height"))).isEqualTo(500);
        assertThat(text).startsWith("<?xml").doesNotContain("<script").doesNotContain("\u0007");
        assertThat(d.getElementsByTagNameNS("*", "script").getLength()).isZero();
        assertThat(texts(d)).contains("depth of " + HOSTILE, "depth (m)", "time (UTC)", "m_depth", HOSTILE);
        assertThat(d.getElementsByTagNameNS(SVG, "path").getLength()).as("the lines").isPositive();
    }

    @Test
    void aZoomedChartIsExportedAsZoomed() throws Exception {
        JFreeChart c = ChartRenderer.chart(new ChartData(ChartData.Kind.XY, "", "i", "v", List.of(new ChartData.Series("s", "",
                new double[] {0, 100, 200, 300, 400, 500}, new double[] {0, 1, 0, 1, 0, 1})), null, 6, false));
        List<String> all = texts(parse(ChartRenderer.svg(c, 600, 400)));
        c.getXYPlot().getDomainAxis().setRange(400, 500);
        List<String> zoomed = texts(parse(ChartRenderer.svg(c, 600, 400)));
        assertThat(all).contains("0", "100", "500");
        assertThat(zoomed).contains("420", "480").doesNotContain("100", "200");
    }

    @Test
    void aTrackIsAtTheAspectOfItsLatitudeWithItsNewestFixARedDotInTheLegend() throws Exception {
        JFreeChart c = ChartRenderer.chart(TRACK);
        XYPlot plot = c.getXYPlot();
        assertThat(plot.getDataset().getSeriesCount()).isEqualTo(2);
        assertThat(plot.getDataset().getSeriesKey(1)).isEqualTo("newest fix 2013-09-05 13:45:50 UTC (gps)");
        assertThat(plot.getRenderer().getSeriesPaint(1)).isEqualTo(ChartRenderer.NEWEST);
        assertThat(plot.getRenderer().getSeriesPaint(0)).isEqualTo(ChartRenderer.TRACK);
        ChartRenderer.fitTrack(c, ChartData.Kind.TRACK, 600, 400);
        double spanX = plot.getDomainAxis().getRange().getLength();
        double spanY = plot.getRangeAxis().getRange().getLength();
        double pxPerKmX = 600 / (spanX * Math.cos(Math.toRadians(50.123)));
        assertThat(pxPerKmX / (400 / spanY)).isCloseTo(1.0, within(0.001));

        BufferedImage img = ImageIO.read(new ByteArrayInputStream(ChartRenderer.png(c, 600, 400)));
        assertThat(img.getWidth()).isEqualTo(600);
        assertThat(img.getHeight()).isEqualTo(400);
        int red = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                red += (img.getRGB(x, y) & 0xffffff) == 0xff0000 ? 1 : 0;
            }
        }
        assertThat(red).as("the dot on the map and in the legend").isBetween(50, 400);
        byte[] jpeg = ChartRenderer.jpeg(c, 320, 200);
        assertThat(jpeg).startsWith(0xff, 0xd8);
        assertThat(ImageIO.read(new ByteArrayInputStream(jpeg)).getWidth()).isEqualTo(320);
    }

    @Test
    void cleaningDropsControlCharactersAndBrokenSurrogates() {
        assertThat(ChartRenderer.clean("a\u0000b\u001bc\u0085d\ud800e\tf\uffff\ud83c\udf0a")).isEqualTo("abcde f\ud83c\udf0a");
    }
}
