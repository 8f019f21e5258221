package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 32, item 6: {@code ./ripv demo} as started by a user (headless, its own folder and
 * ports). Its glider carries the real Slocum files of scripts/demo-data, and the queued
 * fetch-slocum-data.wf fetches them on the first call, so {@code positions} has the glider's
 * track right after it (before: {@code Table/View 'POSITIONS' does not exist}). Notifications can
 * be tried: the webhook the hint names is accepted and the demo's receiver gets the events.
 *
 * <p>Its glider speaks PicoDOS, and {@link DemoDialogsTest}'s checks of that dialog (a call record,
 * no false ALERT) are made on this demo rather than on one launched for them (issue 38).
 */
class DemoGliderDataTest {
    @TempDir
    Path tmp;

    record Cli(int exit, String out) {}

    Cli cli(RunningDemo demo, String... lines) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(org.ripv.it.TestJvms.java(),
                "-Duser.home=" + demo.home, "-jar", RipvScriptHelpTest.ROOT.resolve("ripv-client/target/ripv-client.jar").toString(),
                "cli", "--server", "localhost:" + demo.port, "--known-hosts", demo.dir.resolve("known_hosts").toString(),
                "--user", "demo", "--password-file", demo.dir.resolve("password").toString()));
        for (String l : lines) {
            cmd.add("--exec");
            cmd.add(l);
        }
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        return new Cli(p.exitValue(), out);
    }

    @Test
    void theDemosFirstCallBringsRealSlocumDataAndNotificationsReachItsReceiver() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(RipvScriptHelpTest.ROOT.resolve(m + "/target/" + m + ".jar")), "needs the jars");
        }
        assumeTrue(ProcessWatch.supported(), "needs Linux /proc to find the demo's processes");
        try (RunningDemo demo = RunningDemo.start(RipvScriptHelpTest.ROOT, tmp.resolve("demo"), tmp.resolve("home"),
                Duration.ofMinutes(5), Map.of("RIPV_GLIDER_DIALOG", "picodos", "RIPV_SURFACE_SECONDS", "40", "RIPV_DIVE_SECONDS", "5"))) {
            assertThat(demo.output()).contains("queued fetch-slocum-data.wf for sim01's first call")
                    .contains("?notify add webhook http://127.0.0.1:" + demo.webhookPort + "/")
                    .contains(demo.dir.resolve("logs/webhooks.log").toString());
            // Notifications: the hint's subscription is accepted (loopback allowed for the demo's receiver)
            Cli add = cli(demo, "?notify add webhook http://127.0.0.1:" + demo.webhookPort + "/ SURFACED,DIVED,WORKFLOW_DONE");
            assertThat(add.exit()).as(add.out()).isZero();

            String box = "<SerialPortServer>::<localhost>sim01";
            long end = System.nanoTime() + Duration.ofMinutes(4).toNanos();
            // The receiver's WORKFLOW_DONE is the event: a file read, where asking ?receipts every 2 s started
            // a client JVM each time for the minute the first call takes (issue 38: CPU the classes beside it need).
            Path hooks = demo.dir.resolve("logs/webhooks.log");
            long hooked = end - Duration.ofMinutes(1).toNanos(); // then ?receipts as before, with a minute of its own
            while (!(Files.exists(hooks) && Files.readString(hooks).contains("WORKFLOW_DONE")) && System.nanoTime() < hooked) {
                Thread.sleep(200);
            }
            String receipts = "";
            while (!receipts.contains("result: DONE")) {
                assertThat(System.nanoTime()).as("the first call ran fetch-slocum-data.wf; last ?receipts:\n" + receipts
                        + "\nserver.log:\n" + demo.logOf("server")).isLessThan(end);
                Thread.sleep(2000);
                receipts = cli(demo, "?receipts " + box).out();
            }
            assertThat(receipts).contains("fetch-slocum-data.wf").contains("ymodem:get *.cac: OK").contains("ymodem:get *.sbd *.tbd: OK")
                    .contains("rosie_713-2019-166-0-157.sbd").contains("done: fetched 5").doesNotContain("note: ");
            DemoDialogsTest.assertCallRecordWithoutFalseAlerts(demo, "picodos");

            Cli q = cli(demo, "use <DatabaseServer>::<localhost>TTY1", "SELECT COUNT(*) AS n FROM positions WHERE vehicle = 'rosie_713'");
            assertThat(q.exit()).as(q.out()).isZero();
            Matcher m = Pattern.compile("(?m)^\\s*\\|?\\s*(\\d+)\\s*\\|?\\s*$").matcher(q.out());
            assertThat(m.find()).as(q.out()).isTrue();
            assertThat(Long.parseLong(m.group(1))).as("the glider's track in positions").isGreaterThan(10);
            Cli plot = cli(demo, "use <DataVisServer>::<localhost>TTY1", "vis:track rosie_713");
            assertThat(plot.exit()).as(plot.out()).isZero();
            assertThat(plot.out()).contains("track-rosie_713.jpg");

            // The receiver got the events as JSON POSTs
            long until = System.nanoTime() + Duration.ofMinutes(2).toNanos();
            while (!Files.readString(hooks).contains("WORKFLOW_DONE") || !Files.readString(hooks).contains("DIVED")) {
                assertThat(System.nanoTime()).as("webhooks received:\n" + Files.readString(hooks)).isLessThan(until);
                Thread.sleep(1000);
            }
            assertThat(Files.readString(hooks)).contains(" POST / {").contains("sim01");
        }
    }
}
