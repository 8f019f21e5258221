package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

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
    static final Path ROOT = LaunchedSystem.ROOT;
    static final Path SLOCUM = ROOT.resolve("ripv-services/src/test/resources/slocum");
    static final Path SLOCUM_BINARY = ROOT.resolve("../shared/data/slocum-binary").normalize();

    @TempDir
    Path tmp;

    @RegisterExtension
    final LaunchedSystem sys = new LaunchedSystem();

    /** {@code SELECT COUNT(*) AS n FROM} what follows (named: a count's own column name is "1"). */
    long count(String db, String from) {
        assertThat(sys.cli("use " + db, "SELECT COUNT(*) AS n FROM " + from)).as(sys.out()).isZero();
        java.util.regex.Matcher m = Pattern.compile("(?m)^\\s*\\|?\\s*(\\d+)\\s*\\|?\\s*$").matcher(sys.out());
        assertThat(m.find()).as("a number in " + sys.out()).isTrue();
        return Long.parseLong(m.group(1));
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
        sys.start("socat", new ProcessBuilder("socat", "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec bash " + script + " " + dir + "'"));
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!Files.exists(pty)) {
            assertThat(System.nanoTime()).as("socat made " + pty).isLessThan(end);
            Thread.sleep(50);
        }
        return dir;
    }

    @Test
    void aFetchedDbaFileReachesPositionsAndATrackPlotWithEveryPieceLaunched() throws Exception {
        LaunchedSystem.assumeJars();
        Path data = sys.data;
        Path files = Files.createDirectories(tmp.resolve("glider-files"));
        Files.copy(SLOCUM.resolve("cp_388_2016_012_0_0.mrg"), files.resolve("cp_388_2016_012_0_0.mrg"));

        sys.startServer(List.of());
        sys.startSimulator("--listen", "" + sys.gliderPort, "--files", files.toString());
        Path pty = tmp.resolve("lrzsz-pty");
        Path vehicle = lrzszVehicle(pty);
        sys.startService("serial", List.of(), "serial", "--link", "tcp://127.0.0.1:" + sys.gliderPort, "--link", pty.toString());
        sys.startService("database", List.of(), "database");
        sys.startService("datavis", List.of(), "datavis");

        String services = sys.awaitServices("SerialPortServer", "DatabaseServer", "DataVisServer");
        String serial = LaunchedSystem.MAILBOX.matcher(services).results().map(r -> r.group())
                .filter(m -> m.startsWith("<SerialPortServer>") && !m.contains("lrzsz")).findFirst().orElseThrow();
        String lrzsz = LaunchedSystem.MAILBOX.matcher(services).results().map(r -> r.group())
                .filter(m -> m.startsWith("<SerialPortServer>") && m.contains("lrzsz")).findFirst().orElseThrow();
        String db = LaunchedSystem.mailbox(services, "DatabaseServer");
        String vis = LaunchedSystem.mailbox(services, "DataVisServer");

        assertThat(sys.cli("use " + serial, "ymodem:get cp_388_2016_012_0_0.mrg")).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out() + sys.log("database")).contains("received cp_388_2016_012_0_0.mrg")
                .contains("cp_388-2016-012-0-0: 23 rows, 52 sensors, 292 values, 2 positions").doesNotContain("DATABASE_ERROR");
        assertThat(sys.cli("use " + db, "SELECT vehicle, lat, lon FROM positions ORDER BY time_utc")).as(sys.out()).isZero();
        assertThat(sys.out()).contains("cp_388").contains("39.8477").contains("-70.7722").contains("2 rows");
        assertThat(sys.cli("use " + vis, "vis:track cp_388", "?dlfiles")).as(sys.out()).isZero();
        assertThat(sys.out()).contains("plotted 2 rows").contains("track-cp_388.jpg");
        try (var found = Files.walk(data)) {
            Path jpeg = found.filter(f -> f.getFileName().toString().equals("track-cp_388.jpg")).findFirst().orElseThrow();
            byte[] b = Files.readAllBytes(jpeg);
            assertThat(b[0] & 0xff).isEqualTo(0xFF);
            assertThat(b[1] & 0xff).isEqualTo(0xD8);
            assertThat(javax.imageio.ImageIO.read(jpeg.toFile())).as("a decodable JPEG").isNotNull();
        }

        // The glider's own files from an lrzsz vehicle: the .sbd first, without its cache.
        String sbd = "rosie_713-2019-166-0-157.sbd";
        assertThat(sys.cli("use " + lrzsz, "ymodem:get " + sbd)).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).contains("received " + sbd).contains(sbd + ": kept, waiting for the sensor list 6b016a2e.cac");
        // not only in the reply: the database's ?status and its events say so, with the CRC
        assertThat(sys.cli("?status " + db)).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).contains("waiting for sensor lists: 6b016a2e.cac: " + sbd);
        assertThat(sys.awaitHistory(db, "INGEST_WAITING")).contains(sbd + " waits for the sensor list 6b016a2e.cac");
        assertThat(sys.cli("use " + lrzsz, "ymodem:get 6b016a2e.cac rosie_713-2019-166-0-157.tbd 426bd56d.cac")).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).contains("6b016a2e.cac: sensor list 6b016a2e kept in the cache")
                .contains(sbd + " (waited for 6b016a2e.cac): rosie_713-2019-166-0-157: 365 rows, 27 sensors")
                .contains("rosie_713-2019-166-0-157: 642 rows, 9 sensors");
        assertThat(sys.cli("?status " + db)).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).doesNotContain("waiting for sensor lists");
        assertThat(sys.awaitHistory(db, "INGEST_RELEASED"))
                .contains(sbd + " (waited for 6b016a2e.cac): rosie_713-2019-166-0-157: 365 rows");
        // the same file again is stored once
        assertThat(sys.cli("use " + lrzsz, "ymodem:get " + sbd)).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).contains("rosie_713-2019-166-0-157: stored already");
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
        assertThat(sys.cli("use " + lrzsz, "ymodem:get rosie_713-2019-166-0-157.dbd")).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).contains("rosie_713-2019-166-0-157: 365 rows, 28 sensors")
                .contains("365 of the rows' cycles were stored already");
        assertThat(count(db, "cycle WHERE vehicle = 'rosie_713'")).isEqualTo(cycles);
        assertThat(count(db, "positions WHERE vehicle = 'rosie_713'")).isEqualTo(fixes);
        assertThat(count(db, "reading WHERE vehicle = 'rosie_713'")).isEqualTo(readings + 365);
        assertThat(count(db, "dives WHERE vehicle = 'rosie_713'")).isEqualTo(1);
        assertThat(sys.cli("use " + db, "SELECT lat, lon, source FROM positions WHERE vehicle = 'rosie_713' ORDER BY time_utc"
                + " FETCH FIRST 1 ROWS ONLY")).as(sys.out()).isZero();
        assertThat(sys.out()).containsPattern("51\\.58\\d*\\s*\\|\\s*-128\\.31\\d*");
        assertThat(sys.cli("use " + vis, "vis:track rosie_713")).as(sys.out()).isZero();
        assertThat(sys.out()).contains("track-rosie_713.jpg");
        try (var found = Files.walk(data)) {
            Path jpeg = found.filter(f -> f.getFileName().toString().equals("track-rosie_713.jpg")).findFirst().orElseThrow();
            assertThat(javax.imageio.ImageIO.read(jpeg.toFile())).as("a decodable JPEG").isNotNull();
        }
        assertThat(Files.list(vehicle).count()).isPositive();

        assertThat(sys.log("database")).doesNotContain("REJECTED").doesNotContain("Warning: RMI replies");
        assertThat(sys.log("serial") + sys.log("datavis")).doesNotContain("Warning: RMI replies");
    }

    /**
     * Issue 32, item 10, as launched: a real flight file cut short of its end (as over Iridium) is
     * ingested up to its last whole cycle and says what it left; a file the database refuses and a
     * file fetched again are notes of an OK fetch and events of the database's MailBox, never a
     * failed fetch (the CLI exits 0, no DATABASE_ERROR).
     */
    @Test
    void aCutRealFileIsIngestedUpToItsLastWholeCycleAndRefusedOrRepeatedFilesAreNotesOfAnOkFetch() throws Exception {
        LaunchedSystem.assumeJars();
        assumeTrue(Files.isDirectory(SLOCUM_BINARY.resolve("realtime_raw")), "needs ../shared/data/slocum-binary beside the repository");
        Path data = sys.data;
        Path files = Files.createDirectories(tmp.resolve("glider-files"));
        String tbd = "rosie_713-2019-166-0-157.tbd";
        byte[] whole = Files.readAllBytes(SLOCUM_BINARY.resolve("realtime_raw").resolve(tbd));
        Files.write(files.resolve(tbd), java.util.Arrays.copyOf(whole, whole.length - 100)); // the call cut near its end
        Files.copy(SLOCUM_BINARY.resolve("cac/426bd56d.cac"), files.resolve("426bd56d.cac"));
        byte[] noise = new byte[3000];
        new java.util.Random(32).nextBytes(noise);
        Files.write(files.resolve("junk.scd"), noise);

        sys.startServer(List.of());
        sys.startSimulator("--listen", "" + sys.gliderPort, "--files", files.toString());
        sys.startService("serial", List.of(), "serial", "--link", "tcp://127.0.0.1:" + sys.gliderPort);
        sys.startService("database", List.of(), "database");
        String services = sys.awaitServices("SerialPortServer", "DatabaseServer");
        String serial = LaunchedSystem.mailbox(services, "SerialPortServer");
        String db = LaunchedSystem.mailbox(services, "DatabaseServer");

        assertThat(sys.cli("use " + serial, "ymodem:get 426bd56d.cac " + tbd + " junk.scd")).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out())
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
        assertThat(sys.cli("use " + serial, "ymodem:get " + tbd)).as(sys.out()).isZero();
        assertThat(sys.out()).as(sys.out()).contains("received " + tbd).contains("fetched 1, ingested 0 into ")
                .containsPattern("(?m)^note: rosie_713-2019-166-0-157: stored already \\(file \\d+\\), nothing added")
                .doesNotContain("DATABASE_ERROR");
        assertThat(count(db, "cycle WHERE vehicle = 'rosie_713'")).isEqualTo(cycles);
        assertThat(sys.awaitHistory(db, "INGEST_REPEATED")).contains("INGEST_REFUSED").contains("junk.scd: refused, nothing stored")
                .contains("stored already");
    }
}
