package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import java.util.function.IntPredicate;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;
import org.ripv.services.ingest.DbaFiles;
import org.ripv.services.ingest.DbaHeader;
import org.ripv.services.ingest.DbaReader;
import org.ripv.testing.Tools;

/**
 * The drawing styles of {@code % plot:} (docs/datavis.md) drawn the same way by both workers —
 * the built-in one and {@code ripvOut.m} under GNU Octave — judged from the pictures' pixels:
 * a track at 60° N is a map whose degree of longitude is half as long as one of latitude (a
 * circle 10 km across stays round), with the newest fix circled in red and labelled; depth and
 * profile plots draw depth downwards. Octave is skipped with the reason when absent (and fails
 * under RIPV_REQUIRE_TOOLS). Then both draw the shared unit_363 file's track, depth and profile.
 * With {@code -Dripv.styles.images=DIR} the pictures are kept (docs/images has those of unit_363).
 */
class WorkerStylesTest {
    private static final double LAT = 60;
    @TempDir
    Path tmp;

    @Test
    void theBuiltInWorkerDrawsTheStyles() throws Exception {
        drawsTheStyles(WorkerMode.BUILTIN);
    }

    @Test
    void ripvOutUnderOctaveDrawsTheStylesLikeTheBuiltInWorker() throws Exception {
        Tools.require("octave-cli", "gnuplot");
        drawsTheStyles(WorkerMode.OCTAVE);
    }

    private void drawsTheStyles(WorkerMode mode) throws Exception {
        DataVisServer.Config config = DataVisServer.Config.of(tmp.resolve("work")).withWorker(mode)
                .withTimeout(Duration.ofSeconds(90));
        try (VisHarness h = new VisHarness(config)) {
            String name = mode.name().toLowerCase(Locale.ROOT);

            // A circle 10 km in radius at 60° N, drawn counter-clockwise from due east, stopping
            // at 342°: its newest fix is right of the centre and a little below it.
            StringBuilder track = new StringBuilder("% title: a circle at 60 N\n% xlabel: longitude (degrees east)\n"
                    + "% ylabel: latitude (degrees north)\n% plot: track\n% size: 700x700\n"
                    + "% mark: newest fix 2024-04-08 12:00:00 UTC (gps)\n");
            double end = 0.95 * 2 * Math.PI;
            for (int i = 0; i <= 300; i++) {
                double a = end * i / 300;
                track.append(String.format(Locale.ROOT, "%.6f %.6f%n", -30 + 10 / (111.2 * Math.cos(Math.toRadians(LAT)))
                        * Math.cos(a), LAT + 10 / 111.2 * Math.sin(a)));
            }
            BufferedImage img = plot(h, "circle", track.toString(), name);
            Box line = Box.of(img, WorkerStylesTest::blue);
            assertThat(line.count).as("the track's points are drawn in blue").isGreaterThan(300);
            assertThat((double) line.width() / line.height()).as("a circle at 60 N stays round: the map's aspect is"
                    + " right for the latitude (it would be 2:1 if a degree were a degree)").isCloseTo(1.0, within(0.08));
            Box mark = Box.of(img, WorkerStylesTest::red);
            assertThat(mark.count).as("the newest fix is circled in red").isGreaterThan(20);
            double r = line.width() / 2.0;
            assertThat(mark.centreX()).as("the red mark is on the newest fix")
                    .isCloseTo(line.centreX() + r * Math.cos(end), within(r * 0.12));
            assertThat(mark.centreY()).isCloseTo(line.centreY() - r * Math.sin(end), within(r * 0.12));
            Box label = Box.of(img, WorkerStylesTest::darkRed);
            assertThat(label.count).as("the newest fix is labelled (dark red text)").isGreaterThan(40);
            assertThat(label.width()).as("the label is text, wider than the mark").isGreaterThan(100);

            // Depth growing with time: drawn downwards, the line falls from left to right.
            StringBuilder depth = new StringBuilder("% title: depth\n% xlabel: time (UTC)\n% ylabel: depth (m)\n"
                    + "% plot: depth\n");
            for (int i = 0; i <= 200; i++) {
                depth.append(1_712_577_600L + i * 30).append(' ').append(i).append('\n');
            }
            img = plot(h, "depth", depth.toString(), name);
            line = Box.of(img, WorkerStylesTest::coloured);
            assertThat(meanY(img, line, 0.0, 0.2)).as("depth downwards: shallow on the left is high in the picture")
                    .isLessThan(meanY(img, line, 0.8, 1.0) - line.height() * 0.5);

            // A temperature falling from 20 at the surface to 10 at 200 m: against depth downwards,
            // the line falls from right to left.
            StringBuilder profile = new StringBuilder("% title: profile\n% xlabel: t\n% ylabel: depth (m)\n% plot: profile\n");
            for (int i = 0; i <= 200; i++) {
                profile.append(20 - i / 20.0).append(' ').append(i).append('\n');
            }
            img = plot(h, "profile", profile.toString(), name);
            line = Box.of(img, WorkerStylesTest::coloured);
            assertThat(meanY(img, line, 0.8, 1.0)).as("depth downwards: the warm surface (right) is high in the picture")
                    .isLessThan(meanY(img, line, 0.0, 0.2) - line.height() * 0.5);
            realPlots(h, name);
            assertThat(h.leftovers()).isEmpty();
        }
    }

    /**
     * The three named plots of the shared unit_363 file, as the server hands them to a worker
     * (org.ripv.server.dataloop.PlotRequests: the same label lines, newest fix marked): each
     * worker draws them, the track with its mark. These are docs/datavis.md's pictures
     * ({@code -Dripv.styles.images=docs/images}).
     */
    private void realPlots(VisHarness h, String worker) throws Exception {
        StringBuilder track = new StringBuilder("% title: track of unit_363\n% xlabel: longitude (degrees east)\n"
                + "% ylabel: latitude (degrees north)\n% legend: positions\n% plot: track\n% size: 800x800\n");
        StringBuilder depth = new StringBuilder("% title: depth of unit_363\n% xlabel: time (UTC)\n% ylabel: depth (m)\n"
                + "% legend: m_depth\n% plot: depth\n");
        StringBuilder profile = new StringBuilder("% title: sci_water_temp of unit_363 against depth\n"
                + "% xlabel: sci_water_temp\n% ylabel: depth (m)\n% legend: sci_water_temp\n% plot: profile\n");
        String newest = null;
        try (DbaReader r = new DbaReader(new ByteArrayInputStream(DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg"))))) {
            DbaHeader head = r.header();
            int[][] pairs = {{head.column("m_gps_lon"), head.column("m_gps_lat")}, {head.column("m_lon"), head.column("m_lat")}};
            int mDepth = head.column("m_depth");
            int temp = head.column("sci_water_temp");
            int pressure = head.column("sci_water_pressure");
            double[] row = new double[head.sensors().size()];
            while (r.next(row)) {
                double t = r.time(row);
                for (int p = 0; p < 2; p++) {
                    if (!Double.isNaN(row[pairs[p][0]]) && !Double.isNaN(row[pairs[p][1]])) {
                        track.append(row[pairs[p][0]]).append(' ').append(row[pairs[p][1]]).append('\n');
                        newest = java.time.LocalDateTime.ofEpochSecond((long) Math.floor(t), (int) Math.round((t - Math.floor(t))
                                * 1000) * 1_000_000, java.time.ZoneOffset.UTC).toString().replace('T', ' ')
                                + " UTC (" + (p == 0 ? "gps" : "dead-reckoned") + ")";
                    }
                }
                if (!Double.isNaN(row[mDepth])) {
                    depth.append(t).append(' ').append(row[mDepth]).append('\n');
                }
                if (!Double.isNaN(row[temp]) && !Double.isNaN(row[pressure])) {
                    profile.append(row[temp]).append(' ').append(row[pressure] * 10).append('\n');
                }
            }
        }
        track.append("% mark: newest fix ").append(newest).append('\n');
        BufferedImage img = plot(h, "vis-track-unit_363", track.toString(), worker);
        assertThat(Box.of(img, WorkerStylesTest::red).count).as("the newest fix is marked").isGreaterThan(20);
        assertThat(Box.of(img, WorkerStylesTest::darkRed).width()).as("and labelled").isGreaterThan(100);
        assertThat(Box.of(img, WorkerStylesTest::blue).count).as("the track").isGreaterThan(50);
        assertThat(Box.of(plot(h, "vis-depth-unit_363", depth.toString(), worker), WorkerStylesTest::coloured).count)
                .isGreaterThan(200);
        assertThat(Box.of(plot(h, "vis-profile-unit_363", profile.toString(), worker), WorkerStylesTest::coloured).count)
                .isGreaterThan(200);
    }

    private BufferedImage plot(VisHarness h, String what, String data, String worker) throws Exception {
        OutgoingServiceMessage reply = h.finalReply(h.send("vis:" + what + ".dat", what + ".dat", data), 120);
        assertThat(reply.footer().status()).as(reply.footer().replyText()).isEqualTo(Status.OK);
        byte[] jpeg = ((ImageResult) reply.footer().result()).jpeg();
        String keep = System.getProperty("ripv.styles.images");
        if (keep != null) {
            Files.createDirectories(Path.of(keep));
            Files.write(Path.of(keep, what + "-" + worker + ".jpg"), jpeg);
        }
        return VisHarness.decode(jpeg);
    }

    /** The mean row of the pixels of {@code box} whose column lies in the given fraction of its width. */
    private static double meanY(BufferedImage img, Box box, double from, double to) {
        long sum = 0;
        int n = 0;
        for (int x = box.minX + (int) (from * box.width()); x <= box.minX + (int) (to * box.width()) && x <= box.maxX; x++) {
            for (int y = box.minY; y <= box.maxY; y++) {
                if (coloured(img.getRGB(x, y))) {
                    sum += y;
                    n++;
                }
            }
        }
        assertThat(n).as("line pixels between %.0f%% and %.0f%% of the plot's width", from * 100, to * 100).isPositive();
        return (double) sum / n;
    }

    private static int r(int rgb) {
        return (rgb >> 16) & 0xff;
    }

    private static int g(int rgb) {
        return (rgb >> 8) & 0xff;
    }

    private static int b(int rgb) {
        return rgb & 0xff;
    }

    static boolean blue(int p) {
        return b(p) > 120 && b(p) - r(p) > 80 && b(p) - g(p) > 30;
    }

    static boolean red(int p) {
        return r(p) > 215 && g(p) < 80 && b(p) < 80;
    }

    static boolean darkRed(int p) {
        return r(p) > 120 && r(p) < 200 && g(p) < 50 && b(p) < 50;
    }

    /** A data line's pixel: strongly coloured (not the black, grey and white of text, axes and grid). */
    static boolean coloured(int p) {
        int max = Math.max(r(p), Math.max(g(p), b(p)));
        int min = Math.min(r(p), Math.min(g(p), b(p)));
        return max - min > 60;
    }

    /** The bounding box and centre of the pixels a test picks. */
    private record Box(int minX, int minY, int maxX, int maxY, long count, double sumX, double sumY) {
        static Box of(BufferedImage img, IntPredicate pick) {
            int minX = Integer.MAX_VALUE;
            int minY = Integer.MAX_VALUE;
            int maxX = -1;
            int maxY = -1;
            long n = 0;
            double sx = 0;
            double sy = 0;
            for (int y = 0; y < img.getHeight(); y++) {
                for (int x = 0; x < img.getWidth(); x++) {
                    if (pick.test(img.getRGB(x, y))) {
                        minX = Math.min(minX, x);
                        maxX = Math.max(maxX, x);
                        minY = Math.min(minY, y);
                        maxY = Math.max(maxY, y);
                        n++;
                        sx += x;
                        sy += y;
                    }
                }
            }
            return new Box(minX, minY, maxX, maxY, n, sx, sy);
        }

        int width() {
            return maxX - minX + 1;
        }

        int height() {
            return maxY - minY + 1;
        }

        double centreX() {
            return sumX / count;
        }

        double centreY() {
            return sumY / count;
        }
    }
}
