package org.ripv.services.serial;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/** Starts socat (pty pairs, lrzsz behind a pty) for tests, and checks the tools are there. */
public final class Socat implements AutoCloseable {
    private final Process process;
    private final Path log;

    private Socat(Process process, Path log) {
        this.process = process;
        this.log = log;
    }

    /** Runs {@code socat ADDRESS1 ADDRESS2} in {@code cwd} and waits for the pty links to appear. */
    public static Socat start(Path cwd, String address1, String address2, Path... links) throws IOException {
        Path log = Files.createTempFile("socat", ".log");
        List<String> cmd = new ArrayList<>(List.of("socat", "-d", address1, address2));
        Process p = new ProcessBuilder(cmd).directory(cwd.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        Socat socat = new Socat(p, log);
        for (Path link : links) {
            Eventually.await("socat made " + link + "; its log: " + socat.log(), Duration.ofSeconds(10),
                    () -> Files.exists(link) || !p.isAlive());
            if (!p.isAlive()) {
                throw new IOException("socat exited: " + socat.log());
            }
        }
        return socat;
    }

    /** Waits for socat (and the program behind it) to finish; its exit status. */
    public int waitFor(Duration timeout) throws InterruptedException {
        if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new AssertionError("socat still running after " + timeout + "; log: " + log());
        }
        return process.exitValue();
    }

    public String log() {
        try {
            return Files.readString(log);
        } catch (IOException e) {
            return e.toString();
        }
    }

    @Override
    public void close() {
        process.descendants().forEach(ProcessHandle::destroy);
        process.destroy();
        try {
            if (!process.waitFor(5, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
        }
    }
}
