package org.ripv.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.server.permit.PermitFile;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * What an idle logged-in client costs the server (docs/performance.md): a real server in a JVM of
 * its own, its threads and resident memory (after a full GC) before and after N clients log in
 * over TLS and then do nothing.
 */
@Command(name = "connections", mixinStandardHelpOptions = true, description = "Threads and memory per idle logged-in client.")
public final class ConnectionCostBench implements Callable<Integer> {
    @Option(names = "--clients", defaultValue = "500", description = "Idle clients to log in (default ${DEFAULT-VALUE}).")
    int clients;
    @Option(names = "--plain", description = "Plain TCP instead of TLS.")
    boolean plain;

    private final PrintStream out;

    public ConnectionCostBench() {
        this(System.out);
    }

    ConnectionCostBench(PrintStream out) {
        this.out = out;
    }

    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("ripv-bench-connections");
        PermitFile.setUser(dir.resolve("permit.txt"), "bench", "bench-password".toCharArray(), List.of("operators"), 1000);
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-cp", System.getProperty("java.class.path"), "org.ripv.server.ServerMain",
                "server", "--data", dir.toString(), "--port", "0", "--registry-port", "0", "--http-port", "0"));
        if (plain) {
            cmd.add("--plain");
        }
        Process server = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        List<ClientSocketHandler> open = new ArrayList<>();
        try {
            int port = readyPort(server);
            long pid = server.pid();
            gc(pid);
            long[] before = sample(pid);
            for (int i = 0; i < clients; i++) {
                ClientSocketHandler c = plain ? ClientSocketHandler.connectPlain("localhost", port)
                        : ClientSocketHandler.connect("localhost", port);
                c.login("bench", "bench-password".toCharArray());
                open.add(c);
            }
            Thread.sleep(8_000); // longer than a writer's idle time: the clients are idle now
            gc(pid);
            long[] after = sample(pid);
            double threads = (after[0] - before[0]) / (double) clients;
            double kib = (after[1] - before[1]) / (double) clients;
            out.printf("%d idle logged-in clients over %s: server threads %d -> %d (%.2f per client),"
                    + " resident memory %d -> %d KiB (%.1f KiB per client), live heap %d -> %d KiB (%.1f KiB per client)%n",
                    clients, plain ? "plain TCP" : "TLS", before[0], after[0], threads, before[1], after[1], kib,
                    before[2], after[2], (after[2] - before[2]) / (double) clients);
            out.printf("10,000 such clients: about %.0f threads and %.0f MiB%n", threads * 10_000, kib * 10_000 / 1024);
            return 0;
        } finally {
            open.forEach(ClientSocketHandler::close);
            server.destroy();
            server.waitFor(20, TimeUnit.SECONDS);
        }
    }

    private static int readyPort(Process p) throws IOException {
        BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        Pattern ready = Pattern.compile("RIPVServer ready: clients on port (\\d+)");
        for (String line = r.readLine(); line != null; line = r.readLine()) {
            Matcher m = ready.matcher(line);
            if (m.find()) {
                Thread t = new Thread(() -> {
                    try {
                        r.transferTo(java.io.Writer.nullWriter());
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

    private static String jcmd(long pid, String what) throws Exception {
        String jcmd = Path.of(System.getProperty("java.home"), "bin", "jcmd").toString();
        Process p = new ProcessBuilder(jcmd, Long.toString(pid), what).redirectErrorStream(true).start();
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        p.waitFor(60, TimeUnit.SECONDS);
        return text;
    }

    /** Threads and VmRSS (KiB) of a process, from /proc, and its live heap (KiB) from jcmd. */
    private static long[] sample(long pid) throws Exception {
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
