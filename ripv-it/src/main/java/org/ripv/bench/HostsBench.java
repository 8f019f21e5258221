package org.ripv.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.ripv.it.Netns;
import org.ripv.it.Postgres;

/**
 * {@code ./ripv bench hosts}: RIPV across hosts, as root, in network namespaces on one bridge —
 * PostgreSQL, two servers sharing it (one active, one standing by), a service host and an
 * operator. It measures, each against what bounds it in the same run:
 * <ul>
 * <li>the request round trip operator → server → service → back, against the bare TCP round
 *     trips between the same namespaces ({@code ?ping} against operator → server alone);</li>
 * <li>the time from cutting the service host off to {@code ?services} saying so, against the
 *     server's check interval;</li>
 * <li>the time from killing the active server (SIGKILL) to the standby answering a client,
 *     against the 15 s the issue allows, several times, the killed server coming back each time
 *     as the standby.</li>
 * </ul>
 * Prints a table; docs/performance.md "Across hosts" records the figures.
 */
final class HostsBench {
    private static final String S1 = "10.231.1.1";
    private static final String SVC = "10.231.1.2";
    private static final String OP = "10.231.1.4";
    private static final String DB = "10.231.1.9";
    private static final String S2 = "10.231.1.11";
    private static final String PW = "correct horse";
    private static final String USAGE = "Usage: ripv bench hosts [--requests N] [--takeovers N]   (as root: network namespaces)";

    private HostsBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int requests = 300;
        int takeovers = 3;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--requests" -> requests = Integer.parseInt(args[++i]);
                case "--takeovers" -> takeovers = Integer.parseInt(args[++i]);
                default -> {
                    System.err.println("Error: unknown option " + args[i] + "\n" + USAGE);
                    return 2;
                }
            }
        }
        String why = Netns.unusable();
        if (why == null) {
            why = Postgres.unusable();
        }
        if (why == null && !Netns.onPath("ss")) {
            why = "needs ss (iproute2)";
        }
        if (why != null) {
            System.err.println("Error: ripv bench hosts " + why);
            return 1;
        }
        Path dir = Files.createTempDirectory("ripv-bench-hosts");
        try {
            run(dir, requests, takeovers);
        } finally {
            Netns.sh("rm", "-rf", dir.toString());
        }
        return 0;
    }

    private static void run(Path dir, int requests, int takeovers) throws Exception {
        Path logs = Files.createDirectories(dir.resolve("logs"));
        try (Netns net = Netns.create(); Postgres pg = Postgres.start(net, "db", DB + "/24", "10.231.1.0/24")) {
            net.host("s1", S1 + "/24");
            net.host("s2", S2 + "/24");
            net.host("svc", SVC + "/24");
            net.host("op", OP + "/24");
            String[] addr = {S1, S2};
            Path[] data = {dir.resolve("s1"), dir.resolve("s2")};
            Process[] servers = new Process[2];
            servers[0] = server(net, 0, addr, data, logs, pg.url(), "0");
            await(logs.resolve("s1-0.log"), "RIPVServer ready", 60);
            org.ripv.server.permit.PermitFile.setUser(data[0].resolve("permit.txt"), "otto", PW.toCharArray(),
                    List.of("operators"), 1000);
            Files.createDirectories(data[1]);
            Files.copy(data[0].resolve("service.secret"), data[1].resolve("service.secret"));
            Files.copy(data[0].resolve("permit.txt"), data[1].resolve("permit.txt"));
            // the same TLS identity: a client that pinned the first refuses a standby with another certificate
            Files.createDirectories(data[1].resolve("tls"));
            for (String f : new String[] {"server.p12", "server.pass"}) {
                Files.copy(data[0].resolve("tls").resolve(f), data[1].resolve("tls").resolve(f));
            }
            servers[1] = server(net, 1, addr, data, logs, pg.url(), "0");
            await(logs.resolve("s2-0.log"), "standing by", 60);
            String clients = S1 + ":4444," + S2 + ":4444";
            net.java("svc", logs.resolve("clock.log"), "org.ripv.examples.ClockService", "--server", S1 + ":1099," + S2 + ":1099",
                    "--secret-file", data[0].resolve("service.secret").toString(), "--host", SVC);
            String clock = "<ClockService>::<" + SVC + ">" + org.ripv.naming.Handles.platformDefault();
            awaitServices(net, logs, clients, 60);

            // Round trips, each against bare TCP between the same namespaces.
            net.java("s1", logs.resolve("echo-s1.log"), "org.ripv.it.NetProbe", "echo-server", "7777");
            net.java("svc", logs.resolve("echo-svc.log"), "org.ripv.it.NetProbe", "echo-server", "7777");
            await(logs.resolve("echo-s1.log"), "READY", 30);
            await(logs.resolve("echo-svc.log"), "READY", 30);
            long[] opSrv = numbers(probe(net, logs, "op", 120, "tcp-rtt", S1, "7777", Integer.toString(requests)), "RTT tcp");
            long[] srvSvc = numbers(probe(net, logs, "s1", 120, "tcp-rtt", SVC, "7777", Integer.toString(requests)), "RTT tcp");
            String rtt = probe(net, logs, "op", 300, "rtt", S1 + ":4444", "otto", PW, Integer.toString(requests), clock, "echo x");
            long[] ping = numbers(rtt, "RTT ping");
            long[] req = numbers(rtt, "RTT request");

            // Cut the service host off; time until ?services says so.
            Path watch = logs.resolve("watch.log");
            Process w = net.java("op", watch, "org.ripv.it.NetProbe", "watch", S1 + ":4444", "otto", PW, "<ClockService>::<" + SVC + ">", "60");
            await(watch, "READY", 60);
            long cut = System.currentTimeMillis();
            net.cut("svc");
            w.waitFor(70, TimeUnit.SECONDS);
            String seen = read(watch);
            double noticed = seen.contains("SEEN ") ? (Long.parseLong(seen.substring(seen.indexOf("SEEN ") + 5).split(" ")[0]) - cut) / 1000.0
                    : Double.NaN;
            net.mend("svc");
            awaitServices(net, logs, clients, 60);

            // Kill the active server, again and again; the killed one comes back as the standby.
            Path probeLog = logs.resolve("takeover.log");
            net.java("op", probeLog, "org.ripv.it.NetProbe", "takeover", clients, "otto", PW, Integer.toString(60 + 40 * takeovers));
            await(probeLog, "ANSWER", 60);
            List<Double> takeoverSeconds = new ArrayList<>();
            List<Double> servicesBack = new ArrayList<>();
            int active = 0;
            for (int k = 0; k < takeovers; k++) {
                int standby = 1 - active;
                int seenBefore = answers(read(probeLog));
                long killed = System.currentTimeMillis();
                servers[active].destroyForcibly();
                servers[active].waitFor(20, TimeUnit.SECONDS);
                long answered = answerAfter(probeLog, seenBefore, addr[standby] + ":4444", 40);
                takeoverSeconds.add((answered - killed) / 1000.0);
                servicesBack.add((awaitServices(net, logs, clients, 40) - killed) / 1000.0);
                servers[active] = server(net, active, addr, data, logs, pg.url(), Integer.toString(k + 1));
                await(logs.resolve("s" + (active + 1) + "-" + (k + 1) + ".log"), "standing by", 60);
                active = standby;
            }

            System.out.printf("RIPV across hosts (network namespaces on one bridge; PostgreSQL, 2 servers, a service host, an operator;"
                    + " %d cores, load average %.1f)%n", Runtime.getRuntime().availableProcessors(),
                    ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
            System.out.printf("%-62s %10s %10s %s%n", "", "median", "p90", "against");
            System.out.printf("%-62s %8d us %8d us%n", "bare TCP round trip, operator -> server", opSrv[0], opSrv[1]);
            System.out.printf("%-62s %8d us %8d us%n", "bare TCP round trip, server -> service host", srvSvc[0], srvSvc[1]);
            System.out.printf("%-62s %8d us %8d us %.1fx the bare round trip%n", "?ping, operator -> server", ping[0], ping[1],
                    (double) ping[0] / opSrv[0]);
            System.out.printf("%-62s %8d us %8d us %.1fx the two bare round trips%n", "request, operator -> server -> service -> back",
                    req[0], req[1], (double) req[0] / (opSrv[0] + srvSvc[0]));
            System.out.printf("%-62s %8.1f s  %10s check interval 3 s: %.1f intervals%n", "service host cut off -> ?services says so",
                    noticed, "", noticed / 3);
            for (int k = 0; k < takeoverSeconds.size(); k++) {
                System.out.printf("%-62s %8.1f s  %10s %.0f%% of the 15 s allowed; services back after %.1f s%n",
                        "kill -9 of the active server -> standby answers (" + (k + 1) + ")", takeoverSeconds.get(k), "",
                        takeoverSeconds.get(k) / 15 * 100, servicesBack.get(k));
            }
        }
    }

    private static Process server(Netns net, int i, String[] addr, Path[] data, Path logs, String url, String run) throws IOException {
        return net.java("s" + (i + 1), logs.resolve("s" + (i + 1) + "-" + run + ".log"), "org.ripv.server.ServerMain", "server",
                "--data", data[i].toString(), "--port", "4444", "--registry-port", "1099", "--http-port", "0",
                "--rmi-hostname", addr[i], "--state-db", url, "--state-db-user", "postgres");
    }

    private static String probe(Netns net, Path logs, String host, int seconds, String... args) throws Exception {
        Path log = logs.resolve("probe-" + System.nanoTime() + ".log");
        Process p = net.java(host, log, "org.ripv.it.NetProbe", args);
        if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
            throw new IllegalStateException("probe " + Arrays.toString(args) + " did not finish: " + read(log));
        }
        return read(log);
    }

    /** Waits until ?services lists the clock answering; returns when (epoch ms). */
    private static long awaitServices(Netns net, Path logs, String clients, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        String last = "";
        while (System.nanoTime() < end) {
            last = probe(net, logs, "op", 60, "requests", clients, "otto", PW, "|?services");
            if (last.contains("1 service(s)") && !last.contains("NOT ANSWERING")) {
                return System.currentTimeMillis();
            }
            Thread.sleep(200);
        }
        throw new IllegalStateException("the service did not come back within " + seconds + " s: " + last);
    }

    private static int answers(String log) {
        return (int) log.lines().filter(l -> l.startsWith("ANSWER ")).count();
    }

    /** The time of the first ANSWER line after the first {@code skip} that names {@code server}. */
    private static long answerAfter(Path log, int skip, String server, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (System.nanoTime() < end) {
            List<String> lines = read(log).lines().filter(l -> l.startsWith("ANSWER ")).toList();
            for (int i = skip; i < lines.size(); i++) {
                String[] w = lines.get(i).split(" ");
                if (w.length == 3 && w[2].equals(server)) {
                    return Long.parseLong(w[1]);
                }
            }
            Thread.sleep(100);
        }
        throw new IllegalStateException(server + " never answered: " + read(log));
    }

    private static long[] numbers(String out, String prefix) {
        for (String line : out.split("\n")) {
            if (line.startsWith(prefix + " ")) {
                String[] w = line.substring(prefix.length()).trim().split(" ");
                return new long[] {Long.parseLong(w[0]), Long.parseLong(w[1])};
            }
        }
        throw new IllegalStateException("no '" + prefix + "' in: " + out);
    }

    private static void await(Path log, String text, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!read(log).contains(text)) {
            if (System.nanoTime() > end) {
                throw new IllegalStateException(log.getFileName() + " never said '" + text + "': " + read(log));
            }
            Thread.sleep(100);
        }
    }

    private static String read(Path log) throws IOException {
        return Files.exists(log) ? Files.readString(log, StandardCharsets.UTF_8) : "";
    }
}
