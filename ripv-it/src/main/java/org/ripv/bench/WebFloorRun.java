package org.ripv.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * {@code bench web}'s floor ({@link WebSocketFloor}) as a process of its own for the whole run,
 * read by readers of its own. It is measured at growing socket counts — right after the server's
 * crowd phase of the same size, paced and timed as that phase is (warm-up, then the measuring
 * seconds, then one second for the last lines) — so each ratio compares two phases of one run
 * with the same sockets, the same readers and the same line rate. Its sockets stay open between
 * phases (idle: no lines), and a phase opens only the ones it adds.
 */
final class WebFloorRun implements AutoCloseable {
    /** One phase: the delays at the floor's sockets and its process's CPU per delivery. */
    record Result(ConsoleBench.Figures f, double cpuMicros, ThreadCpu.Split split) {}

    private final Process floor;
    private final BufferedReader said;
    private final Writer lines;
    private final WebWatchers readers;
    private final WebWatchers.Page page;
    private final List<ConsoleBench.Watch> ws = new ArrayList<>();
    /** Seconds of lines sent at each socket count by {@link #warm}. */
    private final Map<Integer, Integer> warmed = new HashMap<>();
    /** The floor's threads when the phase being measured began recording. */
    private ThreadCpu.Snapshot threads;
    private final int rate;
    private final int warmup;
    private final int seconds;
    final int frame;
    final int writers;

    /**
     * Starts the floor process: frames of {@code frame} bytes on the wire, one writer thread per
     * core (at least two, as the server's writer pool), read by {@code readerThreads} selector threads.
     */
    WebFloorRun(int frame, int readerThreads, int rate, int warmup, int seconds) throws IOException {
        this.frame = frame;
        this.writers = Math.max(2, Runtime.getRuntime().availableProcessors());
        this.rate = rate;
        this.warmup = warmup;
        this.seconds = seconds;
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        floor = new ProcessBuilder(java, "-Xmx256m", "-cp", System.getProperty("java.class.path"),
                WebSocketFloor.class.getName(), Integer.toString(frame), Integer.toString(writers))
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        said = new BufferedReader(new InputStreamReader(floor.getInputStream(), StandardCharsets.US_ASCII));
        lines = new OutputStreamWriter(floor.getOutputStream(), StandardCharsets.US_ASCII);
        String first = said.readLine();
        if (first == null || !first.startsWith("port ")) {
            close();
            throw new IOException("the WebSocket floor did not start: " + first);
        }
        page = new WebWatchers.Page("localhost", Integer.parseInt(first.substring(5).trim()), "x=y", "http://localhost", "");
        readers = new WebWatchers(readerThreads);
    }

    /**
     * Opens {@code sockets} and sends lines at the bench's rate for {@code secs} seconds, measuring
     * nothing: a fresh JVM spends its first seconds at full rate compiling its loop. Measured right
     * after its start on a busy machine (load 20–30), the floor was seconds behind (p50 4.6–7.1 s)
     * where the server, running for minutes, kept up. Done before the server's crowd phase, so the
     * floor is at least as warm as the server when either is measured.
     */
    void warm(int sockets, int secs) throws Exception {
        grow(sockets);
        send((long) secs * rate, -1);
        Thread.sleep(1000);
        warmed.merge(sockets, secs, Integer::sum);
    }

    /**
     * Seconds of lines the floor will have sent at {@code sockets} before its measured seconds
     * there: its warm-up, then its phase's own. The server's phase of that size is warmed as long.
     */
    int warmSeconds(int sockets) {
        return warmed.getOrDefault(sockets, 0) + warmup;
    }

    /** Grows the floor to {@code sockets} sockets and measures one phase at the bench's rate. */
    Result measure(int sockets) throws Exception {
        grow(sockets);
        ws.forEach(w -> w.n.set(0));
        long cpu = send((long) (warmup + seconds) * rate, (long) warmup * rate);
        Thread.sleep(1000); // let the last lines arrive, as the server's phase does
        ws.forEach(w -> w.recording = false);
        cpu = WebBench.processCpuNanos(floor.pid()) - cpu;
        ThreadCpu.Split split = ThreadCpu.between(threads, ThreadCpu.snapshot(floor.pid()));
        ConsoleBench.Figures f = ConsoleBench.figures(ws);
        return new Result(f, cpu / 1000.0 / Math.max(1, f.samples()), split);
    }

    private void grow(int sockets) throws Exception {
        if (sockets > ws.size()) {
            WebBench.connect(readers, page, "floor", ws, sockets - ws.size(), rate * (seconds + 2));
        }
    }

    /**
     * Sends {@code total} lines at the rate; from line {@code recordFrom} on (none when negative)
     * the readers record, and the floor's CPU clock then is returned (0 when never).
     */
    private long send(long total, long recordFrom) throws Exception {
        long period = 1_000_000_000L / rate;
        long start = System.nanoTime();
        long cpu = 0;
        for (long i = 0; i < total; i++) {
            if (i == recordFrom) {
                ws.forEach(w -> w.recording = true);
                threads = ThreadCpu.snapshot(floor.pid());
                cpu = WebBench.processCpuNanos(floor.pid());
            }
            long wait = start + i * period - System.nanoTime();
            if (wait > 0) {
                Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
            }
            lines.write("bench " + i + " " + System.nanoTime() + "\n");
            lines.flush();
        }
        return cpu;
    }

    @Override
    public void close() throws IOException {
        try {
            if (readers != null) {
                readers.close();
            }
        } finally {
            floor.destroy();
            try {
                if (!floor.waitFor(20, TimeUnit.SECONDS)) {
                    floor.destroyForcibly();
                }
            } catch (InterruptedException e) {
                floor.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }
}
