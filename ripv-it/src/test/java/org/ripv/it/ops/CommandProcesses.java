package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Processes a test starts from command lines ({@code java -jar ripv-server.jar …}), each with its
 * output and errors in a log file of the test's folder; closing stops them, the last started first.
 */
final class CommandProcesses implements AutoCloseable {
    private final Path dir;
    private final List<Process> started = new ArrayList<>();

    CommandProcesses(Path dir) {
        this.dir = dir;
    }

    /** The java that runs the tests, with the flags of short-lived JVMs ({@code org.ripv.it.TestJvms}). */
    static String java() {
        return org.ripv.it.TestJvms.java();
    }

    /** {@code MODULE/target/MODULE.jar}, as {@code mvn package} builds it. */
    static String jar(String module) {
        return RipvScriptHelpTest.ROOT.resolve(module + "/target/" + module + ".jar").toString();
    }

    /** Runs {@code command} with no input, its output to {@code log} in the test's folder. */
    Process launch(String log, String... command) throws IOException {
        return start(new ProcessBuilder(command).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))), log);
    }

    /** Starts {@code pb} with its output and errors to {@code log} in the test's folder. */
    Process start(ProcessBuilder pb, String log) throws IOException {
        Process p = pb.redirectErrorStream(true).redirectOutput(dir.resolve(log).toFile()).start();
        synchronized (started) {
            started.add(p);
        }
        return p;
    }

    /** What is in {@code log} so far ("" before its process started). */
    String log(String log) throws IOException {
        Path p = dir.resolve(log);
        return Files.exists(p) ? Files.readString(p, StandardCharsets.UTF_8) : "";
    }

    /** Waits until {@code log} says {@code text}, at most {@code max}. */
    void awaitLog(String log, String text, Duration max) throws Exception {
        long end = System.nanoTime() + max.toNanos();
        while (!log(log).contains(text)) {
            assertThat(System.nanoTime()).as("'" + text + "' in " + log + ":\n" + log(log)).isLessThan(end);
            Thread.sleep(200);
        }
    }

    /** Stops every process, the last started first, each forcibly after 20 s. */
    @Override
    public void close() throws InterruptedException {
        List<Process> all;
        synchronized (started) {
            all = new ArrayList<>(started);
            started.clear();
        }
        for (int i = all.size() - 1; i >= 0; i--) {
            all.get(i).destroy();
        }
        for (Process p : all) {
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
    }
}
