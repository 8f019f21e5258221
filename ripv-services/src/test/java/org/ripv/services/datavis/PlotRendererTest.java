package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.BufferedWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class PlotRendererTest {
    @TempDir
    Path tmp;

    @Test
    void smallFilesAreDrawnPointByPoint() throws Exception {
        Path f = tmp.resolve("d.dat");
        Files.writeString(f, "% title: T\n% legend: a | b\n1 2 3\n2 NaN 4\n3 4 5\n");
        PlotRenderer.Rendered r = PlotRenderer.render(f);
        assertThat(r.rows()).isEqualTo(3);
        assertThat(r.series()).isEqualTo(2);
        assertThat(r.points()).isEqualTo(6);
        BufferedImage img = VisHarness.decode(r.jpeg());
        assertThat(img.getWidth()).isEqualTo(800);
        assertThat(img.getHeight()).isEqualTo(600);
    }

    @Test
    void sizeLineSetsThePictureSizeAndOneColumnPlotsAgainstRowNumber() throws Exception {
        Path f = tmp.resolve("d.dat");
        Files.writeString(f, "% size: 320x200\n5\n3\n4\n");
        PlotRenderer.Rendered r = PlotRenderer.render(f);
        BufferedImage img = VisHarness.decode(r.jpeg());
        assertThat(img.getWidth()).isEqualTo(320);
        assertThat(img.getHeight()).isEqualTo(200);
        assertThat(r.series()).isEqualTo(1);
    }

    @Test
    void aMillionRowsAreReducedToBoundedPoints() throws Exception {
        Path f = tmp.resolve("big.dat");
        try (BufferedWriter w = Files.newBufferedWriter(f, StandardCharsets.UTF_8)) {
            w.write("% title: a million\n% legend: sin | cos\n");
            for (int i = 0; i < 1_000_000; i++) {
                double x = i * 0.001;
                w.write(i % 100_000 == 50_000 ? x + " NaN NaN\n" : x + " " + Math.sin(x) + " " + Math.cos(x) + "\n");
            }
        }
        PlotRenderer.Rendered r = PlotRenderer.render(f);
        assertThat(r.rows()).isEqualTo(1_000_000);
        // at most 4 points and one break per bucket, 2 x 800 buckets, per series
        assertThat(r.points()).isLessThanOrEqualTo(2L * 5 * 2 * 800);
        assertThat(r.points()).isGreaterThan(2L * 2 * 800);
        VisHarness.decode(r.jpeg());
    }

    @Test
    void aMillionRowsPlotInA48MegabyteHeapWhenTheWorkerRunsAsItsOwnProcess() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("work"));
        try (BufferedWriter w = Files.newBufferedWriter(dir.resolve(Exchange.DATA), StandardCharsets.UTF_8)) {
            w.write("% title: a million rows, 3 series\n");
            for (int i = 0; i < 1_000_000; i++) {
                w.write(i + " " + (i % 977) + " " + Math.sqrt(i) + " " + (i % 10_007 == 0 ? "NaN" : "-1") + "\n");
            }
        }
        Files.writeString(dir.resolve(Exchange.INFO), "million\n");
        Files.writeString(dir.resolve(Exchange.STOP), ""); // plot what is there, then stop
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx48m",
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), PlotWorker.class.getName(),
                dir.toString()).redirectErrorStream(true).redirectOutput(tmp.resolve("worker.log").toFile()).start();
        boolean done = p.waitFor(120, java.util.concurrent.TimeUnit.SECONDS);
        if (!done) {
            p.destroyForcibly();
        }
        assertThat(done).as("worker finished").isTrue();
        assertThat(Files.readString(dir.resolve(Exchange.OK)).strip()).as(Files.readString(tmp.resolve("worker.log")))
                .isEqualTo("1");
        VisHarness.decode(Files.readAllBytes(dir.resolve("million.jpg")));
        assertThat(dir.resolve(Exchange.DATA)).doesNotExist();
        assertThat(dir.resolve(Exchange.INFO)).doesNotExist();
    }

    @Test
    void aGapLeavesItsColumnsEmpty() throws Exception {
        // a flat line at y=1 from x=0..100 with x 30..70 missing: the middle of the plot has no line pixels
        StringBuilder sb = new StringBuilder("% size: 400x300\n0 0\n"); // (0,0) fixes the y range below the line
        for (int x = 0; x <= 100; x++) {
            sb.append(x).append(' ').append(x > 30 && x < 70 ? "NaN" : "1").append('\n');
        }
        Path f = tmp.resolve("gap.dat");
        Files.writeString(f, sb.toString());
        byte[] jpeg = PlotRenderer.render(f).jpeg();
        BufferedImage img = VisHarness.decode(jpeg);
        assertThat(redPixelsInColumn(img, 200)).as("no line drawn in the gap").isZero();
        assertThat(redPixelsInColumn(img, 100)).as("the line outside the gap").isPositive();
    }

    private static int redPixelsInColumn(BufferedImage img, int x) {
        int n = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            int rgb = img.getRGB(x, y);
            int r = (rgb >> 16) & 0xff;
            int g = (rgb >> 8) & 0xff;
            int b = rgb & 0xff;
            if (r > 150 && r - g > 60 && r - b > 60) { // the first series' red
                n++;
            }
        }
        return n;
    }
}
