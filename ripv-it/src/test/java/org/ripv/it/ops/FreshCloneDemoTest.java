package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.testing.Tools;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The README's first command as a new user types it: {@code git clone} of this repository into an
 * empty folder, nothing built, then {@code ./ripv demo} (headless, free ports, a folder of its own),
 * which builds the jars and starts; then the CLI on a real terminal (tmux), as the demo's hint
 * says: {@code --follow sim01}, which follows the glider's console (its calls and dives) instead of
 * opening a prompt, until the glider's first call; then {@code ?history sim01} at the interactive prompt.
 */
@ResourceLock(Shared.CPU)
class FreshCloneDemoTest {
    @TempDir
    Path tmp;

    @Test
    void aFreshCloneRunsTheDemoAsTheReadmeSaysAndTheCliDrivesIt() throws Exception {
        Tools.require("git", "mvn", "tmux");
        assumeTrue(ProcessWatch.supported(), "needs Linux /proc to find the demo's processes");
        Path clone = tmp.resolve("ripv");
        Process git = new ProcessBuilder("git", "clone", "--quiet", RipvScriptHelpTest.ROOT.toString(), clone.toString())
                .redirectErrorStream(true).start();
        String gitOut = new String(git.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(git.waitFor(300, TimeUnit.SECONDS)).isTrue();
        assertThat(git.exitValue()).as(gitOut).isZero();
        assertThat(clone.resolve("ripv-server/target")).as("nothing built in a fresh clone").doesNotExist();

        Path home = Files.createDirectories(tmp.resolve("home"));
        // The first run builds every jar (minutes on a busy 2-core machine); short calls and dives after.
        try (RunningDemo demo = RunningDemo.start(clone, tmp.resolve("demo"), home, Duration.ofMinutes(25),
                Map.of("RIPV_SURFACE_SECONDS", "20", "RIPV_DIVE_SECONDS", "5"))) {
            assertThat(demo.output()).contains("ripv: building the jars").contains("./ripv cli --server localhost:" + demo.port);
            // the first build says how far it is, module by module, and prints no escape codes (issue 32, item 12)
            assertThat(demo.output()).contains("ripv: [2/6] RIPV common").contains("ripv: [6/6] ")
                    .containsPattern("ripv: the jars are built \\(\\d+ s\\)").doesNotContain("\u001b").doesNotContain("[0m");
            assertThat(clone.resolve("ripv-server/target/ripv-server.jar")).exists();

            String cli = "cd '" + clone + "' && export HOME='" + home + "' && unset RIPV_KNOWN_HOSTS RIPV_PASSWORD && ./ripv cli --server localhost:"
                    + demo.port + " --known-hosts '" + demo.dir.resolve("known_hosts") + "' --user demo --password-file '"
                    + demo.dir.resolve("password") + "'";
            // --follow first: it replays the recent entries and then waits for the next, so it is also
            // how a user waits for the demo glider's first call (its JVM starts after the server's, and
            // on a loaded machine the call comes tens of seconds after the demo says it is ready).
            try (Tmux t = new Tmux(200, 50, "bash", "-c", cli + " --follow sim01; echo CLI-EXIT=$?; sleep 600")) {
                String s = t.awaitInScrollback("the glider's call on its console, live", Duration.ofSeconds(240),
                        x -> x.contains("SURFACED") && x.contains("Glider sim01 at surface") || x.contains("CLI-EXIT") || x.contains("Error"));
                assertThat(s).doesNotContain("CLI-EXIT").doesNotContain("Error").doesNotContain("demo@localhost");
                t.keys("C-c");
                t.await("Ctrl-C ends following", Duration.ofSeconds(30), x -> x.contains("CLI-EXIT="));
            }
            try (Tmux t = new Tmux(200, 50, "bash", "-c", cli + "; echo CLI-EXIT=$?; sleep 600")) {
                t.await("the interactive prompt", Duration.ofSeconds(120), s -> Tmux.lastLine(s).startsWith("demo@localhost"));
                t.type("?history sim01");
                t.keys("Enter");
                // The whole transcript, then the prompt again (Ctrl-D only ends the CLI at the prompt); the
                // call's first lines may have scrolled off the screen.
                String s = t.awaitInScrollback("the glider's transcript", Duration.ofSeconds(60),
                        x -> x.contains("entries of <SerialPortServer>::<localhost>sim01") && Tmux.lastLine(x).startsWith("demo@localhost")
                                || x.contains("Error"));
                assertThat(s).contains("entries of <SerialPortServer>::<localhost>sim01").contains("Glider sim01 at surface")
                        .doesNotContain("Error");
                t.keys("C-d");
                t.await("the CLI ends", Duration.ofSeconds(30), x -> x.contains("CLI-EXIT=0"));
            }
        }
    }
}
