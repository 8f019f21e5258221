package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.cli.CliCommand;
import org.ripv.it.TestSystem;
import org.ripv.server.permit.PermitFile;
import picocli.CommandLine;

/**
 * The data loop as the README starts it: {@code ripv-server.jar}, and {@code ripv-services.jar}
 * as the serial, database and datavis services and as the glider simulator, each a process of its
 * own with the launchers' RMI filter factory. A {@code ymodem:get} of a DBA file is ingested on
 * its own, {@code positions} answers, and {@code vis:track} draws a JPEG. Then a vehicle whose
 * YMODEM is lrzsz ({@code sb}, on a socat pseudo-terminal) sends the glider's own binary files
 * (issue 22): a {@code .sbd} whose sensor-list cache the shore lacks waits, and is ingested by
 * itself when {@code ymodem:get} brings the {@code .cac}; the {@code .tbd} and its cache come
 * together; the positions and a track plot follow.
 *
 * <p>Issue 22: the in-process tests (TestSystem) never install the process-wide filter the
 * launchers do, so they did not see it judge Derby's own object streams and refuse the Slocum
 * tables; this test runs what users run.
 */
class LaunchedDataLoopTest {
    static final Path ROOT = RipvScriptHelpTest.ROOT;
    static final Path SLOCUM = ROOT.resolve("ripv-services/src/test/resources/slocum");
    static final Path SLOCUM_BINARY = ROOT.resolve("../shared/data/slocum-binary").normalize();

    @TempDir
    Path tmp;
    final List<Process> started = new ArrayList<>();
    final ByteArrayOutputStream out = new ByteArrayOutputStream();
    final ByteArrayOutputStream err = new ByteArrayOutputStream();
    int clientPort;
    Path knownHosts;

    static int[] freePorts(int n) throws Exception {
        int[] ports = new int[n];
        ServerSocket[] s = new ServerSocket[n];
        for (int i = 0; i < n; i++) {
            s[i] = new ServerSocket(0);
            ports[i] = s[i].getLocalPort();
        }
        for (ServerSocket x : s) {
            x.close();
        }
        return ports;
    }

    static Path jar(String module) {
        return ROOT.resolve(module + "/target/" + module + ".jar");
    }

    /** Starts {@code java -jar JAR ARGS} as the launcher does, with HOME in the test's directory. */
    Process launch(String name, String module, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(org.ripv.it.TestJvms.java(),
                "-Xmx256m", "-Duser.home=" + tmp.resolve("home"), "-jar", jar(module).toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(tmp.toFile()).redirectErrorStream(true)
                .redirectOutput(tmp.resolve(name + ".log").toFile());
        pb.environment().put("HOME", tmp.resolve("home").toString());
        Process p = pb.start();
        started.add(p);
        return p;
    }

    String log(String name) throws Exception {
        if (!Files.exists(tmp.resolve(name + ".log"))) {
            return ""; // not launched by this test
        }
        return Files.readString(tmp.resolve(name + ".log"), StandardCharsets.UTF_8);
    }

    @AfterEach
    void stop() throws Exception {
        for (int i = started.size() - 1; i >= 0; i--) {
            started.get(i).destroy();
        }
        for (Process p : started) {
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
    }

    int cli(String... lines) {
        out.reset();
        err.reset();
        List<String> all = new ArrayList<>(List.of("--server", "localhost:" + clientPort, "--user", "alice",
                "--password", TestSystem.PASSWORD, "--timeout", "120", "--known-hosts", knownHosts.toString()));
        for (String l : lines) {
            all.add("--exec");
            all.add(l);
        }
        CliCommand cmd = new CliCommand(new ByteArrayInputStream(new byte[0]),
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        return new CommandLine(cmd).execute(all.toArray(String[]::new));
    }

    String out() {
        return out.toString(StandardCharsets.UTF_8) + err.toString(StandardCharsets.UTF_8);
    }

    static final Pattern MAILBOX = Pattern.compile("<(\\w+)>::<[^>]+>[A-Za-z0-9_.-]+");

    /** {@code ?mailboxes} once every one of the services has a MailBox there. */
    String awaitServices(String... services) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (true) {
            cli("?mailboxes");
            String text = out();
            java.util.Set<String> seen = new java.util.HashSet<>();
            MAILBOX.matcher(text).results().forEach(r -> seen.add(r.group(1)));
            if (seen.containsAll(List.of(services))) {
                return text;
            }
            assertThat(System.nanoTime()).as("services registered; last answer: " + text + "\nlogs: "
                    + log("serial") + log("database") + log("datavis")).isLessThan(end);
            Thread.sleep(500);
        }
    }

    /** {@code SELECT COUNT(*) AS n FROM} what follows (named: a count's own column name is "1"). */
    long count(String db, String from) {
        assertThat(cli("use " + db, "SELECT COUNT(*) AS n FROM " + from)).as(out()).isZero();
        java.util.regex.Matcher m = Pattern.compile("(?m)^\\s*\\|?\\s*(\\d+)\\s*\\|?\\s*$").matcher(out());
        assertThat(m.find()).as("a number in " + out()).isTrue();
        return Long.parseLong(m.group(1));
    }

    /** {@code ?history MAILBOX} once it has the event (services publish on a thread of their own). */
    String awaitHistory(String mailbox, String event) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (true) {
            cli("?history " + mailbox);
            if (out().contains(event)) {
                return out();
            }
            assertThat(System.nanoTime()).as("?history " + mailbox + " has " + event + "; last answer: " + out()).isLessThan(end);
            Thread.sleep(500);
        }
    }

    static String mailbox(String mailboxes, String service) {
        return MAILBOX.matcher(mailboxes).results().filter(r -> r.group(1).equals(service)).findFirst().orElseThrow().group();
    }

    /** A PicoDOS-like shell whose ys/yr are lrzsz's sb/rb, behind a socat pseudo-terminal at {@code pty}. */
    Path lrzszVehicle(Path pty) throws Exception {
        org.ripv.testing.Tools.require("socat", "sb", "rb");
        Path dir = Files.createDirectories(tmp.resolve("lrzsz-vehicle"));
        Path shared = SLOCUM_BINARY;
        assumeTrue(Files.isDirectory(shared.resolve("realtime_raw")), "needs ../shared/data/slocum-binary beside the repository");
        for (String f : List.of("rosie_713-2019-166-0-157.sbd", "rosie_713-2019-166-0-157.tbd")) {
            Files.copy(shared.resolve("realtime_raw").resolve(f), dir.resolve(f));
        }
        Files.copy(shared.resolve("cac/6b016a2e.cac"), dir.resolve("6b016a2e.cac"));
        Files.copy(shared.resolve("cac/426bd56d.cac"), dir.resolve("426bd56d.cac"));
        Path script = ROOT.resolve("ripv-services/src/test/resources/org/ripv/services/serial/lrzsz-vehicle.sh");
        Process socat = new ProcessBuilder("socat", "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec bash " + script + " " + dir + "'")
                .redirectErrorStream(true).redirectOutput(tmp.resolve("socat.log").toFile()).start();
        started.add(socat);
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!Files.exists(pty)) {
            assertThat(System.nanoTime()).as("socat made " + pty).isLessThan(end);
            Thread.sleep(50);
        }
        return dir;
    }

    @Test
    void aFetchedDbaFileReachesPositionsAndATrackPlotWithEveryPieceLaunched() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services")) {
            assumeTrue(Files.isRegularFile(jar(m)), "needs the jars (mvn verify builds them before this module's tests)");
        }
        int[] p = freePorts(4);
        clientPort = p[0];
        Path data = tmp.resolve("ripv-data");
        knownHosts = tmp.resolve("known_hosts");
        Files.createDirectories(tmp.resolve("home"));
        Path files = Files.createDirectories(tmp.resolve("glider-files"));
        Files.copy(SLOCUM.resolve("cp_388_2016_012_0_0.mrg"), files.resolve("cp_388_2016_012_0_0.mrg"));

        launch("server", "ripv-server", "server", "--data", data.toString(), "--port", "" + p[0], "--registry-port", "" + p[1],
                "--http-port", "0", "--outbound-port", "" + p[2]);
        launch("simulator", "ripv-services", "simulator", "--listen", "" + p[3], "--files", files.toString());
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (!log("server").contains("RIPVServer ready")) {
            assertThat(System.nanoTime()).as(log("server")).isLessThan(end);
            assertThat(started.get(0).isAlive()).as(log("server")).isTrue();
            Thread.sleep(200);
        }
        PermitFile.setUser(data.resolve("permit.txt"), "alice", TestSystem.PASSWORD.toCharArray(), List.of("operators"), 1000);
        String secret = data.resolve("service.secret").toString();
        String server = "localhost:" + p[1];
        Path pty = tmp.resolve("lrzsz-pty");
        Path vehicle = lrzszVehicle(pty);
        launch("serial", "ripv-services", "serial", "--server", server, "--secret-file", secret,
                "--link", "tcp://127.0.0.1:" + p[3], "--link", pty.toString());
        launch("database", "ripv-services", "database", "--server", server, "--secret-file", secret);
        launch("datavis", "ripv-services", "datavis", "--server", server, "--secret-file", secret);

        String services = awaitServices("SerialPortServer", "DatabaseServer", "DataVisServer");
        String serial = MAILBOX.matcher(services).results().map(r -> r.group())
                .filter(m -> m.startsWith("<SerialPortServer>") && !m.contains("lrzsz")).findFirst().orElseThrow();
        String lrzsz = MAILBOX.matcher(services).results().map(r -> r.group())
                .filter(m -> m.startsWith("<SerialPortServer>") && m.contains("lrzsz")).findFirst().orElseThrow();
        String db = mailbox(services, "DatabaseServer");
        String vis = mailbox(services, "DataVisServer");

        assertThat(cli("use " + serial, "ymodem:get cp_388_2016_012_0_0.mrg")).as(out()).isZero();
        assertThat(out()).as(out() + log("database")).contains("received cp_388_2016_012_0_0.mrg")
                .contains("cp_388-2016-012-0-0: 23 rows, 52 sensors, 292 values, 2 positions").doesNotContain("DATABASE_ERROR");
        assertThat(cli("use " + db, "SELECT vehicle, lat, lon FROM positions ORDER BY time_utc")).as(out()).isZero();
        assertThat(out()).contains("cp_388").contains("39.8477").contains("-70.7722").contains("2 rows");
        assertThat(cli("use " + vis, "vis:track cp_388", "?dlfiles")).as(out()).isZero();
        assertThat(out()).contains("plotted 2 rows").contains("track-cp_388.jpg");
        try (var found = Files.walk(data)) {
            Path jpeg = found.filter(f -> f.getFileName().toString().equals("track-cp_388.jpg")).findFirst().orElseThrow();
            byte[] b = Files.readAllBytes(jpeg);
            assertThat(b[0] & 0xff).isEqualTo(0xFF);
            assertThat(b[1] & 0xff).isEqualTo(0xD8);
            assertThat(javax.imageio.ImageIO.read(jpeg.toFile())).as("a decodable JPEG").isNotNull();
        }

        // The glider's own files from an lrzsz vehicle: the .sbd first, without its cache.
        String sbd = "rosie_713-2019-166-0-157.sbd";
        assertThat(cli("use " + lrzsz, "ymodem:get " + sbd)).as(out()).isZero();
        assertThat(out()).as(out()).contains("received " + sbd).contains(sbd + ": kept, waiting for the sensor list 6b016a2e.cac");
        // not only in the reply: the database's ?status and its events say so, with the CRC
        assertThat(cli("?status " + db)).as(out()).isZero();
        assertThat(out()).as(out()).contains("waiting for sensor lists: 6b016a2e.cac: " + sbd);
        assertThat(awaitHistory(db, "INGEST_WAITING")).contains(sbd + " waits for the sensor list 6b016a2e.cac");
        assertThat(cli("use " + lrzsz, "ymodem:get 6b016a2e.cac rosie_713-2019-166-0-157.tbd 426bd56d.cac")).as(out()).isZero();
        assertThat(out()).as(out()).contains("6b016a2e.cac: sensor list 6b016a2e kept in the cache")
                .contains(sbd + " (waited for 6b016a2e.cac): rosie_713-2019-166-0-157: 365 rows, 27 sensors")
                .contains("rosie_713-2019-166-0-157: 642 rows, 9 sensors");
        assertThat(cli("?status " + db)).as(out()).isZero();
        assertThat(out()).as(out()).doesNotContain("waiting for sensor lists");
        assertThat(awaitHistory(db, "INGEST_RELEASED")).contains(sbd + " (waited for 6b016a2e.cac): rosie_713-2019-166-0-157: 365 rows");
        // the same file again is stored once
        assertThat(cli("use " + lrzsz, "ymodem:get " + sbd)).as(out()).isZero();
        assertThat(out()).as(out()).contains("rosie_713-2019-166-0-157: stored already");
        // after recovery, the segment's .dbd: the same cycles with a sensor more; each cycle stays one
        long cycles = count(db, "cycle WHERE vehicle = 'rosie_713'");
        long fixes = count(db, "positions WHERE vehicle = 'rosie_713'");
        long readings = count(db, "reading WHERE vehicle = 'rosie_713'");
        Path shared = SLOCUM_BINARY;
        byte[] plain = Files.readAllBytes(shared.resolve("realtime_raw").resolve(sbd));
        org.ripv.services.ingest.SensorListCache cache = new org.ripv.services.ingest.SensorListCache(shared.resolve("cac"));
        int extra = new org.ripv.services.ingest.SlocumBinaryReader(new ByteArrayInputStream(plain), sbd, cache).sensors().size();
        Files.write(vehicle.resolve("rosie_713-2019-166-0-157.dbd"), org.ripv.services.ingest.SlocumEncoder.recode(plain, cache,
                "dbd", List.of(new org.ripv.services.ingest.SlocumSensor("x_dbd_only", "nodim", 8)), (row, n) -> row[extra] = n));
        assertThat(cli("use " + lrzsz, "ymodem:get rosie_713-2019-166-0-157.dbd")).as(out()).isZero();
        assertThat(out()).as(out()).contains("rosie_713-2019-166-0-157: 365 rows, 28 sensors")
                .contains("365 of the rows' cycles were stored already");
        assertThat(count(db, "cycle WHERE vehicle = 'rosie_713'")).isEqualTo(cycles);
        assertThat(count(db, "positions WHERE vehicle = 'rosie_713'")).isEqualTo(fixes);
        assertThat(count(db, "reading WHERE vehicle = 'rosie_713'")).isEqualTo(readings + 365);
        assertThat(count(db, "dives WHERE vehicle = 'rosie_713'")).isEqualTo(1);
        assertThat(cli("use " + db, "SELECT lat, lon, source FROM positions WHERE vehicle = 'rosie_713' ORDER BY time_utc"
                + " FETCH FIRST 1 ROWS ONLY")).as(out()).isZero();
        assertThat(out()).containsPattern("51\\.58\\d*\\s*\\|\\s*-128\\.31\\d*");
        assertThat(cli("use " + vis, "vis:track rosie_713")).as(out()).isZero();
        assertThat(out()).contains("track-rosie_713.jpg");
        try (var found = Files.walk(data)) {
            Path jpeg = found.filter(f -> f.getFileName().toString().equals("track-rosie_713.jpg")).findFirst().orElseThrow();
            assertThat(javax.imageio.ImageIO.read(jpeg.toFile())).as("a decodable JPEG").isNotNull();
        }
        assertThat(Files.list(vehicle).count()).isPositive();

        assertThat(log("database")).doesNotContain("REJECTED").doesNotContain("Warning: RMI replies");
        assertThat(log("serial") + log("datavis")).doesNotContain("Warning: RMI replies");
    }

    /**
     * Issue 32, item 10, as launched: a real flight file cut short of its end (as over Iridium) is
     * ingested up to its last whole cycle and says what it left; a file the database refuses and a
     * file fetched again are notes of an OK fetch and events of the database's MailBox, never a
     * failed fetch (the CLI exits 0, no DATABASE_ERROR).
     */
    @Test
    void aCutRealFileIsIngestedUpToItsLastWholeCycleAndRefusedOrRepeatedFilesAreNotesOfAnOkFetch() throws Exception {
        for (String m : List.of("ripv-server", "ripv-services")) {
            assumeTrue(Files.isRegularFile(jar(m)), "needs the jars (mvn verify builds them before this module's tests)");
        }
        assumeTrue(Files.isDirectory(SLOCUM_BINARY.resolve("realtime_raw")), "needs ../shared/data/slocum-binary beside the repository");
        int[] p = freePorts(4);
        clientPort = p[0];
        Path data = tmp.resolve("ripv-data");
        knownHosts = tmp.resolve("known_hosts");
        Files.createDirectories(tmp.resolve("home"));
        Path files = Files.createDirectories(tmp.resolve("glider-files"));
        String tbd = "rosie_713-2019-166-0-157.tbd";
        byte[] whole = Files.readAllBytes(SLOCUM_BINARY.resolve("realtime_raw").resolve(tbd));
        Files.write(files.resolve(tbd), java.util.Arrays.copyOf(whole, whole.length - 100)); // the call cut near its end
        Files.copy(SLOCUM_BINARY.resolve("cac/426bd56d.cac"), files.resolve("426bd56d.cac"));
        byte[] noise = new byte[3000];
        new java.util.Random(32).nextBytes(noise);
        Files.write(files.resolve("junk.scd"), noise);

        launch("server", "ripv-server", "server", "--data", data.toString(), "--port", "" + p[0], "--registry-port", "" + p[1],
                "--http-port", "0", "--outbound-port", "" + p[2]);
        launch("simulator", "ripv-services", "simulator", "--listen", "" + p[3], "--files", files.toString());
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (!log("server").contains("RIPVServer ready")) {
            assertThat(System.nanoTime()).as(log("server")).isLessThan(end);
            assertThat(started.get(0).isAlive()).as(log("server")).isTrue();
            Thread.sleep(200);
        }
        PermitFile.setUser(data.resolve("permit.txt"), "alice", TestSystem.PASSWORD.toCharArray(), List.of("operators"), 1000);
        String secret = data.resolve("service.secret").toString();
        String server = "localhost:" + p[1];
        launch("serial", "ripv-services", "serial", "--server", server, "--secret-file", secret, "--link", "tcp://127.0.0.1:" + p[3]);
        launch("database", "ripv-services", "database", "--server", server, "--secret-file", secret);
        String services = awaitServices("SerialPortServer", "DatabaseServer");
        String serial = mailbox(services, "SerialPortServer");
        String db = mailbox(services, "DatabaseServer");

        assertThat(cli("use " + serial, "ymodem:get 426bd56d.cac " + tbd + " junk.scd")).as(out()).isZero();
        assertThat(out()).as(out())
                .contains("received 426bd56d.cac").contains(tbd + " (" + (whole.length - 100) + " bytes)").contains("junk.scd (3000 bytes)")
                .contains("fetched 3, ingested 2 into " + db + " (1 not ingested, see the notes")
                .containsPattern("rosie_713-2019-166-0-157: \\d+ rows, 9 sensors")
                .contains("the file ends after ").contains(" cycles without its end tag 'X' (")
                .contains("bytes of a cut cycle left out): read up to its last whole cycle")
                .containsPattern("(?m)^note: \\S*junk.scd: refused, nothing stored")
                .doesNotContain("DATABASE_ERROR").doesNotContain("Error:");
        long cycles = count(db, "cycle WHERE vehicle = 'rosie_713'");
        assertThat(cycles).as("the cut file's whole cycles are stored").isBetween(600L, 641L);

        // the same file again: stored already, a note of an OK fetch
        assertThat(cli("use " + serial, "ymodem:get " + tbd)).as(out()).isZero();
        assertThat(out()).as(out()).contains("received " + tbd).contains("fetched 1, ingested 0 into ")
                .containsPattern("(?m)^note: rosie_713-2019-166-0-157: stored already \\(file \\d+\\), nothing added")
                .doesNotContain("DATABASE_ERROR");
        assertThat(count(db, "cycle WHERE vehicle = 'rosie_713'")).isEqualTo(cycles);
        assertThat(awaitHistory(db, "INGEST_REPEATED")).contains("INGEST_REFUSED").contains("junk.scd: refused, nothing stored")
                .contains("stored already");
    }
}
