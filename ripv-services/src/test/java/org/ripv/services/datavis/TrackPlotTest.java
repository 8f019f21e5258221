package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.ingest.DbaFiles;
import org.ripv.services.ingest.DbaReader;

/**
 * The {@code % plot: track} style on the real unit_363 file: a map at 800x800 with the newest fix
 * marked in red (docs/datavis.md's pictures come from {@link WorkerStylesTest}).
 */
class TrackPlotTest {
    @TempDir
    Path dir;

    @Test
    void aTrackOfTheSharedFileHasItsNewestFixMarked() throws Exception {
        StringBuilder data = new StringBuilder("% title: track of unit_363\n% xlabel: longitude (degrees east)\n"
                + "% ylabel: latitude (degrees north)\n% legend: positions\n% plot: track\n% size: 800x800\n");
        String newest = null;
        int n = 0;
        try (DbaReader r = new DbaReader(new ByteArrayInputStream(DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg"))))) {
            double[] row = new double[r.header().sensors().size()];
            int lat = r.header().column("m_gps_lat");
            int lon = r.header().column("m_gps_lon");
            while (r.next(row)) {
                if (!Double.isNaN(row[lat]) && !Double.isNaN(row[lon])) {
                    data.append(row[lon]).append(' ').append(row[lat]).append('\n');
                    newest = Instant.ofEpochMilli((long) (r.time(row) * 1000)).toString();
                    n++;
                }
            }
        }
        assertThat(n).isGreaterThan(10);
        data.insert(0, "% mark: newest fix " + newest + "\n");
        Path file = dir.resolve("data.dat");
        Files.writeString(file, data, StandardCharsets.UTF_8);
        PlotRenderer.Rendered out = PlotRenderer.render(file);
        BufferedImage img = ImageIO.read(new ByteArrayInputStream(out.jpeg()));
        assertThat(img.getWidth()).isEqualTo(800);
        assertThat(img.getHeight()).isEqualTo(800);
        int red = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int p = img.getRGB(x, y);
                if (((p >> 16) & 0xff) > 200 && ((p >> 8) & 0xff) < 60 && (p & 0xff) < 60) {
                    red++;
                }
            }
        }
        assertThat(red).as("the newest fix is marked in red (the track itself is blue)").isGreaterThan(20).isLessThan(400);
    }
}
