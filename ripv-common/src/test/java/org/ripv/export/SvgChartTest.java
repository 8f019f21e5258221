package org.ripv.export;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.time.LocalTime;
import java.util.ArrayList;
import java.util.List;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilder;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ChartData;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

class SvgChartTest {
    private static final String SVG = "http://www.w3.org/2000/svg";
    private static final String HOSTILE = "<script>&\"";
    private static final double T0 = 1452700000_000.0; // 2016-01-13 15:46:40 UTC
    private static final double NaN = Double.NaN;

    /** Depth against time, two series: the first with two gaps (3 runs), the second with a missing x (2 runs). */
    private static final ChartData DEPTH = new ChartData(ChartData.Kind.DEPTH, "depth of " + HOSTILE, "time (UTC)", "depth (m)",
            List.of(new ChartData.Series("m_depth", "m", times(10), new double[] {0, 5, 10, NaN, 20, 25, 30, NaN, 40, 45}),
                    new ChartData.Series(HOSTILE, "m\u0007", withGap(times(6), 2), new double[] {1, 6, 11, 16, 21, 26})),
            null, 16, false);

    private static final ChartData TRACK = new ChartData(ChartData.Kind.TRACK, "track of unit_363", "longitude (degrees east)",
            "latitude (degrees north)", List.of(new ChartData.Series("positions", "", new double[] {-144.70, -144.68, -144.66,
                -144.64}, new double[] {50.10, 50.12, 50.13, 50.146})),
            new ChartData.Mark(-144.64, 50.146, "newest fix 2013-09-05 13:45:50 UTC (gps)"), 4, false);

    private static double[] times(int n) {
        double[] t = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = T0 + i * 600_000.0; // every 10 minutes
        }
        return t;
    }

    private static double[] withGap(double[] a, int at) {
        a[at] = NaN;
        return a;
    }

    private static Document parse(String svg) throws Exception {
        DocumentBuilderFactory f = DocumentBuilderFactory.newInstance();
        f.setNamespaceAware(true);
        f.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
        f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
        f.setExpandEntityReferences(false);
        DocumentBuilder b = f.newDocumentBuilder();
        return b.parse(new ByteArrayInputStream(svg.getBytes(StandardCharsets.UTF_8)));
    }

    private static List<Element> all(Document d, String name) {
        NodeList n = d.getElementsByTagNameNS(SVG, name);
        List<Element> out = new ArrayList<>();
        for (int i = 0; i < n.getLength(); i++) {
            out.add((Element) n.item(i));
        }
        return out;
    }

    private static Element group(Document d, String cls) {
        return all(d, "g").stream().filter(g -> g.getAttribute("class").equals(cls)).findFirst().orElseThrow(
                () -> new AssertionError("no <g class=" + cls + ">"));
    }

    private static List<String> texts(Element g) {
        NodeList n = g.getElementsByTagNameNS(SVG, "text");
        List<String> out = new ArrayList<>();
        for (int i = 0; i < n.getLength(); i++) {
            out.add(n.item(i).getTextContent());
        }
        return out;
    }

    private static List<Element> texts(Document d, String content) {
        return all(d, "text").stream().filter(t -> t.getTextContent().equals(content)).toList();
    }

    private static List<double[]> points(Element polyline) {
        List<double[]> out = new ArrayList<>();
        for (String p : polyline.getAttribute("points").trim().split(" ")) {
            String[] xy = p.split(",");
            out.add(new double[] {Double.parseDouble(xy[0]), Double.parseDouble(xy[1])});
        }
        return out;
    }

    private static double attr(Element e, String name) {
        return Double.parseDouble(e.getAttribute(name));
    }

    @Test
    void aTimeSeriesIsValidSvgWithOnePolylineARunTicksAndDepthDownwards() throws Exception {
        String svg = SvgChart.svg(DEPTH, SvgChart.View.fit(DEPTH, 800, 500));
        Document d = parse(svg);
        Element root = d.getDocumentElement();
        assertThat(root.getLocalName()).isEqualTo("svg");
        assertThat(root.getNamespaceURI()).isEqualTo(SVG);
        assertThat(root.getAttribute("version")).isEqualTo("1.1");
        assertThat(root.getAttribute("width")).isEqualTo("800");
        assertThat(root.getAttribute("height")).isEqualTo("500");
        assertThat(svg).startsWith("<?xml version=\"1.0\" encoding=\"UTF-8\"?>");

        // Gaps break the lines as the panel does: 3 + 2 runs, in the palette's first two colours.
        List<Element> series = all(d, "g").stream().filter(g -> g.getAttribute("class").equals("series")).toList();
        assertThat(series).hasSize(2);
        assertThat(series.get(0).getAttribute("stroke")).isEqualTo("#1f77b4");
        assertThat(series.get(1).getAttribute("stroke")).isEqualTo("#ff7f0e");
        assertThat(series.get(0).getElementsByTagNameNS(SVG, "polyline").getLength()).isEqualTo(3);
        assertThat(series.get(1).getElementsByTagNameNS(SVG, "polyline").getLength()).isEqualTo(2);
        assertThat(all(d, "polyline")).hasSize(5);
        assertThat(points((Element) series.get(0).getElementsByTagNameNS(SVG, "polyline").item(0))).hasSize(3);

        // Clipped to the plot area, which the clipPath names.
        Element plot = group(d, "plot");
        assertThat(plot.getAttribute("clip-path")).isEqualTo("url(#plot-area)");
        Element clip = all(d, "clipPath").get(0);
        assertThat(clip.getAttribute("id")).isEqualTo("plot-area");

        // x ticks: times of day at round ten minutes, left to right; the axis says which day.
        List<String> xTicks = texts(group(d, "x-ticks"));
        assertThat(xTicks.size()).isBetween(3, 12);
        for (String t : xTicks) {
            assertThat(LocalTime.parse(t).getMinute() % 10).as(t).isZero();
        }
        assertThat(texts(d, "time (UTC), 2016-01-13")).hasSize(1);
        // y ticks: round numbers, depth growing downwards.
        List<Element> yTicks = all(d, "text").stream().filter(t -> t.getParentNode() == group(d, "y-ticks")).toList();
        assertThat(yTicks.size()).isBetween(3, 12);
        double step = Double.parseDouble(yTicks.get(1).getTextContent()) - Double.parseDouble(yTicks.get(0).getTextContent());
        assertThat(List.of(1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0)).contains(step);
        assertThat(attr(yTicks.get(1), "y")).as("deeper is lower").isGreaterThan(attr(yTicks.get(0), "y"));
        assertThat(texts(d, "depth (m)")).hasSize(1);
        // The first point (depth 0, the first time) is at the top-left of the data.
        double[] first = points((Element) all(d, "polyline").get(0)).get(0);
        double[] deepest = points((Element) all(d, "polyline").get(2)).get(1);
        assertThat(first[1]).isLessThan(deepest[1]);
        assertThat(first[0]).isLessThan(deepest[0]);
    }

    @Test
    void hostileNamesAreTextNotMarkup() throws Exception {
        String svg = SvgChart.svg(DEPTH, SvgChart.View.fit(DEPTH, 800, 500));
        Document d = parse(svg);
        assertThat(svg).doesNotContain("<script").doesNotContain("\u0007");
        assertThat(d.getElementsByTagNameNS("*", "script").getLength()).isZero();
        assertThat(d.getElementsByTagName("script").getLength()).isZero();
        // The legend names the series with its unit (the bell dropped), the title keeps its text.
        assertThat(texts(group(d, "legend"))).containsExactly("m_depth (m)", HOSTILE + " (m)");
        assertThat(texts(d, "depth of " + HOSTILE)).hasSize(1);
        assertThat(all(d, "title").get(0).getTextContent()).isEqualTo("depth of " + HOSTILE);
    }

    @Test
    void escapingDropsControlCharactersAndBrokenSurrogates() {
        assertThat(SvgChart.escape("a&b<c>d\"e'f\u0000g\u001bh\u0085i\ud800j\tk\uffff\ud83c\udf0a"))
                .isEqualTo("a&amp;b&lt;c&gt;d&quot;e&apos;fghij k\ud83c\udf0a");
    }

    @Test
    void aTrackMarksAndLabelsItsNewestFixAtItsAspect() throws Exception {
        String svg = SvgChart.svg(TRACK, SvgChart.View.fit(TRACK, 700, 500));
        Document d = parse(svg);
        assertThat(all(d, "polyline")).hasSize(1);
        Element line = all(d, "polyline").get(0);
        assertThat(((Element) line.getParentNode()).getAttribute("marker-mid")).isEqualTo("url(#dot-0)");
        assertThat(all(d, "marker")).hasSize(1);
        Element newest = group(d, "newest");
        Element dot = (Element) newest.getElementsByTagNameNS(SVG, "circle").item(0);
        assertThat(dot.getAttribute("fill")).isEqualTo("#ff0000");
        List<double[]> p = points(line);
        assertThat(attr(dot, "cx")).isCloseTo(p.get(3)[0], org.assertj.core.api.Assertions.within(0.11));
        assertThat(attr(dot, "cy")).isCloseTo(p.get(3)[1], org.assertj.core.api.Assertions.within(0.11));
        assertThat(texts(newest)).containsExactly("newest fix 2013-09-05 13:45:50 UTC (gps)");
        // The label's box, inside the plot, covers none of the track's points.
        Element box = (Element) newest.getElementsByTagNameNS(SVG, "rect").item(0);
        Element area = (Element) all(d, "clipPath").get(0).getElementsByTagNameNS(SVG, "rect").item(0);
        double bx = attr(box, "x");
        double by = attr(box, "y");
        assertThat(bx).isGreaterThanOrEqualTo(attr(area, "x"));
        assertThat(bx + attr(box, "width")).isLessThanOrEqualTo(attr(area, "x") + attr(area, "width"));
        for (double[] q : points(line)) {
            assertThat(q[0] >= bx && q[0] <= bx + attr(box, "width") && q[1] >= by && q[1] <= by + attr(box, "height"))
                    .as("point %s,%s under the label", q[0], q[1]).isFalse();
        }
        assertThat(texts(group(d, "legend"))).containsExactly("positions", "newest fix 2013-09-05 13:45:50 UTC (gps)");
        // North up; a kilometre as long east-west as north-south: pixels per degree of longitude
        // are cos(latitude) of those per degree of latitude.
        assertThat(p.get(3)[1]).isLessThan(p.get(0)[1]);
        double perLon = (p.get(3)[0] - p.get(0)[0]) / (-144.64 + 144.70);
        double perLat = (p.get(0)[1] - p.get(3)[1]) / (50.146 - 50.10);
        assertThat(perLon / perLat).isCloseTo(Math.cos(Math.toRadians(50.123)), org.assertj.core.api.Assertions.within(0.01));
    }

    @Test
    void aZoomedViewClipsAndLeavesOutWhatLiesOutside() throws Exception {
        // 1,000 points of a sine; the view shows x 400..500 only, and y -0.5..0.5.
        int n = 1000;
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = i;
            y[i] = Math.sin(i / 20.0);
        }
        ChartData c = new ChartData(ChartData.Kind.XY, "", "i", "sin", List.of(new ChartData.Series("s", "", x, y)), null, n, false);
        Document d = parse(SvgChart.svg(c, new SvgChart.View(400, 500, -0.5, 0.5, 600, 400)));
        Element rect = (Element) all(d, "clipPath").get(0).getElementsByTagNameNS(SVG, "rect").item(0);
        double left = attr(rect, "x");
        double right = left + attr(rect, "width");
        double top = attr(rect, "y");
        double bottom = top + attr(rect, "height");
        int emitted = 0;
        List<Element> lines = all(d, "polyline");
        assertThat(lines).isNotEmpty();
        for (Element l : lines) {
            List<double[]> pts = points(l);
            emitted += pts.size();
            // Every polyline reaches into the plot area, and is drawn inside the clipped group.
            assertThat(pts.stream().anyMatch(q -> q[0] >= left && q[0] <= right && q[1] >= top && q[1] <= bottom)).isTrue();
            assertThat(((Element) l.getParentNode().getParentNode()).getAttribute("clip-path")).isEqualTo("url(#plot-area)");
        }
        int inside = 0;
        for (int i = 0; i < n; i++) {
            inside += x[i] >= 400 && x[i] <= 500 && Math.abs(y[i]) <= 0.5 ? 1 : 0;
        }
        // Only the visible points, and at each end of a piece the one beyond the edge (or two, when the
        // first beyond it is within the few pixels' margin kept for the line's width).
        assertThat(emitted).as("of 1,000 points").isBetween(inside, inside + 4 * lines.size());
        // The sine leaves the y range (sin < -0.5) and comes back: two pieces.
        assertThat(lines).hasSize(2);
        List<String> xTicks = texts(group(d, "x-ticks"));
        assertThat(xTicks).containsExactly("400", "420", "440", "460", "480", "500");
        assertThat(texts(group(d, "y-ticks"))).contains("-0.4", "0.0", "0.4");
    }

    @Test
    void aTrackZoomedAwayFromItsNewestFixKeepsItInTheLegendOnly() throws Exception {
        Document d = parse(SvgChart.svg(TRACK, new SvgChart.View(-144.71, -144.69, 50.09, 50.11, 600, 400)));
        assertThat(all(d, "g").stream().filter(g -> g.getAttribute("class").equals("newest")).toList()).isEmpty();
        assertThat(texts(group(d, "legend"))).contains("newest fix 2013-09-05 13:45:50 UTC (gps)");
    }

    @Test
    void ticksAreRoundNumbersAndTimes() {
        assertThat(AxisTicks.numbers(0.13, 0.87, 5)).usingComparatorWithPrecision(1e-12)
                .containsExactly(0.2, 0.4, 0.6, 0.8);
        assertThat(AxisTicks.numbers(-3, 3, 6)).containsExactly(-3, -2, -1, 0, 1, 2, 3);
        // 3 days in about 6 ticks: midnights and noons.
        double[] t = AxisTicks.times(T0, T0 + 3 * 86_400_000.0, 6);
        for (double v : t) {
            assertThat(v % 43_200_000).isZero();
        }
        assertThat(t.length).isBetween(5, 7);
    }

    @Test
    void anEmptyChartOrABadViewIsRefusedOrDrawnEmpty() throws Exception {
        ChartData empty = new ChartData(ChartData.Kind.XY, "nothing", "x", "y", List.of(), null, 0, false);
        Document d = parse(SvgChart.svg(empty, SvgChart.View.fit(empty, 400, 300)));
        assertThat(all(d, "polyline")).isEmpty();
        assertThatThrownBy(() -> new SvgChart.View(1, 1, 0, 1, 400, 300)).hasMessageContaining("x range");
        assertThatThrownBy(() -> new SvgChart.View(0, 1, 0, NaN, 400, 300)).hasMessageContaining("y range");
        assertThatThrownBy(() -> new SvgChart.View(0, 1, 0, 1, 400, 100_000)).hasMessageContaining("size");
    }
}
