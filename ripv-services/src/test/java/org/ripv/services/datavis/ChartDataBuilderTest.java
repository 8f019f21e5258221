package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ChartData;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;
import org.ripv.wire.WireFilter;

/** The chart data a plot's reply carries for the client's interactive chart (docs/datavis.md). */
class ChartDataBuilderTest {
    @TempDir
    Path tmp;

    private static ChartData chart(String file, PlotLabels options) throws Exception {
        byte[] data = file.getBytes(StandardCharsets.UTF_8);
        DataFile.Summary s = DataFile.normalize(data, options, new StringWriter());
        return ChartDataBuilder.build(data, s);
    }

    @Test
    void seriesCarryNamesUnitsAndTheFilesNumbersWithGaps() throws Exception {
        ChartData c = chart(DataVisServerTest.SAMPLE, PlotLabels.NONE);
        assertThat(c.kind()).isEqualTo(ChartData.Kind.XY);
        assertThat(c.title()).isEqualTo("Glider temperature");
        assertThat(c.xLabel()).isEqualTo("time (s)");
        assertThat(c.series()).extracting(ChartData.Series::name).containsExactly("surface", "10 m");
        assertThat(c.series()).extracting(ChartData.Series::unit).containsExactly("C", "C"); // from "T (C)"
        assertThat(c.series().get(0).x()).containsExactly(0, 60, 120, 180);
        assertThat(c.series().get(0).y()[2]).isNaN();
        assertThat(c.series().get(1).y()).containsExactly(18.0, 18.1, 18.3, 18.2);
        assertThat(c.rows()).isEqualTo(4);
        assertThat(c.reduced()).isFalse();
        assertThat(c.newest()).isNull();
    }

    @Test
    void optionsWinAndALegendsUnitsAreKept() throws Exception {
        ChartData c = chart("% legend: m_depth (m) | sci_water_temp (degc)\n1 2 3\n4 5 6\n",
                new PlotLabels("Dive", null, null, null, 0, 0));
        assertThat(c.title()).isEqualTo("Dive");
        assertThat(c.series()).extracting(ChartData.Series::name).containsExactly("m_depth", "sci_water_temp");
        assertThat(c.series()).extracting(ChartData.Series::unit).containsExactly("m", "degc");
    }

    @Test
    void stylesBecomeKindsTimeInMillisecondsDepthDownAndATracksNewestFix() throws Exception {
        ChartData depth = chart("% plot: depth\n% legend: m_depth\n1452700000 0\n1452700060 12.5\n", PlotLabels.NONE);
        assertThat(depth.kind()).isEqualTo(ChartData.Kind.DEPTH);
        assertThat(depth.kind().timeAxis()).isTrue();
        assertThat(depth.kind().yInverted()).isTrue();
        assertThat(depth.series().get(0).x()).containsExactly(1452700000_000.0, 1452700060_000.0);

        ChartData track = chart("% plot: track\n% mark: newest fix 2016-01-13 17:00 UTC (gps)\n"
                + "-70.5 41.1\n-70.6 41.2\n-70.7 41.3\n", PlotLabels.NONE);
        assertThat(track.kind()).isEqualTo(ChartData.Kind.TRACK);
        assertThat(track.newest()).isNotNull();
        assertThat(track.newest().x()).isEqualTo(-70.7);
        assertThat(track.newest().y()).isEqualTo(41.3);
        assertThat(track.newest().label()).isEqualTo("newest fix 2016-01-13 17:00 UTC (gps)");
        assertThat(chart("% plot: profile\n1 2\n", PlotLabels.NONE).kind().yInverted()).isTrue();
    }

    @Test
    void twoHundredThousandRowsAreReducedWithinTheBoundKeepingExtremesGapsAndTheNewestFix() throws Exception {
        StringBuilder b = new StringBuilder(6_000_000);
        for (int i = 0; i < 200_000; i++) {
            double y = i == 80_000 ? 99 : i == 140_000 ? -99 : Math.sin(i / 1000.0);
            b.append(i).append(' ').append(i == 100_000 ? "NaN" : Double.toString(y)).append('\n');
        }
        ChartData c = chart(b.toString(), PlotLabels.NONE);
        ChartData.Series s = c.series().get(0);
        assertThat(c.reduced()).isTrue();
        assertThat(c.rows()).isEqualTo(200_000);
        assertThat(s.size()).isBetween(1000, ChartData.MAX_POINTS_PER_SERIES);
        double min = Double.MAX_VALUE;
        double max = -Double.MAX_VALUE;
        int gaps = 0;
        for (double y : s.y()) {
            if (Double.isNaN(y)) {
                gaps++;
            } else {
                min = Math.min(min, y);
                max = Math.max(max, y);
            }
        }
        assertThat(max).isEqualTo(99);
        assertThat(min).isEqualTo(-99);
        assertThat(gaps).isEqualTo(1);
        assertThat(s.x()[0]).isEqualTo(0);
        assertThat(s.x()[s.size() - 1]).isEqualTo(199_999);

        StringBuilder t = new StringBuilder("% plot: track\n");
        for (int i = 0; i < 100_000; i++) {
            t.append(-70 - i * 1e-5).append(' ').append(41 + i * 1e-5).append('\n');
        }
        ChartData track = chart(t.toString(), PlotLabels.NONE);
        ChartData.Series ts = track.series().get(0);
        assertThat(ts.size()).isLessThanOrEqualTo(ChartData.MAX_POINTS_PER_SERIES).isGreaterThan(10_000);
        assertThat(ts.x()[ts.size() - 1]).isCloseTo(-70 - 99_999 * 1e-5, within(1e-9)); // the newest fix is kept
        assertThat(track.newest().y()).isCloseTo(41 + 99_999 * 1e-5, within(1e-9));
    }

    @Test
    void manySeriesShareTheTotalBound() throws Exception {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < 30_000; i++) {
            b.append(i);
            for (int s = 0; s < 40; s++) {
                b.append(' ').append(s + i % 7);
            }
            b.append('\n');
        }
        ChartData c = chart(b.toString(), PlotLabels.NONE);
        assertThat(c.series()).hasSize(40);
        assertThat(c.points()).isLessThanOrEqualTo(ChartData.MAX_POINTS);
    }

    @Test
    void theChartCrossesTheWireFilterIntact() throws Exception {
        ChartData c = chart(DataVisServerTest.SAMPLE, PlotLabels.NONE);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(new ImageResult("t.jpg", new byte[] {(byte) 0xFF, (byte) 0xD8}, c));
        }
        for (WireFilter f : new WireFilter[] {WireFilter.forFrames(1 << 20), WireFilter.forRmi(1 << 20)}) {
            try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
                in.setObjectInputFilter(f);
                ImageResult back = (ImageResult) in.readObject();
                assertThat(back.chart().series().get(1).y()).containsExactly(c.series().get(1).y());
                assertThat(back.chart().title()).isEqualTo(c.title());
            }
        }
    }

    @Test
    void theBuiltInWorkersReplyCarriesTheChartAndTheJpeg() throws Exception {
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            OutgoingServiceMessage reply = h.run("vis:t.dat title=\"Dive 3\"", "t.dat", DataVisServerTest.SAMPLE);
            assertThat(reply.footer().status()).isEqualTo(Status.OK);
            ImageResult img = (ImageResult) reply.footer().result();
            assertThat(VisHarness.decode(img.jpeg()).getWidth()).isEqualTo(800);
            assertThat(img.chart()).isNotNull();
            assertThat(img.chart().title()).isEqualTo("Dive 3");
            assertThat(img.chart().series()).hasSize(2);
        }
        assertThat(ChartDataBuilder.forReply(WorkerMode.OCTAVE, DataVisServerTest.SAMPLE.getBytes(StandardCharsets.UTF_8),
                null)).as("Octave and MATLAB draw their own: JPEG only").isNull();
    }
}
