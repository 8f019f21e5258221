package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.naming.Handles;
import org.ripv.server.permit.PermitFile;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * RIPV across hosts for real (issue 15): network namespaces for the server, a service host, a
 * vehicle and an operator on one bridge (10.231.1.0/24), and a service host behind a NAT router
 * (10.231.2.0/24). The real programs run inside them: the reference scenario through the CLI;
 * the service host cut off for 30 s while requests are in flight (each must end within its
 * deadline, {@code ?services} must say so within two check intervals, and all works again
 * afterwards with nothing restarted); a service behind NAT refused at once with the address and
 * what to set, and the same service working with {@code --outbound-only}; a server restart. It
 * writes the speeds it measured to {@code target/multihost-report.txt}.
 */
@ResourceLock(Shared.NETNS)
class MultiHostTest {
    private static final String SRV = "10.231.1.1";
    private static final String SVC = "10.231.1.2";
    private static final String VEH = "10.231.1.3";
    private static final String NAT = "10.231.2.2";
    private static final String PW = "correct horse";
    private static final int CHECK_SECONDS = 3;   // the server's default service check interval
    private static final int REQUEST_TIMEOUT = 20;
    private static final String SERIAL = "<SerialPortServer>::<" + SVC + ">";
    private static final String DB = "<DatabaseServer>::<" + SVC + ">TTY1";
    private static final String VIS = "<DataVisServer>::<" + SVC + ">TTY1";
    private static final String CLOCK = "<ClockService>::<" + SVC + ">" + Handles.platformDefault();
    private static final String NAT_CLOCK = "<ClockService>::<" + NAT + ">";

    @TempDir
    Path dir;
    private final StringBuilder report = new StringBuilder();

    @Test
    void fourHostsACutLinkANatRouterAndARestart() throws Exception {
        NetnsAssume.usable();
        long began = System.nanoTime();
        try (Netns net = Netns.create()) {
            net.host("srv", SRV + "/24");
            net.host("svc", SVC + "/24");
            net.host("veh", VEH + "/24");
            net.host("op", "10.231.1.4/24");
            net.natHost("rtr", "10.231.1.5/24", "nat", "10.231.2.1/24", NAT + "/24", "10.231.2.1");
            net.route("srv", "10.231.2.0/24", "10.231.1.5"); // the server can route there; the router's firewall drops it

            Path data = dir.resolve("server");
            Path logs = Files.createDirectories(dir.resolve("logs"));
            Process server = startServer(net, data, logs.resolve("server.log"));
            PermitFile.setUser(data.resolve("permit.txt"), "otto", PW.toCharArray(), List.of("operators"), 1000);
            PermitFile.setUser(data.resolve("permit.txt"), "olga", PW.toCharArray(), List.of("observers", "db-reader"), 1000);
            String secret = data.resolve("service.secret").toString();
            String registry = SRV + ":1099";

            Path glider = dir.resolve("glider");
            net.java("veh", logs.resolve("simulator.log"), "org.ripv.services.ServicesMain", "simulator", "--listen", "2323", "--bind", VEH,
                    "--dir", glider.toString(), "--submerge-seconds", "2");
            List<Process> services = new ArrayList<>();
            services.add(net.java("svc", logs.resolve("serial.log"), "org.ripv.services.ServicesMain", "serial", "--server", registry,
                    "--secret-file", secret, "--host", SVC, "--link", "tcp://" + VEH + ":2323", "--carrier", "ignore",
                    "--no-enumerate", "--idle-timeout", "1000", "--reconnect", "1", "--work", dir.resolve("work").toString()));
            services.add(net.java("svc", logs.resolve("database.log"), "org.ripv.services.ServicesMain", "database", "--server",
                    registry, "--secret-file", secret, "--host", SVC, "--data", dir.resolve("database").toString()));
            services.add(net.java("svc", logs.resolve("datavis.log"), "org.ripv.services.ServicesMain", "datavis", "--server",
                    registry, "--secret-file", secret, "--host", SVC, "--workdir", dir.resolve("vis").toString()));
            services.add(net.java("svc", logs.resolve("clock.log"), "org.ripv.examples.ClockService", "--server", registry,
                    "--secret-file", secret, "--host", SVC));
            awaitServices(net, 4, 90);
            String gliderBox = SERIAL + Handles.forLink("tcp://" + VEH + ":2323");

            // 1. The reference scenario through the CLI, operator host to server to service host to vehicle.
            Path binary = dir.resolve("GLIDER.BIN");
            Files.write(binary, new byte[20_000]);
            Path sample = Path.of("..", "docs", "samples", "glider-temperature.dat").toAbsolutePath().normalize();
            Cli otto = cli(net, logs, "otto", "put " + binary, "?ulfiles", "use " + gliderBox, "dir", "ymodem:get MISSION1.LOG",
                    "?dlfiles", "use " + DB,
                    "SELECT m.name, v.name FROM mission m JOIN vehicle v ON m.vehicle_id = v.vehicle_id WHERE m.endt IS NULL",
                    "put " + sample, "use " + VIS, "vis:glider-temperature.dat");
            assertThat(otto.exit).as(otto.out).isZero();
            assertThat(otto.out).contains("GLIDER.BIN").contains("MISSION1.LOG").contains("(3 rows)");
            assertThat(Files.readAllBytes(downloaded(data, "MISSION1.LOG"))).isEqualTo(Files.readAllBytes(glider.resolve("MISSION1.LOG")));
            assertThat(downloaded(data, "glider-temperature.jpg")).isNotEmptyFile();
            Cli olga = cli(net, logs, "olga", "use " + gliderBox, "GO");
            assertThat(olga.exit).isEqualTo(1);
            assertThat(olga.out).contains("FORBIDDEN");
            Cli go = cli(net, logs, "otto", "use " + gliderBox, "ymodem:put GLIDER.BIN", "GO");
            assertThat(go.exit).as(go.out).isZero();
            assertThat(go.out).contains("submerging");
            report.append(String.format("reference scenario across 4 namespaces: passed (%d s into the test)%n", seconds(began)));

            // 2. Speeds: request round trips against bare TCP between the same namespaces.
            speeds(net, logs);

            // 3. Cut the service host off for 30 s with requests in flight.
            cutLink(net, logs, services, gliderBox);

            // 4. A service behind NAT: refused at once with what to set; then outbound-only through the same NAT.
            nat(net, logs, registry, secret);

            // 5. Restart the server: every service, the outbound one too, comes back by itself.
            server.destroy();
            assertThat(server.waitFor(20, TimeUnit.SECONDS)).isTrue();
            long restart = System.nanoTime();
            startServer(net, data, logs.resolve("server2.log"));
            awaitServices(net, 5, 60);
            double back = (System.nanoTime() - restart) / 1e9;
            report.append(String.format("server restart: all 5 services registered again %.1f s after the new server started%n", back));
            Map<Integer, Reply> after = requests(net, logs, "after-restart", gliderBox + "|dir", NAT_CLOCK + Handles.platformDefault()
                    + "|echo natted");
            assertThat(after.get(0).status).as(after.get(0).text).isEqualTo("OK");
            assertThat(after.get(1).text).isEqualTo("natted");
            for (Process p : services) {
                assertThat(p.isAlive()).as("no service was restarted").isTrue();
            }
            report.append(String.format("whole multi-host test: %d s%n", seconds(began)));
        } catch (Throwable t) {
            keepLogs();
            throw t;
        } finally {
            Path out = Path.of("target", "multihost-report.txt");
            Files.createDirectories(out.getParent());
            Files.writeString(out, report.toString(), StandardCharsets.UTF_8);
            System.err.print("multi-host report:\n" + report);
        }
    }

    /** A downloaded file, at the top of the download directory or in its vehicle's folder. */
    private static Path downloaded(Path data, String name) throws IOException {
        Path top = data.resolve("download").resolve(name);
        if (Files.exists(top)) {
            return top;
        }
        try (var folders = Files.list(data.resolve("download"))) {
            return folders.map(f -> f.resolve(name)).filter(Files::isRegularFile).findFirst().orElse(top);
        }
    }

    /** On failure, the programs' logs go to target/multihost-logs (the temporary directory is removed). */
    private void keepLogs() {
        try {
            Path to = Files.createDirectories(Path.of("target", "multihost-logs"));
            try (var logs = Files.list(dir.resolve("logs"))) {
                for (Path l : logs.toList()) {
                    Files.copy(l, to.resolve(l.getFileName()), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                }
            }
        } catch (IOException e) {
            System.err.println("could not keep the logs: " + e);
        }
    }

    private static long seconds(long since) {
        return (System.nanoTime() - since) / 1_000_000_000;
    }

    private Process startServer(Netns net, Path data, Path log) throws Exception {
        Process p = net.java("srv", log, "org.ripv.server.ServerMain", "server", "--data", data.toString(), "--port", "4444",
                "--registry-port", "1099", "--http-port", "0", "--rmi-hostname", SRV, "--request-timeout",
                Integer.toString(REQUEST_TIMEOUT));
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!read(log).contains("RIPVServer ready")) {
            assertThat(p.isAlive()).as("server: " + read(log)).isTrue();
            assertThat(System.nanoTime()).as("server ready").isLessThan(end);
            Thread.sleep(100);
        }
        return p;
    }

    private static String read(Path log) throws IOException {
        return Files.exists(log) ? Files.readString(log, StandardCharsets.UTF_8) : "";
    }

    /** Waits until {@code ?services} lists n services, all answering. */
    private void awaitServices(Netns net, int n, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        String last = "";
        while (System.nanoTime() < end) {
            Map<Integer, Reply> r = requests(net, dir.resolve("logs"), "services", "|?services");
            Reply s = r.get(0);
            last = s == null ? "" : s.text;
            if (last.startsWith(n + " service(s)") && !last.contains("NOT ANSWERING")) {
                return;
            }
            Thread.sleep(500);
        }
        throw new AssertionError("expected " + n + " services answering within " + seconds + " s; last: " + last);
    }

    private record Cli(int exit, String out) {}

    private Cli cli(Netns net, Path logs, String user, String... lines) throws Exception {
        // Each run's server makes a new certificate: remember it in this run's file, not ~/.ripv/known_hosts.
        List<String> args = new ArrayList<>(List.of("cli", "--server", SRV + ":4444", "--user", user, "--password", PW,
                "--timeout", "120", "--known-hosts", logs.resolve("known_hosts").toString()));
        for (String l : lines) {
            args.add("--exec");
            args.add(l);
        }
        Path log = logs.resolve("cli-" + user + "-" + System.nanoTime() + ".log");
        Process p = net.java("op", log, "org.ripv.client.ClientMain", args.toArray(String[]::new));
        assertThat(p.waitFor(180, TimeUnit.SECONDS)).isTrue();
        return new Cli(p.exitValue(), read(log));
    }

    record Reply(long millis, String status, String code, String text) {}

    private static final Pattern REPLY = Pattern.compile("REPLY (\\d+) (\\d+) (\\S+) (\\S+) ?(.*)");

    /** Sends requests from the operator host at once and returns each one's time and answer. */
    private Map<Integer, Reply> requests(Netns net, Path logs, String tag, String... specs) throws Exception {
        Path log = logs.resolve("probe-" + tag + "-" + System.nanoTime() + ".log");
        List<String> args = new ArrayList<>(List.of("requests", SRV + ":4444", "otto", PW));
        args.addAll(List.of(specs));
        Process p = net.java("op", log, "org.ripv.it.NetProbe", args.toArray(String[]::new));
        assertThat(p.waitFor(200, TimeUnit.SECONDS)).isTrue();
        return parse(read(log));
    }

    private static Map<Integer, Reply> parse(String out) {
        Map<Integer, Reply> replies = new HashMap<>();
        for (String line : out.split("\n")) {
            Matcher m = REPLY.matcher(line.strip());
            if (m.matches()) {
                replies.put(Integer.parseInt(m.group(1)), new Reply(Long.parseLong(m.group(2)), m.group(3), m.group(4), m.group(5)));
            }
        }
        return replies;
    }

    private void speeds(Netns net, Path logs) throws Exception {
        net.java("srv", logs.resolve("echo-srv.log"), "org.ripv.it.NetProbe", "echo-server", "7777");
        net.java("svc", logs.resolve("echo-svc.log"), "org.ripv.it.NetProbe", "echo-server", "7777");
        waitFor(logs.resolve("echo-srv.log"), "READY", 30);
        waitFor(logs.resolve("echo-svc.log"), "READY", 30);
        long[] opSrv = rtt(net, logs, "op", "tcp-rtt", SRV, "7777", "500");
        long[] srvSvc = rtt(net, logs, "srv", "tcp-rtt", SVC, "7777", "500");
        Path log = logs.resolve("rtt.log");
        Process p = net.java("op", log, "org.ripv.it.NetProbe", "rtt", SRV + ":4444", "otto", PW, "300", CLOCK, "echo x");
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        String out = read(log);
        long[] ping = numbers(out, "RTT ping");
        long[] request = numbers(out, "RTT request");
        report.append(String.format("bare TCP round trip, operator -> server: median %d us (p90 %d)%n", opSrv[0], opSrv[1]));
        report.append(String.format("bare TCP round trip, server -> service host: median %d us (p90 %d)%n", srvSvc[0], srvSvc[1]));
        report.append(String.format("?ping round trip, operator -> server: median %d us (p90 %d), %.1fx bare TCP%n", ping[0], ping[1],
                (double) ping[0] / opSrv[0]));
        report.append(String.format("request round trip, operator -> server -> service host (echo): median %d us (p90 %d),"
                + " %.1fx the two bare TCP round trips%n", request[0], request[1], (double) request[0] / (opSrv[0] + srvSvc[0])));
    }

    private long[] rtt(Netns net, Path logs, String host, String... args) throws Exception {
        Path log = logs.resolve("tcp-" + host + ".log");
        Process p = net.java(host, log, "org.ripv.it.NetProbe", args);
        assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
        return numbers(read(log), "RTT tcp");
    }

    private static long[] numbers(String out, String prefix) {
        for (String line : out.split("\n")) {
            if (line.startsWith(prefix + " ")) {
                String[] w = line.substring(prefix.length()).trim().split(" ");
                return new long[] {Long.parseLong(w[0]), Long.parseLong(w[1])};
            }
        }
        throw new AssertionError("no '" + prefix + "' in: " + out);
    }

    private static void waitFor(Path log, String text, int seconds) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        while (!read(log).contains(text)) {
            assertThat(System.nanoTime()).as(log + " says " + text + ": " + read(log)).isLessThan(end);
            Thread.sleep(100);
        }
    }

    private void cutLink(Netns net, Path logs, List<Process> services, String gliderBox) throws Exception {
        Path watchLog = logs.resolve("watch.log");
        Process watch = net.java("op", watchLog, "org.ripv.it.NetProbe", "watch", SRV + ":4444", "otto", PW, SERIAL, "60");
        waitFor(watchLog, "READY", 30);
        // In flight at the cut: a command running on the service host.
        Path inflightLog = logs.resolve("probe-inflight.log");
        Process inflight = net.java("op", inflightLog, "org.ripv.it.NetProbe", "requests", SRV + ":4444", "otto", PW,
                CLOCK + "|sleep 8000");
        waitFor(inflightLog, "SENT", 30);
        Thread.sleep(500);
        long cut = System.currentTimeMillis();
        net.cut("svc");
        // Sent during the cut: to each service on the cut host, and the server's own commands.
        Map<Integer, Reply> during = requests(net, logs, "during", gliderBox + "|dir", DB + "|SELECT COUNT(*) FROM vehicle",
                "|?mailboxes", "|?status " + DB, "|?ping");
        assertThat(inflight.waitFor(60, TimeUnit.SECONDS)).isTrue();
        Reply sleeping = parse(read(inflightLog)).get(0);
        assertThat(watch.waitFor(60, TimeUnit.SECONDS)).isTrue();
        String seen = read(watchLog);
        assertThat(seen).contains("SEEN");
        long detected = Long.parseLong(seen.substring(seen.indexOf("SEEN ") + 5).split(" ")[0]) - cut;

        report.append(String.format("cut of the service host: ?services said so %.1f s after the cut (check interval %d s)%n",
                detected / 1000.0, CHECK_SECONDS));
        String[] names = {"dir to the vehicle", "SQL to the database", "?mailboxes", "?status", "?ping"};
        for (int i = 0; i < names.length; i++) {
            Reply r = during.get(i);
            assertThat(r).as(names[i] + " answered").isNotNull();
            report.append(String.format("  during the cut, %-20s %6d ms  %s %s  %s%n", names[i], r.millis, r.status, r.code,
                    r.text.length() > 140 ? r.text.substring(0, 140) + "..." : r.text));
        }
        report.append(String.format("  in flight at the cut, sleep 8000  %6d ms  %s %s  %s%n", sleeping.millis, sleeping.status,
                sleeping.code, sleeping.text));
        assertThat(detected).as("?services says so within two check intervals").isLessThanOrEqualTo(2L * CHECK_SECONDS * 1000 + 5_000);
        assertThat(during.get(4).millis).as("?ping waits for nobody").isLessThan(10_000);
        assertThat(during.get(2).millis).as("?mailboxes: one per-service deadline, not the request timeout").isLessThan(10_000);
        assertThat(during.get(2).text).contains("not answering");
        assertThat(during.get(3).millis).isLessThan(10_000);
        assertThat(during.get(3).code).isEqualTo("SERVICE_GONE");
        for (int i = 0; i < 2; i++) {
            assertThat(during.get(i).millis).as(names[i] + " within its deadline").isLessThanOrEqualTo(REQUEST_TIMEOUT * 1000L + 2_000);
            assertThat(during.get(i).code).as(names[i]).isEqualTo("SERVICE_GONE");
            assertThat(during.get(i).text).as(names[i]).contains(SVC).doesNotContain("may still complete");
        }
        assertThat(sleeping.millis).as("in flight: within its deadline").isLessThanOrEqualTo(REQUEST_TIMEOUT * 1000L + 9_000);
        assertThat(sleeping.status).isEqualTo("ERROR");

        // The cut lasts until every request sent into it has been answered (above), not a fixed 30 s:
        // what follows needs the link back, not more time without it.
        long cutMillis = System.currentTimeMillis() - cut;
        net.mend("svc");
        long mended = System.nanoTime();
        awaitServices(net, 4, 60);
        report.append(String.format("after the cut of %.1f s: all 4 services answering again %.1f s after the link came back%n",
                cutMillis / 1000.0,
                (System.nanoTime() - mended) / 1e9));
        Map<Integer, Reply> after = requests(net, logs, "after-cut", gliderBox + "|dir", DB + "|SELECT COUNT(*) FROM vehicle",
                CLOCK + "|echo back");
        assertThat(after.get(0).status).as(after.get(0).text).isEqualTo("OK");
        assertThat(after.get(1).status).as(after.get(1).text).isEqualTo("OK");
        assertThat(after.get(2).text).isEqualTo("back");
        for (Process p : services) {
            assertThat(p.isAlive()).as("nothing restarted").isTrue();
        }
    }

    private void nat(Netns net, Path logs, String registry, String secret) throws Exception {
        Path naive = logs.resolve("nat-clock.log");
        long t0 = System.nanoTime();
        Process p = net.java("nat", naive, "org.ripv.examples.ClockService", "--server", registry, "--secret-file", secret,
                "--host", NAT);
        waitFor(naive, "registration refused", 60);
        double refusedAfter = (System.nanoTime() - t0) / 1e9;
        String text = read(naive);
        assertThat(text).contains("could not call " + NAT_CLOCK + " back at " + NAT + ":").contains("--host")
                .contains("--export-port").contains("--outbound-only");
        Map<Integer, Reply> listed = requests(net, logs, "nat-services", "|?services");
        assertThat(listed.get(0).text).doesNotContain(NAT_CLOCK + "  SID").contains(NAT_CLOCK + "  REFUSED at ")
                .contains("cannot call it back at " + NAT + ":");
        p.destroy();
        p.waitFor(20, TimeUnit.SECONDS);
        report.append(String.format("service behind NAT: refused %.1f s after its start (JVM start included): %s%n", refusedAfter,
                text.lines().filter(l -> l.contains("registration refused")).findFirst().orElse("").strip()));

        Path outbound = logs.resolve("nat-clock-outbound.log");
        t0 = System.nanoTime();
        net.java("nat", outbound, "org.ripv.examples.ClockService", "--server", registry, "--secret-file", secret,
                "--host", NAT, "--outbound-only");
        awaitServices(net, 5, 60);
        double up = (System.nanoTime() - t0) / 1e9;
        Map<Integer, Reply> r = requests(net, logs, "nat-outbound", NAT_CLOCK + Handles.platformDefault() + "|echo through the NAT",
                "|?mailboxes");
        assertThat(r.get(0).text).isEqualTo("through the NAT");
        assertThat(r.get(1).text).contains(NAT_CLOCK);
        report.append(String.format("same service with --outbound-only through the NAT: registered and answering %.1f s after"
                + " its start; request round trip %d ms%n", up, r.get(0).millis));
    }
}
