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
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 32, item 3: {@code ./ripv demo} starts with each of the simulated glider's dialogs
 * ({@code RIPV_GLIDER_DIALOG=picodos}, {@code gliderdos}; the GliderDOS demo once passed an
 * {@code alert=} pattern RE2 refuses), its glider calls in, the server keeps a call record of the
 * surfacing, and no ALERT is raised for a routine surfacing (the countdown text, "to abort",
 * ABORT HISTORY and sensor names are not trouble).
 */
class DemoDialogsTest {
    static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();

    @TempDir
    Path tmp;

    @ParameterizedTest
    @ValueSource(strings = {"picodos", "gliderdos"})
    void theDemoStartsWithEachDialogAndKeepsCallRecordsWithoutFalseAlerts(String dialog) throws Exception {
        for (String m : List.of("ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")), "needs the jars (mvn package builds them)");
        }
        Path home = tmp.resolve("home");
        try (RunningDemo demo = RunningDemo.start(ROOT, tmp.resolve("demo"), home, Duration.ofMinutes(10),
                Map.of("RIPV_GLIDER_DIALOG", dialog, "RIPV_SURFACE_SECONDS", "6", "RIPV_DIVE_SECONDS", "3"))) {
            String records = "";
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            while (!records.contains("\"vehicle\":\"sim01\"") && System.nanoTime() < end) {
                Thread.sleep(1000);
                records = cli(demo, home, "?surfacings sim01 --json");
            }
            assertThat(records).as("the demo's glider left a call record; server.log:\n" + demo.logOf("server"))
                    .contains("\"vehicle\":\"sim01\"").contains("\"because\":\"Surface interval [1]\"").contains("\"battery_v\":");
            String history = cli(demo, home, "?history sim01 --last 1000");
            assertThat(history).contains("SURFACED").doesNotContain("* ALERT").doesNotContain("ALERT ");
            if (dialog.equals("gliderdos")) {
                assertThat(history).contains("Hit Control-C within").contains("ABORT HISTORY: total since reset: 0");
                assertThat(records).contains("\"abort_total\":0").contains("\"new_abort\":false");
            }
        }
    }

    /** One command through the launched CLI, as the demo's hint says to run it; its output. */
    private static String cli(RunningDemo demo, Path home, String command) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("bash", ROOT.resolve("ripv").toString(), "cli", "--server", "localhost:" + demo.port,
                "--known-hosts", demo.dir.resolve("known_hosts").toString(), "--user", "demo", "--password-file",
                demo.dir.resolve("password").toString(), "--exec", command));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectErrorStream(true);
        pb.environment().put("HOME", home.toString());
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
