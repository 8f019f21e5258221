package org.ripv.services.datavis;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;

class DataVisServerTest {
    static final String SAMPLE = "% title: Glider temperature\n% xlabel: time (s)\n% ylabel: T (C)\n"
            + "% legend: surface | 10 m\n0 20.1 18.0\n60 20.3 18.1\n120 NaN 18.3\n180 20.6 18.2\n";

    @TempDir
    Path tmp;

    private static ImageResult image(OutgoingServiceMessage reply) {
        assertThat(reply.footer().status()).as(reply.footer().replyText()).isEqualTo(Status.OK);
        assertThat(reply.footer().result()).isInstanceOf(ImageResult.class);
        return (ImageResult) reply.footer().result();
    }

    @Test
    void describesItselfForTheClient() throws Exception {
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            assertThat(h.service.sid()).isEqualTo(Ids.SID_DATAVIS);
            assertThat(h.service.descriptor().panel()).isEqualTo("DAV");
            assertThat(h.service.descriptor().attachPrefixes()).containsExactly("vis:");
            assertThat(h.mailbox()).isEqualTo("<DataVisServer>::<testhost>TTY1");
            List<MailboxStatus> boxes = h.service.mailboxes();
            assertThat(boxes).hasSize(1);
            assertThat(boxes.get(0).available()).isTrue();
        }
    }

    @Test
    void plotsAnAttachedFileThroughTheBuiltInWorkerAndCleansUp() throws Exception {
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            long id = h.send("vis:glider-temperature.dat", "glider-temperature.dat", SAMPLE);
            OutgoingServiceMessage reply = h.finalReply(id, 30);
            ImageResult img = image(reply);
            assertThat(img.name()).isEqualTo("glider-temperature.jpg");
            assertThat(reply.footer().serviceId()).isEqualTo(Ids.SID_DATAVIS);
            assertThat(reply.footer().replyText()).contains("4 rows x 2 series").contains("builtin");
            BufferedImage pic = VisHarness.decode(img.jpeg());
            assertThat(pic.getWidth()).isEqualTo(800);
            assertThat(h.leftovers()).isEmpty();

            OutgoingServiceMessage second = h.run("vis:glider-temperature.dat out=dive3 size=400x300 title=\"Dive 3\"",
                    "glider-temperature.dat", SAMPLE);
            assertThat(image(second).name()).isEqualTo("dive3.jpg");
            assertThat(VisHarness.decode(image(second).jpeg()).getWidth()).isEqualTo(400);
        }
    }

    @Test
    void malformedFilesGetAnErrorNamingTheLineAndTheNextRequestWorks() throws Exception {
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            OutgoingServiceMessage bad = h.run("vis:bad.dat", "bad.dat", "% t\n1 2\n2 x7\n");
            assertThat(bad.footer().status()).isEqualTo(Status.ERROR);
            assertThat(bad.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
            assertThat(bad.footer().replyText()).contains("bad.dat").contains("line 3").contains("'x7'");
            assertThat(h.leftovers()).isEmpty();

            OutgoingServiceMessage ragged = h.run("vis:r.dat", "r.dat", "1 2\n3\n");
            assertThat(ragged.footer().replyText()).contains("line 2").contains("ragged");
            OutgoingServiceMessage empty = h.run("vis:e.dat", "e.dat", "");
            assertThat(empty.footer().replyText()).contains("empty");
            assertThat(h.leftovers()).isEmpty();

            image(h.run("vis:good.dat", "good.dat", SAMPLE));
            assertThat(h.leftovers()).isEmpty();
        }
    }

    @Test
    void missingAttachmentUnknownCommandAndBadOptionsAreExplained() throws Exception {
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            OutgoingServiceMessage none = h.run("vis:nothere.dat", null, (String) null);
            assertThat(none.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
            assertThat(none.footer().replyText()).contains("nothere.dat").contains("upload");
            OutgoingServiceMessage unknown = h.run("plot now", null, (String) null);
            assertThat(unknown.footer().errorCode()).isEqualTo(ErrorCode.UNKNOWN_COMMAND);
            OutgoingServiceMessage opt = h.run("vis:a.dat colour=red", "a.dat", SAMPLE);
            assertThat(opt.footer().replyText()).contains("unknown option 'colour'");
            assertThat(h.run("help", null, (String) null).footer().replyText()).contains("vis:NAME");
        }
    }

    @Test
    void noWorkerWithinTheTimeoutIsAClearErrorThenAHandStartedWorkerProcessServes() throws Exception {
        DataVisServer.Config config = DataVisServer.Config.of(tmp).withWorker(WorkerMode.NONE).withTimeout(Duration.ofSeconds(1));
        try (VisHarness h = new VisHarness(config)) {
            long t0 = System.nanoTime();
            OutgoingServiceMessage late = h.run("vis:a.dat", "a.dat", SAMPLE);
            assertThat(late.footer().status()).isEqualTo(Status.ERROR);
            assertThat(late.footer().errorCode()).isEqualTo(ErrorCode.TIMEOUT);
            assertThat(late.footer().replyText()).contains("no plot worker answered").contains("within 1 s")
                    .contains("ripvOut");
            assertThat(System.nanoTime() - t0).isLessThan(TimeUnit.SECONDS.toNanos(10));
            assertThat(h.leftovers()).isEmpty();

            // The built-in worker as its own process, started by hand, speaks the same protocol.
            Process worker = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", System.getProperty("java.class.path"), "-Djava.awt.headless=true",
                    PlotWorker.class.getName(), tmp.toString()).redirectErrorStream(true)
                    .redirectOutput(tmp.resolveSibling(tmp.getFileName() + "-worker.log").toFile()).start();
            try {
                DataVisServer.Config patient = config.withTimeout(Duration.ofSeconds(30));
                h.service.stop();
                try (VisHarness h2 = new VisHarness(patient)) {
                    ImageResult img = image(h2.run("vis:a.dat", "a.dat", SAMPLE));
                    VisHarness.decode(img.jpeg());
                    assertThat(h2.leftovers()).isEmpty();
                    Files.writeString(tmp.resolve(Exchange.STOP), "");
                    assertThat(worker.waitFor(20, TimeUnit.SECONDS)).as("worker stops on stop.dat").isTrue();
                }
            } finally {
                worker.destroyForcibly();
            }
        }
    }

    @Test
    void workerFailuresAreReportedAndLeaveTheDirectoryClean() throws Exception {
        DataVisServer.Config config = DataVisServer.Config.of(tmp).withWorker(WorkerMode.NONE).withTimeout(Duration.ofSeconds(20));
        try (VisHarness h = new VisHarness(config)) {
            for (FakeWorker.Mode mode : List.of(FakeWorker.Mode.FAIL, FakeWorker.Mode.GARBLE, FakeWorker.Mode.NO_JPEG)) {
                try (FakeWorker w = new FakeWorker(tmp, mode)) {
                    OutgoingServiceMessage r = h.run("vis:a.dat", "a.dat", SAMPLE);
                    assertThat(r.footer().status()).as(mode.name()).isEqualTo(Status.ERROR);
                    assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.WORKER_ERROR);
                    assertThat(r.footer().replyText()).contains(switch (mode) {
                        case FAIL -> "the plot engine exploded";
                        case GARBLE -> "not a JPEG";
                        default -> "wrote no";
                    });
                    assertThat(h.leftovers()).isEmpty();
                    assertThat(w.handled.await(10, TimeUnit.SECONDS)).as("the fake worker answered").isTrue();
                }
            }
        }
    }

    @Test
    void aStaleOkFromAnAbandonedRequestIsNotTakenForTheAnswer() throws Exception {
        DataVisServer.Config config = DataVisServer.Config.of(tmp).withWorker(WorkerMode.NONE).withTimeout(Duration.ofSeconds(30));
        try (VisHarness h = new VisHarness(config); FakeWorker stale = new FakeWorker(tmp, FakeWorker.Mode.STALE)) {
            long id = h.send("vis:a.dat", "a.dat", SAMPLE);
            assertThat(stale.handled.await(20, TimeUnit.SECONDS)).isTrue();
            try (PlotWorker real = PlotWorker.start(tmp)) {
                ImageResult img = image(h.finalReply(id, 30));
                VisHarness.decode(img.jpeg());
                assertThat(real.plots()).isEqualTo(1);
            }
            assertThat(h.leftovers()).isEmpty();
        }
    }

    @Test
    void aWorkerThatSignalsBeforeDeletingItsInputsAsTheThesisDidIsStillUnderstood() throws Exception {
        DataVisServer.Config config = DataVisServer.Config.of(tmp).withWorker(WorkerMode.NONE).withTimeout(Duration.ofSeconds(30));
        try (VisHarness h = new VisHarness(config); FakeWorker w = new FakeWorker(tmp, FakeWorker.Mode.THESIS_ORDER)) {
            VisHarness.decode(image(h.run("vis:a.dat", "a.dat", SAMPLE)).jpeg());
            // The worker deletes its inputs after the service took the answer, so it may finish a moment later.
            assertThat(w.handled.await(10, TimeUnit.SECONDS)).as("the fake worker finished").isTrue();
            assertThat(h.leftovers()).isEmpty();
        }
    }

    @Test
    void plotsOneAtATimeAndEachGetsItsOwnPicture() throws Exception {
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            List<Long> ids = new ArrayList<>();
            for (int i = 0; i < 4; i++) {
                ids.add(h.send("vis:d.dat out=p" + i + " size=" + (200 + 50 * i) + "x200", "d.dat", SAMPLE));
            }
            for (int i = 0; i < 4; i++) {
                ImageResult img = image(h.finalReply(ids.get(i), 60));
                assertThat(img.name()).isEqualTo("p" + i + ".jpg");
                assertThat(VisHarness.decode(img.jpeg()).getWidth()).isEqualTo(200 + 50 * i);
            }
            assertThat(h.leftovers()).isEmpty();
        }
    }

    @Test
    void leftoversOfACrashedRunAreRemovedOnStart() throws Exception {
        Files.writeString(tmp.resolve("ok.dat"), "1");
        Files.writeString(tmp.resolve("data.dat"), "1 2");
        Files.writeString(tmp.resolve("old.jpg"), "x");
        Files.writeString(tmp.resolve("keep.txt"), "not an exchange file");
        try (VisHarness h = new VisHarness(DataVisServer.Config.of(tmp))) {
            assertThat(h.leftovers()).containsExactly("keep.txt");
        }
    }

    @Test
    void launcherParsesOptionsAndTheThesisForm() {
        assertThat(org.ripv.service.ServiceLaunchOptions.thesisForm(new String[] {"//deslab.mit.edu", "--worker", "octave"}))
                .containsExactly("--server", "deslab.mit.edu", "--worker", "octave");
        assertThat(org.ripv.service.ServiceLaunchOptions.thesisForm(new String[] {"--server", "h", "--timeout", "5"}))
                .containsExactly("--server", "h", "--timeout", "5");
        DataVisServerCommand c = new DataVisServerCommand();
        new picocli.CommandLine(c).parseArgs("--server", "h", "--workdir", tmp.toString(), "--worker", "none",
                "--timeout", "7");
        DataVisServer.Config cfg = c.config();
        assertThat(cfg.worker()).isEqualTo(WorkerMode.NONE);
        assertThat(cfg.timeout()).isEqualTo(Duration.ofSeconds(7));
        assertThat(cfg.workDir()).isEqualTo(tmp);
        assertThat(DataVisServerCommand.run("--server", "h", "--worker", "matlab")).isEqualTo(2);
        assertThat(new File(tmp.toFile(), "x").exists()).isFalse();
    }

    @Test
    void launcherFailsClearlyWhenOctaveCannotBeStarted() throws Exception {
        Path secret = tmp.resolve("service.secret");
        Files.writeString(secret, "0123456789abcdef0123456789abcdef");
        java.io.StringWriter err = new java.io.StringWriter();
        picocli.CommandLine cl = new picocli.CommandLine(new DataVisServerCommand());
        cl.setErr(new java.io.PrintWriter(err, true));
        int exit = cl.execute(org.ripv.service.ServiceLaunchOptions.thesisForm(new String[] {"//localhost:1", "--secret-file",
                secret.toString(), "--workdir", tmp.resolve("vis").toString(), "--worker", "octave", "--octave",
                tmp.resolve("no-such-octave").toString()}));
        assertThat(exit).isEqualTo(1);
        assertThat(err.toString()).contains("cannot start the DataVisServer").contains("no-such-octave")
                .contains("is Octave installed?");
    }
}
