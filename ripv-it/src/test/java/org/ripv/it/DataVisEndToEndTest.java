package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.FileListing;
import org.ripv.messages.Ids;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.datavis.WorkerMode;

/**
 * The DataVisServer through the whole system (issue 5, "done when"): the CLI puts the shipped
 * sample data file, sends {@code vis:} to the DataVisServer registered over RMI, and a valid JPEG
 * shows in {@code ?dlfiles} and downloads with {@code get}.
 */
class DataVisEndToEndTest {
    static final String MAILBOX = "<DataVisServer>::<localhost>TTY1";
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path dir;

    private static Path sample() {
        Path p = Path.of("..", "docs", "samples", "glider-temperature.dat");
        assertThat(p).as("the demo's sample data file").exists();
        return p;
    }

    private record Cli(int exit, String out, String err) {}

    private static Cli cli(TestSystem sys, String... lines) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int exit = InJvmCli.exec(out, err, InJvmCli.as("alice", "localhost:" + sys.server().port(), "--timeout", "120"), lines);
        return new Cli(exit, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    private static BufferedImage jpeg(Path file) throws Exception {
        byte[] b = Files.readAllBytes(file);
        assertThat(b.length).isGreaterThan(1000);
        assertThat(b[0] & 0xff).isEqualTo(0xFF);
        assertThat(b[1] & 0xff).isEqualTo(0xD8);
        BufferedImage img = ImageIO.read(file.toFile());
        assertThat(img).as("a decodable JPEG").isNotNull();
        return img;
    }

    @Test
    void putThenVisLeavesAJpegInTheDownloadDirectoryWithTheBuiltInWorker() throws Exception {
        try (TestSystem sys = TestSystem.start(dir)) {
            sys.user("alice", "operators");
            DataVisServer vis = new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis")));
            sys.register(vis);
            Path local = dir.resolve("got");
            Files.createDirectories(local);
            Cli run = cli(sys, "put " + sample().toAbsolutePath(), "use " + MAILBOX, "vis:glider-temperature.dat",
                    "?dlfiles", "get glider-temperature.jpg " + local);
            assertThat(run.exit()).as(run.out() + run.err()).isZero();
            assertThat(run.out()).contains("plotted").contains("glider-temperature.jpg");
            BufferedImage img = jpeg(sys.downloaded("glider-temperature.jpg"));
            assertThat(img.getWidth()).isEqualTo(800);
            jpeg(local.resolve("glider-temperature.jpg"));
            try (var files = Files.list(vis.workDir())) {
                assertThat(files).as("the exchange is left clean").isEmpty();
            }

            // The reply the client gets carries the picture for its ImagePanel, marked with the DataVisServer's SID.
            ClientSocketHandler c = sys.login("alice");
            OutgoingServerMessage r = c.call(MAILBOX, "vis:glider-temperature.dat out=dive title=\"Dive 1-3\"",
                    Priority.NORMAL, T, null);
            assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
            assertThat(r.footer().serviceId()).isEqualTo(Ids.SID_DATAVIS);
            assertThat(r.footer().result()).isInstanceOf(ImageResult.class);
            FileListing dl = (FileListing) c.call("", "?dlfiles", Priority.NORMAL, T, null).footer().result();
            // each MailBox's files live in a folder of their own: FOLDER/NAME
            assertThat(dl.files()).extracting(e -> e.name().substring(e.name().indexOf('/') + 1))
                    .contains("glider-temperature.jpg", "dive.jpg");

            // Bad input: an error naming the line, and the next request still works.
            Files.writeString(dir.resolve("bad.dat"), "1 2\n3 oops\n");
            Cli bad = cli(sys, "put " + dir.resolve("bad.dat"), "use " + MAILBOX, "vis:bad.dat");
            assertThat(bad.exit()).isEqualTo(CliCommand.EXIT_ERROR_REPLY);
            assertThat(bad.err()).contains("Error:").contains("line 2").contains("'oops'");
            Cli missing = cli(sys, "use " + MAILBOX, "vis:never-uploaded.dat");
            assertThat(missing.exit()).isEqualTo(CliCommand.EXIT_ERROR_REPLY);
            assertThat(cli(sys, "use " + MAILBOX, "vis:glider-temperature.dat out=again").exit()).isZero();
            jpeg(sys.downloaded("again.jpg"));
        }
    }

    @Test
    void theSameWorksWithTheOctaveWorker() throws Exception {
        assumeTrue(onPath("octave-cli"), "octave-cli is not on the PATH (CI installs octave gnuplot-nox ghostscript "
                + "fonts-dejavu-core fonts-freefont-otf)");
        try (TestSystem sys = TestSystem.start(dir)) {
            sys.user("alice", "operators");
            DataVisServer vis = new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))
                    .withWorker(WorkerMode.OCTAVE).withTimeout(Duration.ofSeconds(90)));
            sys.register(vis);
            Cli run = cli(sys, "put " + sample().toAbsolutePath(), "use " + MAILBOX, "vis:glider-temperature.dat", "?dlfiles");
            assertThat(run.exit()).as(run.out() + run.err()).isZero();
            assertThat(run.out()).contains("octave worker");
            jpeg(sys.downloaded("glider-temperature.jpg"));
        }
    }

    private static boolean onPath(String program) {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String d : path.split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(d, program))) {
                return true;
            }
        }
        return false;
    }
}
