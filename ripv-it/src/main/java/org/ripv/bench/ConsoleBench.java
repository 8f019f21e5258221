package org.ripv.bench;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.RIPVServer;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.PermitFile;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The live-console benchmark (docs/performance.md): one vehicle MailBox printing at a steady
 * rate through a real service, RMI, the server and client sockets, measured at the watchers as
 * the delay from the vehicle's write to the watcher's read. In one run: one watcher (the
 * baseline), then many, then many plus one that never reads (whose backlog the server must
 * bound without the others noticing).
 */
@Command(name = "console", mixinStandardHelpOptions = true,
        description = "Measures the live console's delay with 1 and N watchers, and with one that never reads.")
public final class ConsoleBench implements Callable<Integer> {
    @Option(names = "--watchers", defaultValue = "1000", description = "Watchers in the crowd (default ${DEFAULT-VALUE}).")
    int watchers;
    @Option(names = "--rate", defaultValue = "50", description = "Lines per second the vehicle prints (default ${DEFAULT-VALUE}).")
    int rate;
    @Option(names = "--seconds", defaultValue = "20", description = "Measuring time per phase (default ${DEFAULT-VALUE}).")
    int seconds;
    @Option(names = "--baseline-seconds", defaultValue = "60", description = "Measuring time of the one-watcher"
            + " phase (default ${DEFAULT-VALUE}): its p99 rests on rate × seconds samples, the crowd's on"
            + " a thousand times more, so the yardstick needs the longer run to hold still.")
    int baselineSeconds;
    @Option(names = "--warmup", defaultValue = "3", description = "Warm-up seconds per phase (default ${DEFAULT-VALUE}).")
    int warmup;
    @Option(names = "--full-clients", defaultValue = "10", description = "How many of the watchers are full clients that"
            + " deserialize every push (default ${DEFAULT-VALUE}); the others read raw frames (see RawWatchers).")
    int fullClients;

    @Option(names = "--raw-threads", description = "Selector threads reading the raw watchers (default: one per core,"
            + " as real watchers read side by side on their own machines).")
    int rawThreads = Runtime.getRuntime().availableProcessors();

    @picocli.CommandLine.Spec
    picocli.CommandLine.Model.CommandSpec spec;

    private final PrintStream out;

    public ConsoleBench() {
        this(System.out);
    }

    ConsoleBench(PrintStream out) {
        this.out = out;
    }

    /** One watching client and the delays it saw, in microseconds. */
    static final class Watch implements ClientSocketHandler.Listener {
        final AutoCloseable client;
        final long[] delays;
        final AtomicInteger n = new AtomicInteger();
        volatile boolean recording;
        volatile long skipped;
        /** When the latest line it recorded was sent (System.nanoTime), as its arrival less its delay: no earlier than that. */
        volatile long lastSent = Long.MIN_VALUE;
        final CountDownLatch stall;

        Watch(AutoCloseable client, int capacity, CountDownLatch stall) {
            this.client = client;
            this.delays = new long[capacity];
            this.stall = stall;
        }

        void record(long nanos) {
            if (recording) {
                int i = n.getAndIncrement();
                if (i < delays.length) {
                    delays[i] = nanos / 1000;
                }
                lastSent = Math.max(lastSent, System.nanoTime() - nanos); // one reader thread per watcher
            }
        }

        @Override
        public void onReply(OutgoingServerMessage r) {
            if (!r.footer().serviceId().equals(Ids.FID_CONSOLE) || !(r.footer().result() instanceof ConsoleBatch b)) {
                return;
            }
            if (stall != null) {
                try {
                    stall.await(); // this client's reader stops: it reads nothing more from its socket
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                return;
            }
            long now = System.nanoTime();
            skipped += b.skipped();
            if (!recording) {
                return;
            }
            for (ConsoleEntry e : b.entries()) {
                String t = e.text();
                int sp = t.lastIndexOf(' ');
                if (t.startsWith("bench ") && sp > 0) {
                    record(now - Long.parseLong(t.substring(sp + 1)));
                }
            }
        }
    }

    /**
     * @param fewest the fewest lines one watcher saw (each should see every line: a raw watcher
     *               has no skip marker to count, so a short one shows here)
     * @param shortOnes how many watchers saw fewer lines than the one that saw most, less one
     */
    /** The delays, and the whole process's CPU per line delivered to one watcher while they were recorded ({@link CpuClock}). */
    record Figures(double p50Ms, double p99Ms, double maxMs, long samples, long skipped, int fewest, int shortOnes, double cpuMicros) {
        Figures withCpu(double micros) {
            return new Figures(p50Ms, p99Ms, maxMs, samples, skipped, fewest, shortOnes, micros);
        }
    }

    /** Refuses counts and times the benchmark cannot run with, naming the option. */
    private void check() {
        String bad = watchers < 1 ? "--watchers must be at least 1, got " + watchers
                : rate < 1 || rate > 10_000 ? "--rate must be 1 to 10000 lines a second, got " + rate
                : seconds < 1 || seconds > 3600 ? "--seconds must be 1 to 3600, got " + seconds
                : baselineSeconds < 1 || baselineSeconds > 3600 ? "--baseline-seconds must be 1 to 3600, got " + baselineSeconds
                : warmup < 0 || warmup > 600 ? "--warmup must be 0 to 600, got " + warmup
                : fullClients < 0 ? "--full-clients must not be negative, got " + fullClients
                : rawThreads < 1 || rawThreads > 64 ? "--raw-threads must be 1 to 64, got " + rawThreads : null;
        if (bad != null) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), bad);
        }
    }

    @Override
    public Integer call() throws Exception {
        check();
        Path dir = Files.createTempDirectory("ripv-bench-console");
        out.printf("RIPV console benchmark — %d cores, Java %s (%s), %d lines/s, %d s per phase after %d s warm-up"
                        + " (the one-watcher phase %d s);"
                        + " load average %.1f%n", Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"),
                String.join("+", ManagementFactory.getGarbageCollectorMXBeans().stream().map(b -> b.getName()).toList()),
                rate, seconds, warmup, baselineSeconds, ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        // Plain TCP: the raw watchers read frames off the socket (TLS would add each client's own
        // encryption, the same with any writer design; docs/performance.md).
        RIPVServer server = new RIPVServer(ServerConfig.forTests(dir.resolve("server")).plain().withMaxClients(watchers + 100)
                .withServiceCheck(Duration.ofSeconds(5)));
        server.start();
        PermitFile.setUser(dir.resolve("server/permit.txt"), "bench", "bench-password".toCharArray(), List.of("observers"), 1000);
        server.reloadPermits();
        VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
        String secret = Files.readString(server.secretFile(), StandardCharsets.UTF_8).trim();
        ServiceConnector connector = ServiceConnector.connect(vehicle,
                new ServiceOptions("localhost", server.registryPort(), secret, 0, Duration.ofSeconds(5)));
        connector.awaitRegistered(Duration.ofSeconds(30));
        String box = vehicle.mailbox();
        int capacity = rate * (seconds + 2);
        try {
            out.printf("(%d of the watchers are full clients; the rest read raw frames on %d selector threads: RawWatchers)%n",
                    Math.min(fullClients, watchers), rawThreads);
            List<Watch> one = connect(server, box, 1, rate * (baselineSeconds + 2), null);
            Figures base = run(vehicle, one, baselineSeconds);
            report("1 watcher", base, base);
            close(one);

            List<Watch> crowd = connect(server, box, Math.min(fullClients, watchers), capacity, null);
            RawWatchers raws = new RawWatchers(rawThreads);
            for (int i = crowd.size(); i < watchers; i++) {
                Watch w = new Watch(() -> { }, capacity, null);
                raws.add("localhost", server.port(), "bench", "bench-password".toCharArray(), box, w::record);
                crowd.add(w);
            }
            Figures many = run(vehicle, crowd, seconds);
            report(watchers + " watchers", many, base);
            int full = Math.min(fullClients, watchers);
            if (full > 0 && full < crowd.size()) {
                Figures f = figures(crowd.subList(0, full));
                Figures r = figures(crowd.subList(full, crowd.size()));
                out.printf("  of which %d full clients p50 %.2f ms p99 %.2f ms; %d raw p50 %.2f ms p99 %.2f ms%n",
                        full, f.p50Ms(), f.p99Ms(), crowd.size() - full, r.p50Ms(), r.p99Ms());
            }

            long heapBefore = usedHeapAfterGc();
            CountDownLatch stall = new CountDownLatch(1);
            List<Watch> stalled = connect(server, box, 1, 0, stall);
            crowd.forEach(w -> w.n.set(0));
            Figures withStall = run(vehicle, crowd, seconds);
            long backlog = server.console().backlogTotal();
            long heapAfter = usedHeapAfterGc();
            report(watchers + " + 1 never reading", withStall, base);
            out.printf("  the one that never reads: the server holds %d entries for it (bound %d); heap after GC %d MB before,"
                            + " %d MB after %d s of it (whole JVM: server, service and all clients)%n",
                    backlog, 2_000, heapBefore >> 20, heapAfter >> 20, seconds + warmup);
            out.printf("  p99 with it / p99 without it: %.2f× (target: unchanged)%n", withStall.p99Ms() / many.p99Ms());
            close(crowd);
            raws.close();
            floor(many, raws.lastFrameBytes());
            // Then a flood the never-reading one cannot absorb in socket buffers: its backlog must stay bounded.
            String pad = "x".repeat(200);
            for (int i = 0; i < 50_000; i++) {
                vehicle.line("flood " + i + " " + pad);
                if (i % 2_000 == 1_999) {
                    Thread.sleep(100); // within the service's own publishing queue
                }
            }
            Thread.sleep(2000);
            out.printf("  after a flood of 50,000 lines of 200 bytes: the server holds %d entries for it; heap after GC %d MB%n",
                    server.console().backlogTotal(), usedHeapAfterGc() >> 20);
            stall.countDown();
            close(stalled);
            out.println(CpuClock.machineLine());
        } finally {
            connector.close();
            vehicle.stop();
            server.stop();
        }
        return 0;
    }

    private List<Watch> connect(RIPVServer server, String box, int count, int capacity, CountDownLatch stall) throws Exception {
        List<Watch> list = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            ClientSocketHandler c = ClientSocketHandler.connectPlain("localhost", server.port());
            c.login("bench", "bench-password".toCharArray());
            Watch w = new Watch(c, capacity, stall);
            c.addListener(w);
            if (c.call("", "?watch " + box, Priority.NORMAL, Duration.ofSeconds(30), null).status() != Status.OK) {
                throw new IllegalStateException("?watch failed");
            }
            list.add(w);
        }
        return list;
    }

    private static void close(List<Watch> ws) {
        for (Watch w : ws) {
            try {
                w.client.close();
            } catch (Exception ignored) {
                // closing anyway
            }
        }
    }

    /** Prints at the rate for warm-up plus measuring time; returns the delays seen during measuring. */
    private Figures run(VehicleConsoleService vehicle, List<Watch> ws, int seconds) throws InterruptedException {
        return run(vehicle::line, ws, seconds);
    }

    /** Sends "bench I NANOS" lines at the rate for warm-up plus measuring time; returns the delays seen during measuring. */
    private Figures run(Consumer<String> vehicle, List<Watch> ws, int seconds) throws InterruptedException {
        long period = 1_000_000_000L / rate;
        long start = System.nanoTime();
        long total = (long) (warmup + seconds) * rate;
        CpuClock cpu = CpuClock.start();
        long lastSent = start;
        for (long i = 0; i < total; i++) {
            if (i == (long) warmup * rate) {
                ws.forEach(w -> w.recording = true);
                cpu = CpuClock.start();
            }
            long due = start + i * period;
            long wait = due - System.nanoTime();
            if (wait > 0) {
                Thread.sleep(wait / 1_000_000, (int) (wait % 1_000_000));
            }
            lastSent = System.nanoTime();
            vehicle.accept("bench " + i + " " + lastSent);
        }
        awaitLastLine(ws, lastSent, System.nanoTime() + 1_000_000_000L);
        ws.forEach(w -> w.recording = false);
        Figures f = figures(ws);
        return f.withCpu(cpu.cpuMicrosPer(f.samples()));
    }

    /**
     * Until every watcher has recorded the last line, sent at {@code lastSent}, or until
     * {@code deadline} (a watcher that skipped lines never sees it): a flat second's wait for the
     * last lines cost every phase its full second (issue 38).
     */
    private static void awaitLastLine(List<Watch> ws, long lastSent, long deadline) throws InterruptedException {
        while (System.nanoTime() < deadline && ws.stream().anyMatch(w -> w.lastSent < lastSent)) {
            Thread.sleep(10);
        }
    }

    /**
     * The same fan-out with no RIPV in it ({@link FanOutFloor}): what this machine's kernel costs
     * for it, against which the crowd's p99 is set.
     */
    private void floor(Figures crowd, int lastFrame) throws Exception {
        int frame = lastFrame > 0 ? lastFrame : 480;
        int writers = Math.max(2, Runtime.getRuntime().availableProcessors()); // as the server's WriterPool
        List<Watch> ws = new ArrayList<>();
        for (int i = 0; i < watchers; i++) {
            ws.add(new Watch(() -> { }, rate * (seconds + 2), null));
        }
        try (FanOutFloor f = new FanOutFloor(ws, writers, rawThreads, frame)) {
            Figures bare = run(f::line, ws, seconds);
            out.printf("%-26s p50 %7.2f ms   p99 %7.2f ms   max %8.2f ms   %8d samples   cpu %.1f us/line   (%d-byte frames,"
                            + " %d writer threads, no RIPV: the machine's own cost)%n", "bare fan-out to " + watchers, bare.p50Ms(),
                    bare.p99Ms(), bare.maxMs(), bare.samples(), bare.cpuMicros(), frame, writers);
            out.printf("  %d watchers p99 / bare fan-out p99: %.2f× (what RIPV adds on top of the kernel's fan-out)%n",
                    watchers, crowd.p99Ms() / bare.p99Ms());
            out.println(CpuClock.ratioLine("line to each of " + watchers + " watchers", crowd.cpuMicros(), bare.cpuMicros(),
                    crowd.p99Ms() / bare.p99Ms()));
        }
    }

    /** The delays the watchers recorded, together. */
    static Figures figures(List<Watch> ws) {
        long count = 0;
        for (Watch w : ws) {
            count += Math.min(w.n.get(), w.delays.length);
        }
        long[] all = new long[(int) count];
        int k = 0;
        long skipped = 0;
        for (Watch w : ws) {
            int m = Math.min(w.n.get(), w.delays.length);
            System.arraycopy(w.delays, 0, all, k, m);
            k += m;
            skipped += w.skipped;
        }
        Arrays.sort(all);
        int most = ws.stream().mapToInt(w -> Math.min(w.n.get(), w.delays.length)).max().orElse(0);
        int fewest = ws.stream().mapToInt(w -> Math.min(w.n.get(), w.delays.length)).min().orElse(0);
        int shortOnes = (int) ws.stream().filter(w -> Math.min(w.n.get(), w.delays.length) < most - 1).count(); // the line at the warm-up's end counts for some, not others
        if (all.length == 0) {
            return new Figures(Double.NaN, Double.NaN, Double.NaN, 0, skipped, 0, 0, Double.NaN);
        }
        return new Figures(all[all.length / 2] / 1000.0, all[(int) Math.min(all.length - 1, all.length * 0.99)] / 1000.0,
                all[all.length - 1] / 1000.0, all.length, skipped, fewest, shortOnes, Double.NaN);
    }

    private void report(String what, Figures f, Figures base) {
        out.printf("%-26s p50 %7.2f ms   p99 %7.2f ms   max %8.2f ms   %8d samples   %d skipped   cpu %.1f us/line   p99 %.2f× one watcher%s%n",
                what, f.p50Ms(), f.p99Ms(), f.maxMs(), f.samples(), f.skipped(), f.cpuMicros(), f.p99Ms() / base.p99Ms(),
                f == base ? "" : "   (targets: p99 ≤ 100 ms and ≤ 3×)");
        if (f.shortOnes() > 0) {
            out.printf("  %d watcher(s) saw fewer lines than the others (the fewest: %d)%n", f.shortOnes(), f.fewest());
        }
    }

    private static long usedHeapAfterGc() {
        System.gc();
        return ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
    }
}
