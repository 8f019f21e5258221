package org.ripv.bench;

import com.sun.management.UnixOperatingSystemMXBean;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.io.Writer;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.net.SocketFactory;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.Tls;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.permit.PermitFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * What idle logged-in clients cost the server, and whether it still answers meanwhile
 * (docs/performance.md, issue 26): a real server in a JVM of its own with a 1 GiB heap, its threads,
 * resident memory and live heap (after a full GC) before and after N clients log in over TLS and
 * then do nothing, and a logged-in user's {@code ?services} round trip with them all connected.
 */
@Command(name = "connections", mixinStandardHelpOptions = true,
        description = "Threads and memory of N idle logged-in clients, and ?services meanwhile.")
public final class ConnectionCostBench implements Callable<Integer> {
    /** The heap the server gets: 10,000 idle clients must fit in it (issue 26). */
    static final String HEAP = "1g";
    /** Descriptors the server and this JVM need beyond one per client (jars, Derby, RMI, pipes). */
    static final int SPARE_DESCRIPTORS = 200;

    @Option(names = "--clients", defaultValue = "500", description = "Idle clients to log in (default ${DEFAULT-VALUE}).")
    int clients;
    @Option(names = "--plain", description = "Plain TCP instead of TLS.")
    boolean plain;
    @Option(names = "--openers", defaultValue = "8",
            description = "Threads opening the clients (fewer than the server's 16 pending connections per address; default ${DEFAULT-VALUE}).")
    int openers;
    @Option(names = "--probes", defaultValue = "50", description = "?services round trips timed with the clients connected (default ${DEFAULT-VALUE}).")
    int probes;
    @Option(names = "--idle-seconds", defaultValue = "12",
            description = "Wait after the clients are in, before measuring: longer than a writer's idle time and a log-in"
                    + " waiter's keep-alive, so that what is measured is idle clients (default ${DEFAULT-VALUE}).")
    double idleSeconds;

    private final PrintStream out;

    public ConnectionCostBench() {
        this(System.out);
    }

    ConnectionCostBench(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() throws Exception {
        checkDescriptors();
        Path dir = Files.createTempDirectory("ripv-bench-connections");
        PermitFile.setUser(dir.resolve("permit.txt"), "bench", "bench-password".toCharArray(), List.of("operators"), 1000);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-Xmx" + HEAP, "-cp", System.getProperty("java.class.path"),
                "org.ripv.server.ServerMain", "server", "--data", dir.toString(), "--port", "0", "--registry-port", "0",
                "--http-port", "0", "--max-clients", Integer.toString(clients + 10)));
        if (plain) {
            cmd.add("--plain");
        }
        Process server = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        try (IdleClients idle = new IdleClients()) {
            int port = readyPort(server);
            long pid = server.pid();
            ClientSocketHandler probe = plain ? ClientSocketHandler.connectPlain("localhost", port)
                    : ClientSocketHandler.connect("localhost", port);
            try {
                probe.login("bench", "bench-password".toCharArray());
                double[] quiet = roundTrips(probe, probes);
                gc(pid);
                long[] before = sample(pid);
                SocketFactory sockets = plain ? SocketFactory.getDefault()
                        : Tls.trustOnFirstUse("localhost", port, Path.of(System.getProperty(Tls.KNOWN_HOSTS_PROPERTY,
                                Tls.defaultKnownHosts().toString())), n -> { });
                long start = System.nanoTime();
                idle.open(clients, openers, sockets, "localhost", port, "bench", "bench-password".toCharArray());
                double openSeconds = (System.nanoTime() - start) / 1e9;
                // Longer than a writer's idle time and a log-in waiter's keep-alive: the clients are idle now.
                Thread.sleep((long) (idleSeconds * 1000));
                double[] busy = roundTrips(probe, probes);
                long[] loaded = sample(pid); // before the GC: the heap in use, garbage included
                gc(pid);
                long[] after = sample(pid);
                double threads = (after[0] - before[0]) / (double) clients;
                double kib = (after[1] - before[1]) / (double) clients;
                out.printf("%d idle logged-in clients over %s (opened in %.1f s, %.0f/s): server threads %d -> %d (%.3f per client),"
                        + " resident memory %d -> %d KiB (%.1f KiB per client), live heap %d -> %d KiB (%.1f KiB per client)"
                        + " (%d KiB in use before that GC) of -Xmx%s%n", clients, plain ? "plain TCP" : "TLS", openSeconds,
                        clients / openSeconds, before[0], after[0], threads, before[1], after[1], kib, before[2], after[2],
                        (after[2] - before[2]) / (double) clients, loaded[2], HEAP);
                out.printf("?services round trip (%d, wall): with no other client p50 %.2f ms, max %.2f ms; with %d idle clients"
                        + " p50 %.2f ms, p99 %.2f ms, max %.2f ms (target <= 100 ms)%n", probes, quiet[0], quiet[2], clients,
                        busy[0], busy[1], busy[2]);
                out.println(CpuClock.machineLine());
            } finally {
                probe.close();
            }
            return 0;
        } finally {
            server.destroy();
            if (!server.waitFor(30, TimeUnit.SECONDS)) {
                server.destroyForcibly();
            }
        }
    }

    /** Each client is a socket here and one at the server (both JVMs inherit this limit). */
    private void checkDescriptors() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof UnixOperatingSystemMXBean os) {
            long need = clients + SPARE_DESCRIPTORS;
            if (os.getMaxFileDescriptorCount() < need) {
                throw new IllegalArgumentException("--clients " + clients + " needs " + need + " open files per process, but"
                        + " 'ulimit -n' is " + os.getMaxFileDescriptorCount() + ": raise it (e.g. 'ulimit -n "
                        + Math.max(need, 20_000) + "', docs/operations.md) or ask for fewer clients");
            }
        }
    }

    /** p50, p99 and max (ms) of {@code n} {@code ?services} round trips. */
    private static double[] roundTrips(ClientSocketHandler c, int n) throws IOException {
        double[] ms = new double[n];
        for (int i = 0; i < n; i++) {
            long t = System.nanoTime();
            if (c.call("", "?services", Priority.NORMAL, Duration.ofSeconds(30), null).status() != Status.OK) {
                throw new IllegalStateException("?services failed");
            }
            ms[i] = (System.nanoTime() - t) / 1e6;
        }
        Arrays.sort(ms);
        return new double[] {ms[n / 2], ms[Math.min(n - 1, (int) Math.ceil(n * 0.99) - 1)], ms[n - 1]};
    }

    private static int readyPort(Process p) throws IOException {
        BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        Pattern ready = Pattern.compile("RIPVServer ready: clients on port (\\d+)");
        for (String line = r.readLine(); line != null; line = r.readLine()) {
            Matcher m = ready.matcher(line);
            if (m.find()) {
                Thread t = new Thread(() -> {
                    try {
                        r.transferTo(Writer.nullWriter());
                    } catch (IOException ignored) {
                        // the server ended
                    }
                }, "bench-server-output");
                t.setDaemon(true);
                t.start();
                return Integer.parseInt(m.group(1));
            }
        }
        throw new IOException("the server ended before it was ready");
    }

    private static void gc(long pid) throws Exception {
        jcmd(pid, "GC.run");
        Thread.sleep(500);
    }

    static String jcmd(long pid, String what) throws Exception {
        String jcmd = Path.of(System.getProperty("java.home"), "bin", "jcmd").toString();
        Process p = new ProcessBuilder(jcmd, Long.toString(pid), what).redirectErrorStream(true).start();
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        p.waitFor(60, TimeUnit.SECONDS);
        return text;
    }

    /** Threads and VmRSS (KiB) of a process, from /proc, and its live heap (KiB) from jcmd. */
    static long[] sample(long pid) throws Exception {
        Matcher heap = Pattern.compile("used (\\d+)K").matcher(jcmd(pid, "GC.heap_info"));
        long used = heap.find() ? Long.parseLong(heap.group(1)) : -1;
        long threads = 0;
        long rss = 0;
        for (String line : Files.readAllLines(Path.of("/proc", Long.toString(pid), "status"))) {
            if (line.startsWith("Threads:")) {
                threads = Long.parseLong(line.substring(8).trim());
            } else if (line.startsWith("VmRSS:")) {
                rss = Long.parseLong(line.substring(6).trim().split("\\s+")[0]);
            }
        }
        return new long[] {threads, rss, used};
    }
}
