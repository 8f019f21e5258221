package org.ripv.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.Writer;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.channels.SocketChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.probe.FreePorts;
import org.ripv.server.ServerMain;
import org.ripv.server.permit.PermitFile;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The web console at scale (issue 21, docs/performance.md): a real server in a JVM of its own
 * (heap capped), N WebSocket watchers of one vehicle printing at a steady rate, measured at the
 * watchers' sockets from the vehicle's write to the read, against one watcher in the same run;
 * the server's threads, heap and CPU per delivered line; one page that never reads; and the fleet
 * page with 100 vehicles ({@link FleetPageTiming}).
 *
 * <p>The server's CPU per delivery is set against a floor's ({@link WebFloorRun}: plain WebSocket
 * frames of the push's size to as many sockets, a process of its own) measured right after the
 * crowd phase of the same size: at 1,000 watchers, the judged figure (issue 38: the floor keeps
 * up there on 2 cores), and at the full crowd, reported with its label (there the floor itself
 * fell behind on 2 cores that also run every reader).
 *
 * <p>Longer than 400 lines because its phases share one server and one crowd of sockets, each
 * phase measured against the one before it; the parts that stand alone are classes of their own
 * (the floor, the fleet page's timing, the per-thread CPU).
 */
@Command(name = "web", mixinStandardHelpOptions = true,
        description = "The web console: N WebSocket watchers of one vehicle against one, and the fleet page with 100 vehicles.")
public final class WebBench implements Callable<Integer> {
    @Option(names = "--watchers", defaultValue = "10000", description = "WebSocket watchers in the crowd (default ${DEFAULT-VALUE}).")
    int watchers;
    @Option(names = "--rate", defaultValue = "50", description = "Lines per second the vehicle prints (default ${DEFAULT-VALUE}).")
    int rate;
    @Option(names = "--seconds", defaultValue = "20", description = "Measuring time per crowd phase (default ${DEFAULT-VALUE}).")
    int seconds;
    @Option(names = "--baseline-seconds", defaultValue = "30", description = "Measuring time of the one-watcher phase (default ${DEFAULT-VALUE}).")
    int baselineSeconds;
    @Option(names = "--warmup", defaultValue = "5", description = "Warm-up seconds per phase (default ${DEFAULT-VALUE}: at 3 the server was still compiling the 1,000-page path in the measured seconds).")
    int warmup;
    @Option(names = "--vehicles", defaultValue = "100", description = "Vehicles on the fleet page (default ${DEFAULT-VALUE}).")
    int vehicles;
    @Option(names = "--fleet-runs", defaultValue = "5", description = "Fleet page loads timed (default ${DEFAULT-VALUE}).")
    int fleetRuns;
    @Option(names = "--heap", defaultValue = "1g", description = "The server JVM's -Xmx (default ${DEFAULT-VALUE}).")
    String heap;
    @Option(names = "--reader-threads", description = "Selector threads reading the watchers (default: one per core).")
    int readerThreads = Runtime.getRuntime().availableProcessors();
    @Option(names = "--server-jvm-option", paramLabel = "OPTION", description = "One more option for the server's JVM, after the"
            + " product's own and -Xmx (repeatable; e.g. --server-jvm-option=-XX:StartFlightRecording=filename=web.jfr to profile"
            + " it; a collector, e.g. -XX:+UseG1GC, replaces the product's -XX:+UseParallelGC). Default: none, the server as"
            + " ./ripv server launches it.")
    List<String> serverJvmOptions = new ArrayList<>();

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    private final PrintStream out;

    public WebBench() {
        this(System.out);
    }

    WebBench(PrintStream out) {
        this.out = out;
    }

    /** Refuses counts and times the benchmark cannot run with, naming the option. */
    private void check() {
        String bad = watchers < 1 || watchers > 15_000 ? "--watchers must be 1 to 15000 (two sockets each must fit under"
                + " the open-file limit), got " + watchers
                : rate < 1 || rate > 10_000 ? "--rate must be 1 to 10000 lines a second, got " + rate
                : seconds < 1 || seconds > 3600 ? "--seconds must be 1 to 3600, got " + seconds
                : baselineSeconds < 1 || baselineSeconds > 3600 ? "--baseline-seconds must be 1 to 3600, got " + baselineSeconds
                : warmup < 0 || warmup > 600 ? "--warmup must be 0 to 600, got " + warmup
                : vehicles < 1 || vehicles > 1000 ? "--vehicles must be 1 to 1000, got " + vehicles
                : fleetRuns < 1 || fleetRuns > 100 ? "--fleet-runs must be 1 to 100, got " + fleetRuns
                : !heap.matches("\\d+[kmgKMG]?") ? "--heap must be a size as java's -Xmx takes it (e.g. 1g, 768m), got '" + heap + "'"
                : readerThreads < 1 || readerThreads > 64 ? "--reader-threads must be 1 to 64, got " + readerThreads : null;
        if (bad != null) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), bad);
        }
    }

    /** The server process and what its ready line said. */
    record Server(Process process, int port, int registryPort, Path secretFile, int httpPort) {
        long pid() {
            return process.pid();
        }
    }

    @Override
    public Integer call() throws Exception {
        check();
        Path dir = Files.createTempDirectory("ripv-bench-web");
        out.printf("RIPV web console benchmark — %d cores, Java %s, %d lines/s, %d s per crowd phase after %d s warm-up"
                        + " (one watcher: %d s); server -Xmx%s%s; %s%n", Runtime.getRuntime().availableProcessors(),
                System.getProperty("java.version"), rate, seconds, warmup, baselineSeconds, heap,
                " " + String.join(" ", jvmOptions(serverJvmOptions)), CpuClock.machineLine());
        PermitFile.setUser(dir.resolve("permit.txt"), "bench", "bench-password".toCharArray(), List.of("observers"), 1000);
        Server server = start(dir);
        ServiceConnector vehicleLink = null;
        ServiceConnector fleetLink = null;
        WebFloorRun floor = null;
        VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
        FleetService fleet = new FleetService("localhost", vehicles);
        try {
            String secret = Files.readString(server.secretFile(), StandardCharsets.UTF_8).trim();
            ServiceOptions options = new ServiceOptions("localhost", server.registryPort(), secret, 0, Duration.ofSeconds(5));
            vehicleLink = ServiceConnector.connect(vehicle, options);
            vehicleLink.awaitRegistered(Duration.ofSeconds(30));
            fleetLink = ServiceConnector.connect(fleet, options);
            fleetLink.awaitRegistered(Duration.ofSeconds(30));
            fleet.surfaceAll();
            WebWatchers.Page page = login(server.httpPort(), "bench", "bench-password");
            String box = vehicle.mailbox();
            out.printf("(plain HTTP on the server's web port: TLS would add each socket's own encryption, the same with any"
                    + " design; the watchers are read raw on %d selector threads: WebWatchers)%n", readerThreads);
            long[] idle = sample(server.pid());
            out.printf("server idle: %d threads, live heap %d MiB%n", idle[0], idle[2] >> 10);
            new FleetPageTiming(out, vehicles, fleetRuns).run(page, server.httpPort());

            WebWatchers readers = new WebWatchers(readerThreads);
            List<ConsoleBench.Watch> one = new ArrayList<>(List.of(new ConsoleBench.Watch(() -> { }, rate * (baselineSeconds + 2), null)));
            readers.add(page, box, one.get(0)::record);
            Phase base = run(vehicle, one, baselineSeconds, server);
            report("1 watcher", base, base, "");
            int frame = Math.max(readers.smallestPushBytes(), 64); // one line's push (a watcher behind gets several in one)

            int first = Math.min(JUDGED, watchers);
            floor = new WebFloorRun(frame, readerThreads, rate, warmup, seconds);
            floor.warm(first, warmup + seconds / 2);

            List<ConsoleBench.Watch> crowd = new ArrayList<>();
            long t0 = System.nanoTime();
            // 1,000 first: the size at which the wall targets are judged (p99 ≤ 100 ms and ≤ 3× one watcher)
            connect(readers, page, box, crowd, first, rate * (seconds + 2));
            // Warmed as long at this size as the floor is before its measured seconds (its warm-up
            // above, then its phase's own): with 5 s the server was still compiling the 1,000-page
            // path in the measured seconds (issue 38: the JIT's share is printed beside the figure).
            Phase judged = run(vehicle, crowd, seconds, server, floor.warmSeconds(first));
            report(first + " watchers", judged, base, "   (targets: p99 ≤ 100 ms and ≤ 3×)");
            // The floor at the same size right away: at 1,000 it keeps up on 2 cores, at 10,000 it did not (issue 38).
            floorPhase(floor, judged, first, true, "");
            Phase many = judged;
            if (watchers > first) {
                connect(readers, page, box, crowd, watchers - first, rate * (seconds + 2));
                out.printf("%d WebSockets opened and watching in %.1f s%n", watchers, (System.nanoTime() - t0) / 1e9);
                crowd.forEach(w -> w.n.set(0));
                many = run(vehicle, crowd, seconds, server);
                report(watchers + " watchers", many, base, "   (wall: bounded by this machine, whose "
                        + Runtime.getRuntime().availableProcessors() + " cores also run every reader; " + CpuClock.machineLine() + ")");
            }
            long[] full = sample(server.pid());
            out.printf("server with %d watchers: %d threads (%+d from idle: no thread per watcher), resident %d MiB,"
                            + " live heap after GC %d MiB (target: under 1 GiB; -Xmx%s)%n", watchers, full[0], full[0] - idle[0],
                    full[1] >> 10, full[2] >> 10, heap);

            SocketChannel stalled = WebWatchers.stalled(page, box);
            crowd.forEach(w -> w.n.set(0));
            Phase withStall = run(vehicle, crowd, seconds, server);
            report(watchers + " + 1 never reading", withStall, base, "");
            out.printf("  p99 with it / p99 without it: %.2f× (target: unchanged)%n", withStall.f().p99Ms() / many.f().p99Ms());
            readers.close(); // the crowd leaves: the flood below is for the one that never reads
            flood(vehicle);
            long[] after = sample(server.pid());
            try (WebWatchers again = new WebWatchers(1)) {
                WebWatchers.Conn resumed = again.resume(stalled, n -> { });
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
                while (resumed.markers == 0 && !resumed.closed && System.nanoTime() < until) {
                    vehicle.line("bench-after-stall");
                    Thread.sleep(200);
                }
                out.printf("  the one that never read, after a flood of %,d lines of 1,000 bytes: %s; server live heap after GC %d MiB,"
                                + " %d threads%n", FLOOD,
                        resumed.closed ? "cut off by the server"
                                : resumed.markers > 0 ? "kept, the lines beyond its bound skipped and marked (\"N lines skipped\")"
                                : "neither cut off nor marked within 20 s",
                        after[2] >> 10, after[0]);
            }
            if (watchers > first) {
                floorPhase(floor, many, watchers, false, "reported, not judged: bounded by this machine, whose "
                        + Runtime.getRuntime().availableProcessors() + " cores also run every reader");
            }
        } finally {
            if (floor != null) {
                floor.close();
            }
            if (vehicleLink != null) {
                vehicleLink.close();
            }
            if (fleetLink != null) {
                fleetLink.close();
            }
            vehicle.stop();
            fleet.stop();
            server.process().destroy();
            if (!server.process().waitFor(20, TimeUnit.SECONDS)) {
                server.process().destroyForcibly();
            }
        }
        out.println(CpuClock.machineLine());
        return 0;
    }

    /** Lines in the flood the page that never reads cannot absorb in its socket buffers. */
    static final int FLOOD = 20_000;

    /** A flood: more than a stalled page's socket buffers hold, at a pace the service's own publishing queue takes. */
    private static void flood(VehicleConsoleService vehicle) throws InterruptedException {
        String pad = "x".repeat(1000);
        for (int i = 0; i < FLOOD; i++) {
            vehicle.line("flood " + i + " " + pad);
            if (i % 2_000 == 1_999) {
                Thread.sleep(100);
            }
        }
        Thread.sleep(2000);
    }

    /** Opens the crowd's sockets on a few threads (each upgrade and ?watch is a blocking exchange). */
    static void connect(WebWatchers readers, WebWatchers.Page page, String box, List<ConsoleBench.Watch> crowd, int count,
                                int capacity) throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            List<Future<ConsoleBench.Watch>> opened = new ArrayList<>();
            for (int i = 0; i < count; i++) {
                opened.add(pool.submit(() -> {
                    ConsoleBench.Watch w = new ConsoleBench.Watch(() -> { }, capacity, null);
                    readers.add(page, box, w::record);
                    return w;
                }));
            }
            for (Future<ConsoleBench.Watch> f : opened) {
                crowd.add(f.get(120, TimeUnit.SECONDS));
            }
        } finally {
            pool.shutdownNow();
        }
    }

    /** The figures of one phase and the CPU both processes spent per line delivered to one watcher. */
    private record Phase(ConsoleBench.Figures f, double serverCpuMicros, double benchCpuMicros, ThreadCpu.Split server) {
        double cpuMicros() {
            return serverCpuMicros + benchCpuMicros;
        }

        /** "JIT a, GC b, the rest c": the server's CPU per delivery by kind of thread. */
        String split() {
            return WebBench.split(server, f.samples());
        }
    }

    /** A process's CPU per delivery by kind of thread ({@link ThreadCpu}). */
    static String split(ThreadCpu.Split s, long deliveries) {
        double n = Math.max(1, deliveries) * 1000.0;
        return String.format("JIT %.1f, GC %.1f, the rest %.1f", s.jitNanos() / n, s.gcNanos() / n, s.restNanos() / n);
    }

    /** Prints "bench I NANOS" lines at the rate for warm-up plus measuring time; the delays seen while measuring. */
    private Phase run(VehicleConsoleService vehicle, List<ConsoleBench.Watch> ws, int secs, Server server) throws Exception {
        return run(vehicle, ws, secs, server, warmup);
    }

    /** As above, after {@code warm} seconds of lines not measured. */
    private Phase run(VehicleConsoleService vehicle, List<ConsoleBench.Watch> ws, int secs, Server server, int warm) throws Exception {
        long period = 1_000_000_000L / rate;
        long start = System.nanoTime();
        long total = (long) (warm + secs) * rate;
        long serverCpu = 0;
        long benchCpu = 0;
        ThreadCpu.Snapshot threads = null;
        for (long i = 0; i < total; i++) {
            if (i == (long) warm * rate) {
                ws.forEach(w -> w.recording = true);
                threads = ThreadCpu.snapshot(server.pid());
                serverCpu = processCpuNanos(server.pid());
                benchCpu = CpuClock.processCpuNanos();
            }
            long wait = start + i * period - System.nanoTime();
            if (wait > 0) {
                Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
            }
            vehicle.line("bench " + i + " " + System.nanoTime());
        }
        Thread.sleep(1000); // let the last lines arrive
        ws.forEach(w -> w.recording = false);
        serverCpu = processCpuNanos(server.pid()) - serverCpu;
        benchCpu = CpuClock.processCpuNanos() - benchCpu;
        ThreadCpu.Split split = ThreadCpu.between(threads, ThreadCpu.snapshot(server.pid()));
        ConsoleBench.Figures f = ConsoleBench.figures(ws);
        double n = Math.max(1, f.samples());
        return new Phase(f.withCpu((serverCpu + benchCpu) / 1000.0 / n), serverCpu / 1000.0 / n, benchCpu / 1000.0 / n, split);
    }

    private void report(String what, Phase p, Phase base, String note) {
        ConsoleBench.Figures f = p.f();
        out.printf("%-26s p50 %7.2f ms   p99 %7.2f ms   max %8.2f ms   %8d samples   %d skipped   cpu %.1f us/line (server %.1f,"
                        + " watchers and vehicle %.1f)   p99 %.2f× one watcher%s%n", what, f.p50Ms(), f.p99Ms(), f.maxMs(), f.samples(),
                f.skipped(), p.cpuMicros(), p.serverCpuMicros(), p.benchCpuMicros(), f.p99Ms() / base.f().p99Ms(), note);
        out.printf("  the server's CPU per delivery by thread: %s us%n", p.split());
        if (f.shortOnes() > 0) {
            out.printf("  %d watcher(s) saw fewer lines than the others (the fewest: %d)%n", f.shortOnes(), f.fewest());
        }
    }

    /** The crowd size at which the wall targets are judged. */
    static final int JUDGED = 1_000;

    /**
     * The floor's phase of {@code sockets} and the line comparing the server's CPU per delivery in
     * the crowd phase of the same size with the floor's ({@link WebFloorRun}). {@code judged}: the
     * size the CPU target is judged at; otherwise reported with the label {@code label}.
     */
    private void floorPhase(WebFloorRun floor, Phase crowd, int sockets, boolean judged, String label) throws Exception {
        WebFloorRun.Result r = floor.measure(sockets);
        ConsoleBench.Figures bare = r.f();
        out.printf("%-26s p50 %7.2f ms   p99 %7.2f ms   max %8.2f ms   %8d samples   cpu %.2f us per delivery (the floor's"
                        + " process: %d-byte WebSocket frames, %d writer threads, no RIPV)   %s%n", "WebSocket floor, " + sockets,
                bare.p50Ms(), bare.p99Ms(), bare.maxMs(), bare.samples(), r.cpuMicros(), floor.frame, floor.writers,
                CpuClock.machineLine());
        out.printf("  the floor's CPU per delivery by thread: %s us%n", split(r.split(), bare.samples()));
        boolean behind = bare.p50Ms() > 1000.0 / rate * 10;
        out.println(CpuClock.ratioLine("server per delivery to each of " + sockets + " web watchers", crowd.serverCpuMicros(),
                r.cpuMicros(), crowd.f().p99Ms() / bare.p99Ms()) + (judged && !behind ? "   (target: CPU ≤ 2×; the judged figure)"
                : judged ? "   (target: CPU ≤ 2×; not judged: the floor fell behind)" : "   (" + label + ")"));
        if (behind) {
            out.printf("  the floor itself fell behind (p50 %.0f ms): this machine cannot carry the fan-out now, so this ratio"
                    + " is no measurement (%s)%n", bare.p50Ms(), CpuClock.machineLine());
        }
    }

    /** Logs in with the web form as a browser does: the session cookie and the CSRF token. */
    static WebWatchers.Page login(int httpPort, String user, String password) throws Exception {
        HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
        String origin = "http://localhost:" + httpPort;
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(URI.create(origin + "/login")).header("Origin", origin)
                .header("Content-Type", "application/x-www-form-urlencoded").POST(HttpRequest.BodyPublishers.ofString(
                        "user=" + user + "&password=" + password)).build(), HttpResponse.BodyHandlers.ofString());
        if (r.statusCode() != 303) {
            throw new IOException("the web log-in failed: " + r.statusCode() + " " + r.body());
        }
        String cookie = r.headers().firstValue("Set-Cookie").orElseThrow().split(";")[0];
        Matcher m = Pattern.compile("\"csrf\":\"([0-9a-f]+)\"").matcher(FleetPageTiming.get(http, origin + "/api/session", cookie));
        if (!m.find()) {
            throw new IOException("no CSRF token in /api/session");
        }
        return new WebWatchers.Page("localhost", httpPort, cookie, origin, m.group(1));
    }

    /** Starts the server jar's main in a JVM of its own, with the web console on a free port. */
    private Server start(Path dir) throws IOException {
        return startServer(dir, heap, watchers + 200, 2 * (watchers + 200), serverJvmOptions); // the bench's crowd is one log-in's pages
    }

    /**
     * The server jar's main in a JVM of its own on free ports, plain, with the web console, and
     * with the JVM options {@code ./ripv server} gives it ({@code ServerMain.JVM_OPTIONS}); also
     * used by {@link WebLoadBench}.
     */
    static Server startServer(Path dir, String heap, int maxClients, int webPages) throws IOException {
        return startServer(dir, heap, maxClients, webPages, List.of());
    }

    /** As above, with {@code jvmOptions} after -Xmx and the product's own options (a profiler's, say). */
    static Server startServer(Path dir, String heap, int maxClients, int webPages, List<String> jvmOptions) throws IOException {
        int httpPort = FreePorts.one();
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-Xmx" + heap));
        cmd.addAll(jvmOptions(jvmOptions));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "org.ripv.server.ServerMain",
                "server", "--data", dir.toString(), "--port", "0", "--registry-port", "0", "--http-port", Integer.toString(httpPort),
                "--plain", "--max-clients", Integer.toString(maxClients), "--web-pages", Integer.toString(webPages)));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        Pattern ready = Pattern.compile("RIPVServer ready: clients on port (\\d+).*register at [^:]+:(\\d+) with --secret-file (\\S+?),");
        List<String> seen = new ArrayList<>();
        for (String line = r.readLine(); line != null; line = r.readLine()) {
            seen.add(line);
            Matcher m = ready.matcher(line);
            if (m.find()) {
                Thread drain = new Thread(() -> {
                    try {
                        r.transferTo(Writer.nullWriter());
                    } catch (IOException ignored) {
                        // the server ended
                    }
                }, "bench-server-output");
                drain.setDaemon(true);
                drain.start();
                return new Server(p, Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)), Path.of(m.group(3)), httpPort);
            }
        }
        p.destroyForcibly();
        throw new IOException("the server ended before it was ready:\n" + String.join("\n", seen));
    }

    /**
     * The server's JVM options after -Xmx: those {@code ./ripv server} gives it, then {@code extra}; an
     * extra collector replaces the product's (java refuses two).
     */
    static List<String> jvmOptions(List<String> extra) {
        boolean collector = extra.stream().anyMatch(WebBench::picksCollector);
        List<String> all = new ArrayList<>(ServerMain.JVM_OPTIONS.stream()
                .filter(o -> !collector || !picksCollector(o)).toList());
        all.addAll(extra);
        return all;
    }

    private static boolean picksCollector(String jvmOption) {
        return jvmOption.matches("-XX:\\+Use\\w+GC");
    }

    /** A process's CPU time (user + system, all threads) from /proc/PID/stat. */
    static long processCpuNanos(long pid) throws IOException {
        String stat = Files.readString(Path.of("/proc", Long.toString(pid), "stat"), StandardCharsets.US_ASCII);
        String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        long ticks = Long.parseLong(f[11]) + Long.parseLong(f[12]); // utime, stime (fields 14 and 15)
        return ticks * 10_000_000L; // USER_HZ is 100 on Linux
    }

    /** Threads and VmRSS (KiB) of a process from /proc, and its live heap (KiB) after a full GC from jcmd. */
    static long[] sample(long pid) throws Exception {
        ConnectionCostBench.jcmd(pid, "GC.run");
        Thread.sleep(500);
        return ConnectionCostBench.sample(pid);
    }
}
