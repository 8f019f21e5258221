package org.ripv.it.web;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;

/**
 * The jars a browser test starts as separate processes (as the {@code ripv} launcher does), each
 * with its output in {@code DIR/NAME.log}, and stopped together at the end.
 */
final class LaunchedProcesses {
    private final Path dir;
    private final Duration patience;
    private final List<Process> processes = new ArrayList<>();

    LaunchedProcesses(Path dir, Duration patience) {
        this.dir = dir;
        this.patience = patience;
    }

    /** Starts {@code java -Xmx256m ARGS}, writes {@code input} (or nothing) to it and closes its input. */
    Process launch(String name, String input, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(org.ripv.it.TestJvms.java(), "-Xmx256m"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve(name + ".log").toFile()).start();
        if (input != null) {
            p.getOutputStream().write(input.getBytes(StandardCharsets.UTF_8));
        }
        p.getOutputStream().close();
        synchronized (processes) {
            processes.add(p);
        }
        return p;
    }

    /** What the process printed so far ("" before it printed anything). */
    String log(String name) {
        try {
            return Files.readString(dir.resolve(name + ".log"));
        } catch (IOException e) {
            return "";
        }
    }

    void waitFor(String what, BooleanSupplier check) throws InterruptedException {
        long end = System.nanoTime() + patience.toNanos();
        while (System.nanoTime() < end) {
            if (check.getAsBoolean()) {
                return;
            }
            Thread.sleep(200); // processes of our own starting: nothing to be told by
        }
        throw new AssertionError("waited " + patience + " for " + what + "; logs in " + dir);
    }

    /** Ends every process started, forcibly after 10 s. */
    void stopAll() {
        List<Process> all;
        synchronized (processes) {
            all = List.copyOf(processes);
        }
        all.forEach(Process::destroy);
        for (Process p : all) {
            try {
                if (!p.waitFor(10, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                p.destroyForcibly();
            }
        }
    }
}
