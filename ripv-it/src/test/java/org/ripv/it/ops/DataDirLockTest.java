package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A data directory is locked by the server that uses it ({@code DataDirLock}): with the server
 * jar launched as {@code ./ripv} does, a second server on the same directory says which process
 * holds it, exits 1 and leaves every file as it was; once the first is killed (even with
 * SIGKILL) the OS has let go of the lock and a new server starts there.
 */
class DataDirLockTest {
    static final Path JAR = RipvScriptHelpTest.ROOT.resolve("ripv-server/target/ripv-server.jar");

    @TempDir
    Path tmp;
    final List<Process> started = new ArrayList<>();

    @AfterEach
    void stop() {
        started.forEach(Process::destroyForcibly);
    }

    Process server(Path data, Path log) throws IOException {
        String java = org.ripv.it.TestJvms.java();
        Process p = new ProcessBuilder(java, "-Duser.home=" + tmp.resolve("home"), "-jar", JAR.toString(), "server",
                "--data", data.toString(), "--port", "0", "--registry-port", "0", "--http-port", "0", "--outbound-port", "-1")
                .redirectErrorStream(true).redirectOutput(log.toFile()).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .start();
        started.add(p);
        return p;
    }

    static void awaitReady(Process p, Path log) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (!Files.readString(log, StandardCharsets.UTF_8).contains("RIPVServer ready")) {
            assertThat(p.isAlive()).as("the server ended: " + Files.readString(log, StandardCharsets.UTF_8)).isTrue();
            assertThat(System.nanoTime()).as("the server is ready").isLessThan(end);
            p.waitFor(100, TimeUnit.MILLISECONDS);
        }
    }

    /** Every file under dir with its size and modification time. */
    static Map<String, String> snapshot(Path dir) throws IOException {
        Map<String, String> files = new TreeMap<>();
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                files.put(dir.relativize(p).toString(), Files.isDirectory(p) ? "dir"
                        : Files.size(p) + " " + Files.getLastModifiedTime(p).toMillis());
            }
        }
        return files;
    }

    @Test
    void aSecondServerOnTheSameDataDirectorySaysWhoHoldsItAndTouchesNothing() throws Exception {
        assumeTrue(Files.isRegularFile(JAR), "needs ripv-server.jar (mvn package)");
        Path data = tmp.resolve("data");
        Path log1 = tmp.resolve("first.log");
        Process first = server(data, log1);
        awaitReady(first, log1);
        assertThat(Files.readString(data.resolve("server.lock"), StandardCharsets.UTF_8)).startsWith("process " + first.pid() + " on host ");

        Map<String, String> before = snapshot(data);
        Path log2 = tmp.resolve("second.log");
        Process second = server(data, log2);
        assertThat(second.waitFor(120, TimeUnit.SECONDS)).as("the second server stops by itself").isTrue();
        String out = Files.readString(log2, StandardCharsets.UTF_8);
        assertThat(second.exitValue()).as(out).isEqualTo(1);
        assertThat(out).contains("Error: the data directory " + data + " is in use by process " + first.pid() + " on host ")
                .contains("give this one another --data DIR").doesNotContain("Exception");
        assertThat(snapshot(data)).as("nothing in the directory changed").isEqualTo(before);
        assertThat(first.isAlive()).isTrue();

        // SIGKILL: no shutdown hook runs, and still the lock is gone with the process.
        first.destroyForcibly().waitFor(60, TimeUnit.SECONDS);
        Path log3 = tmp.resolve("third.log");
        Process third = server(data, log3);
        awaitReady(third, log3);
        assertThat(Files.readString(data.resolve("server.lock"), StandardCharsets.UTF_8)).startsWith("process " + third.pid() + " on host ");
    }
}
