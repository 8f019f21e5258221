package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 32, item 3: {@code ./ripv demo} starts with each of the simulated glider's dialogs
 * ({@code RIPV_GLIDER_DIALOG=picodos}, {@code gliderdos}; the GliderDOS demo once passed an
 * {@code alert=} pattern RE2 refuses), its glider calls in, the server keeps a call record of the
 * surfacing, and no ALERT is raised for a routine surfacing (the countdown text, "to abort",
 * ABORT HISTORY and sensor names are not trouble).
 *
 * <p>The PicoDOS demo is {@link DemoGliderDataTest}'s, which makes these checks on it too
 * ({@link #assertCallRecordWithoutFalseAlerts}): a demo launched for each class cost the suite
 * half a minute for checks that only read it (issue 38).
 */
class DemoDialogsTest {
    static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();

    @TempDir
    Path tmp;

    @Test
    void theGliderDosDemoStartsAndKeepsCallRecordsWithoutFalseAlerts() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")), "needs the jars (mvn package builds them)");
        }
        Path home = tmp.resolve("home");
        try (RunningDemo demo = RunningDemo.start(ROOT, tmp.resolve("demo"), home, Duration.ofMinutes(10),
                Map.of("RIPV_GLIDER_DIALOG", "gliderdos", "RIPV_SURFACE_SECONDS", "6", "RIPV_DIVE_SECONDS", "3"))) {
            assertCallRecordWithoutFalseAlerts(demo, "gliderdos");
        }
    }

    /**
     * The running demo's glider (speaking {@code dialog}) left a call record of its surfacing, read
     * through the launched CLI as the demo's hint says, and its history holds the surfacing and no
     * ALERT; a GliderDOS one's countdown and ABORT HISTORY are recorded, not taken for trouble.
     */
    static void assertCallRecordWithoutFalseAlerts(RunningDemo demo, String dialog) throws Exception {
        String records = "";
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (!records.contains("\"vehicle\":\"sim01\"") && System.nanoTime() < end) {
            Thread.sleep(1000);
            records = cli(demo, "?surfacings sim01 --json");
        }
        assertThat(records).as("the demo's glider left a call record; server.log:\n" + demo.logOf("server"))
                .contains("\"vehicle\":\"sim01\"").contains("\"because\":\"Surface interval [1]\"").contains("\"battery_v\":");
        String history = cli(demo, "?history sim01 --last 1000");
        assertThat(history).contains("SURFACED").doesNotContain("* ALERT").doesNotContain("ALERT ");
        if (dialog.equals("gliderdos")) {
            assertThat(history).contains("Hit Control-C within").contains("ABORT HISTORY: total since reset: 0");
            assertThat(records).contains("\"abort_total\":0").contains("\"new_abort\":false");
        }
    }

    /** One command through the launched CLI, as the demo's hint says to run it; its output. */
    private static String cli(RunningDemo demo, String command) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("bash", ROOT.resolve("ripv").toString(), "cli", "--server", "localhost:" + demo.port,
                "--known-hosts", demo.dir.resolve("known_hosts").toString(), "--user", "demo", "--password-file",
                demo.dir.resolve("password").toString(), "--exec", command));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectErrorStream(true);
        pb.environment().put("HOME", demo.home.toString());
        pb.environment().put("JAVA", org.ripv.it.TestJvms.java());
        pb.environment().remove("RIPV_KNOWN_HOSTS");
        pb.environment().remove("RIPV_PASSWORD");
        pb.environment().remove("DISPLAY");
        Process p = pb.start();
        byte[] out = p.getInputStream().readAllBytes();
        p.waitFor(60, TimeUnit.SECONDS);
        return new String(out, StandardCharsets.UTF_8);
    }
}
