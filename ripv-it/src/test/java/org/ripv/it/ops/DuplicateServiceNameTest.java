package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.ripv.it.ops.CommandProcesses.jar;
import static org.ripv.it.ops.CommandProcesses.java;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.probe.FreePorts;

/**
 * Issue 32, item 11: two service processes with one name, as launched ({@code ripv-server.jar},
 * and {@code ripv-common.jar}'s example ClockService twice with one {@code --host}). The second
 * is refused with who holds the name (address, since when) and exits 1; the first stays
 * registered, with no "registering again" back and forth. Once the first is killed (it stops
 * answering), a third of the same name takes over.
 */
class DuplicateServiceNameTest {
    @TempDir
    Path dir;
    CommandProcesses processes;

    @BeforeEach
    void start() {
        processes = new CommandProcesses(dir);
    }

    @AfterEach
    void stop() throws Exception {
        processes.close();
    }

    Process clock(String log, String registry, Path secret) throws Exception {
        return processes.launch(log, java(), "-Dripv.host=localhost", "-jar", jar("ripv-common"), "--server", registry, "--secret-file",
                secret.toString(), "--host", "localhost");
    }

    static int count(String text, String what) {
        return (int) Pattern.compile(Pattern.quote(what)).matcher(text).results().count();
    }

    @Test
    void aSecondServiceWithARegisteredNameIsRefusedAndExitsUnlessTheFirstStoppedAnswering() throws Exception {
        for (String m : List.of("ripv-server", "ripv-common")) {
            assumeTrue(Files.isRegularFile(Path.of(jar(m))), "needs the jars (mvn verify builds them before this module's tests)");
        }
        int port = FreePorts.one();
        int registry = FreePorts.one();
        Path data = dir.resolve("data");
        processes.launch("server.log", java(), "-jar", jar("ripv-server"), "server", "--data", data.toString(), "--port", "" + port,
                "--registry-port", "" + registry, "--http-port", "0", "--outbound-port", "-1", "--bind", "127.0.0.1");
        processes.awaitLog("server.log", "RIPVServer ready", Duration.ofSeconds(90));
        Path secret = data.resolve("service.secret");
        String server = "127.0.0.1:" + registry;

        Process first = clock("first.log", server, secret);
        processes.awaitLog("first.log", "registered with the RIPVServer", Duration.ofSeconds(60));
        Process second = clock("second.log", server, secret);
        assertThat(second.waitFor(60, TimeUnit.SECONDS)).as("the second exits:\n" + processes.log("second.log")).isTrue();
        assertThat(second.exitValue()).isEqualTo(1);
        assertThat(processes.log("second.log")).as(processes.log("second.log"))
                .containsPattern("Error: the server at 127\\.0\\.0\\.1:\\d+ refused the registration: the name is taken:"
                        + " <ClockService>::<localhost> is registered by another running service at [^ ]+:\\d+, registered since"
                        + " \\d{4}-\\d\\d-\\d\\dT")
                .contains("Stop that one first");
        // No flapping: the first stays registered, and nobody registers again.
        Thread.sleep(8_000);
        assertThat(first.isAlive()).as(processes.log("first.log")).isTrue();
        assertThat(processes.log("first.log")).doesNotContain("no longer knows this service").doesNotContain("registration refused");
        assertThat(count(processes.log("server.log"), ") registered from ")).as(processes.log("server.log")).isEqualTo(1);
        assertThat(processes.log("server.log")).contains("refused a second service named <ClockService>::<localhost>");

        // The first stops answering (killed, no goodbye): the next of that name takes over.
        first.destroyForcibly();
        first.waitFor(20, TimeUnit.SECONDS);
        Process third = clock("third.log", server, secret);
        processes.awaitLog("third.log", "registered with the RIPVServer", Duration.ofSeconds(90));
        Thread.sleep(2_000);
        assertThat(third.isAlive()).as(processes.log("third.log")).isTrue();
        assertThat(processes.log("third.log")).doesNotContain("name is taken");
    }
}
