package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;

/**
 * ripvOut.m under GNU Octave ({@code octave-cli}), started and restarted by the service.
 * Skipped when Octave is not installed; CI installs it (docs/datavis.md lists the packages).
 * Few plots: each Octave start costs seconds.
 */
class DataVisOctaveTest {
    @TempDir
    Path tmp;

    static boolean octaveInstalled() {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String d : path.split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(d, "octave-cli"))) {
                return true;
            }
        }
        return false;
    }

    @Test
    void theJarCarriesTheSameRipvOutAsTheMatlabDirectory() throws Exception {
        Path repoCopy = Path.of("..", "matlab", "ripvOut.m");
        assumeTrue(Files.exists(repoCopy), "not run from the ripv-services module directory");
        try (InputStream in = OctaveWorker.class.getResourceAsStream(OctaveWorker.SCRIPT_RESOURCE)) {
            assertThat(in).as("ripvOut.m resource").isNotNull();
            assertThat(in.readAllBytes()).as("the jar must carry matlab/ripvOut.m")
                    .isEqualTo(Files.readAllBytes(repoCopy));
        }
    }

    @Test
    void ripvOutUnderOctavePlotsAndIsRestartedWhenItDies() throws Exception {
        assumeTrue(octaveInstalled(), "octave-cli is not on the PATH: install octave gnuplot-nox ghostscript "
                + "fonts-dejavu-core fonts-freefont-otf to run ripvOut.m");
        DataVisServer.Config config = DataVisServer.Config.of(tmp).withWorker(WorkerMode.OCTAVE)
                .withTimeout(Duration.ofSeconds(90));
        try (VisHarness h = new VisHarness(config)) {
            OutgoingServiceMessage first = h.run("vis:glider-temperature.dat size=640x480", "glider-temperature.dat",
                    DataVisServerTest.SAMPLE);
            assertThat(first.footer().status()).as(first.footer().replyText()).isEqualTo(Status.OK);
            ImageResult img = (ImageResult) first.footer().result();
            assertThat(img.name()).isEqualTo("glider-temperature.jpg");
            BufferedImage pic = VisHarness.decode(img.jpeg());
            assertThat(pic.getWidth()).isCloseTo(640, within(2)); // gnuplot rounds the paper size
            assertThat(pic.getHeight()).isCloseTo(480, within(2));
            assertThat(h.leftovers()).isEmpty();
            assertThat(h.service.mailboxes().get(0).available()).isTrue();

            // Kill Octave: the service starts it again, and the next plot is served by the new one.
            OctaveWorker octave = octaveOf(h.service);
            long pid = octave.pid();
            assertThat(pid).isPositive();
            ProcessHandle running = ProcessHandle.of(pid).orElseThrow();
            running.destroyForcibly();
            running.onExit().get(10, TimeUnit.SECONDS);

            OutgoingServiceMessage second = h.run("vis:two.dat", "two.dat", "% title: after restart\n1\n3\n2\n");
            assertThat(second.footer().status()).as(second.footer().replyText()).isEqualTo(Status.OK);
            VisHarness.decode(((ImageResult) second.footer().result()).jpeg());
            assertThat(octave.starts()).isGreaterThanOrEqualTo(2);
            assertThat(h.leftovers()).isEmpty();
        }
    }

    @Test
    void aCancelledOctavePlotKillsOctaveAndTheNextPlotGetsAFreshOne() throws Exception {
        assumeTrue(octaveInstalled(), "octave-cli is not on the PATH: install octave gnuplot-nox ghostscript "
                + "fonts-dejavu-core fonts-freefont-otf to run ripvOut.m");
        StringBuilder big = new StringBuilder(8_000_000);
        for (int i = 0; i < 500_000; i++) {
            big.append(i).append(' ').append(String.format(java.util.Locale.ROOT, "%.3f", Math.sin(i / 1000.0))).append('\n');
        }
        DataVisServer.Config config = DataVisServer.Config.of(tmp).withWorker(WorkerMode.OCTAVE)
                .withTimeout(Duration.ofSeconds(120));
        try (VisHarness h = new VisHarness(config)) {
            OctaveWorker octave = octaveOf(h.service);
            long id = h.send("vis:big.dat", "big.dat", big.toString());
            h.awaitProgress(id, 60); // handed to Octave, which takes many seconds for half a million points
            long pid = octave.pid();
            assertThat(pid).isPositive();
            ProcessHandle drawing = ProcessHandle.of(pid).orElseThrow();
            assertThat(h.cancel(id)).as("the plot is with Octave: the cancel is taken").isTrue();
            // CANCELLED (not OK with a JPEG) and the drawing Octave gone are the proof; the waits only bound a hang.
            OutgoingServiceMessage r = h.finalReply(id, 60);
            assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(org.ripv.messages.ErrorCode.CANCELLED);
            drawing.onExit().get(60, TimeUnit.SECONDS); // the Octave that was drawing it is gone

            OutgoingServiceMessage next = h.run("vis:two.dat", "two.dat", "% title: after the cancel\n1\n3\n2\n");
            assertThat(next.footer().status()).as(next.footer().replyText()).isEqualTo(Status.OK);
            VisHarness.decode(((ImageResult) next.footer().result()).jpeg());
            assertThat(octave.pid()).as("a new Octave").isNotEqualTo(pid);
            assertThat(octave.starts()).isGreaterThanOrEqualTo(2);
            assertThat(h.leftovers()).as("the cancelled plot left nothing in the exchange").isEmpty();
        }
    }

    private static OctaveWorker octaveOf(DataVisServer s) throws Exception {
        java.lang.reflect.Field workers = DataVisServer.class.getDeclaredField("workers"); // the worker is PlotWorkers' (issue 34)
        workers.setAccessible(true);
        java.lang.reflect.Field f = PlotWorkers.class.getDeclaredField("octave");
        f.setAccessible(true);
        return (OctaveWorker) f.get(workers.get(s));
    }
}
