package org.ripv.services.datavis;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.ripv.files.PrivateFiles;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Supervises {@code octave-cli} running {@code ripvOut.m} in the work directory — the thesis's
 * MATLAB worker, which the thesis's service "cannot presently wake up". This one starts it,
 * logs what it prints, and starts it again when it dies (after 1 s, doubling to at most 30 s
 * while it keeps dying young).
 */
public final class OctaveWorker implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(OctaveWorker.class);
    /** The script's resource name; the same bytes as {@code matlab/ripvOut.m} (a test checks). */
    public static final String SCRIPT_RESOURCE = "ripvOut.m";
    private static final Duration FIRST_BACKOFF = Duration.ofSeconds(1);
    private static final Duration MAX_BACKOFF = Duration.ofSeconds(30);
    private static final Duration HEALTHY_RUN = Duration.ofSeconds(60);

    private final Path workDir;
    private final String octave;
    private final Path scriptDir;
    private final ScheduledExecutorService restarts;
    private final AtomicInteger starts = new AtomicInteger();
    private volatile Process process;
    private volatile Instant startedAt = Instant.EPOCH;
    private volatile Duration backoff = FIRST_BACKOFF;
    private volatile boolean closed;
    private volatile String lastExit = "";

    private OctaveWorker(Path workDir, String octave, Path scriptDir) {
        this.workDir = workDir.toAbsolutePath();
        this.octave = octave;
        this.scriptDir = scriptDir;
        this.restarts = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "ripv-datavis-octave-supervisor");
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Starts {@code octave} on {@code ripvOut.m} in {@code workDir}.
     *
     * @param script the ripvOut.m to run, or null for the copy shipped in the jar
     * @throws IOException when the program cannot be started at all (not installed?)
     */
    public static OctaveWorker start(Path workDir, String octave, Path script) throws IOException {
        Path dir;
        if (script != null) {
            if (!Files.isRegularFile(script) || !script.getFileName().toString().equals("ripvOut.m")) {
                throw new IOException("'" + script + "' is not a ripvOut.m file");
            }
            dir = script.toAbsolutePath().getParent();
        } else {
            dir = Files.createTempDirectory("ripv-octave");
            try (InputStream in = OctaveWorker.class.getResourceAsStream(SCRIPT_RESOURCE)) {
                if (in == null) {
                    throw new IOException("ripvOut.m is missing from the jar");
                }
                Files.copy(in, dir.resolve("ripvOut.m"), StandardCopyOption.REPLACE_EXISTING);
            }
            dir.resolve("ripvOut.m").toFile().deleteOnExit();
            dir.toFile().deleteOnExit();
        }
        PrivateFiles.createDirectories(workDir);
        PrivateFiles.restrict(workDir); // Octave writes with its own umask; the directory keeps it private
        OctaveWorker w = new OctaveWorker(workDir, octave, dir);
        w.launch(); // the first start fails loudly; later ones retry
        return w;
    }

    /** The command line that runs ripvOut.m headless. */
    List<String> command() {
        return List.of(octave, "--no-init-file", "--no-history", "--quiet", "--no-window-system",
                "--path", scriptDir.toString(), "--eval", "ripvOut");
    }

    private synchronized void launch() throws IOException {
        if (closed) {
            return;
        }
        ProcessBuilder pb = new ProcessBuilder(command()).directory(workDir.toFile()).redirectErrorStream(true);
        pb.environment().remove("DISPLAY"); // print off screen even on a desktop
        Process p = pb.start();
        process = p;
        startedAt = Instant.now();
        int n = starts.incrementAndGet();
        log.info("started {} on ripvOut.m in {} (pid {}, start #{})", octave, workDir, p.pid(), n);
        Thread pump = new Thread(() -> pump(p.getInputStream()), "ripv-datavis-octave-output-" + p.pid());
        pump.setDaemon(true);
        pump.start();
        p.onExit().thenAccept(this::exited);
    }

    private void pump(InputStream in) {
        try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            String line;
            while ((line = r.readLine()) != null) {
                if (!line.isBlank()) {
                    log.debug("octave: {}", line);
                }
            }
        } catch (IOException e) {
            log.debug("octave output closed: {}", e.toString());
        }
    }

    private void exited(Process p) {
        p.descendants().forEach(ProcessHandle::destroy); // gnuplot, if it outlived Octave
        if (closed) {
            return;
        }
        Duration ran = Duration.between(startedAt, Instant.now());
        backoff = ran.compareTo(HEALTHY_RUN) > 0 ? FIRST_BACKOFF : backoff;
        Duration wait = backoff;
        backoff = backoff.multipliedBy(2).compareTo(MAX_BACKOFF) > 0 ? MAX_BACKOFF : backoff.multipliedBy(2);
        lastExit = "exited with status " + p.exitValue() + " after " + ran.toSeconds() + " s";
        log.warn("{} on ripvOut.m {}; starting it again in {} s", octave, lastExit, wait.toSeconds());
        restarts.schedule(() -> {
            try {
                launch();
            } catch (IOException e) {
                log.error("cannot start {} again: {}", octave, e.getMessage());
                exitedToStart();
            }
        }, wait.toMillis(), TimeUnit.MILLISECONDS);
    }

    /** A start failed: try again later, with the same backoff. */
    private void exitedToStart() {
        if (!closed) {
            restarts.schedule(() -> {
                try {
                    launch();
                } catch (IOException e) {
                    exitedToStart();
                }
            }, backoff.toMillis(), TimeUnit.MILLISECONDS);
        }
    }

    /** Whether Octave is running now. */
    public boolean isAlive() {
        Process p = process;
        return p != null && p.isAlive();
    }

    /** How many times Octave has been started. */
    public int starts() {
        return starts.get();
    }

    /** The running process's id, or -1. */
    public long pid() {
        Process p = process;
        return p != null && p.isAlive() ? p.pid() : -1;
    }

    /** Why the last Octave stopped, or "". */
    public String lastExit() {
        return lastExit;
    }

    /** Kills the running Octave (a cancelled plot); the supervisor starts it again. */
    public void kill() {
        Process p = process;
        if (p != null) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
    }

    /** Stops Octave (and its gnuplot) and does not start it again. */
    @Override
    public void close() {
        closed = true;
        restarts.shutdownNow();
        Process p = process;
        if (p != null) {
            p.descendants().forEach(ProcessHandle::destroy);
            p.destroy();
            try {
                if (!p.waitFor(5, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                p.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }
}
