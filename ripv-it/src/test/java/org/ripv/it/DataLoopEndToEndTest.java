package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 13's loop through the real server and the CLI: the glider simulator serves the shared
 * Slocum files, {@code ymodem:get} fetches one, the server ingests it into the DatabaseServer on
 * its own, and {@code SELECT * FROM positions} shows the glider's fixes in decimal degrees.
 * Broken, repeated and garbage files are refused or stored once, and everything keeps serving.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class DataLoopEndToEndTest {
    static final Path SHARED = Path.of("../ripv-services/src/test/resources/slocum");
    static final String DB = "<DatabaseServer>::<localhost>TTY1";

    @TempDir
    static Path dir;
    static TestSystem sys;
    static GliderSimulator glider;
    static String serial;
    final ByteArrayOutputStream out = new ByteArrayOutputStream();
    final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @BeforeAll
    static void start() throws Exception {
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), SerialEndToEndTest.YMODEM);
        try (var files = Files.list(SHARED)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".mrg")).toList()) {
                Files.copy(f, glider.directory().resolve(f.getFileName()));
            }
        }
        Files.copy(SHARED.resolve("cp_388_2016_012_0_0.mrg"), glider.directory().resolve("CP388.DBA"));
        int port = glider.listen(0);
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(SerialEndToEndTest.YMODEM);
        SerialPortServer s = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
        sys.register(s);
        serial = "<SerialPortServer>::<localhost>" + s.handles().get(0);
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                QueryLimits.defaults()));
        sys.register(new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))));
    }

    static java.awt.image.BufferedImage jpeg(Path file) throws Exception {
        byte[] b = Files.readAllBytes(file);
        assertThat(b[0] & 0xff).isEqualTo(0xFF);
        assertThat(b[1] & 0xff).isEqualTo(0xD8);
        java.awt.image.BufferedImage img = javax.imageio.ImageIO.read(file.toFile());
        assertThat(img).as("a decodable JPEG").isNotNull();
        return img;
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
    }

    int cli(String... lines) {
        return InJvmCli.exec(out, err, InJvmCli.as("alice", "localhost:" + sys.server().port(), "--timeout", "120"), lines);
    }

    String out() {
        return out.toString(StandardCharsets.UTF_8) + err.toString(StandardCharsets.UTF_8);
    }

    @Test
    @Order(1)
    void aFetchedDbaFileIsIngestedAndItsPositionsAreQueryable() {
        assertThat(cli("use " + serial, "ymodem:get cp_388_2016_012_0_0.mrg")).as(out()).isZero();
        assertThat(out()).contains("received cp_388_2016_012_0_0.mrg").contains("cp_388_2016_012_0_0.mrg into " + DB)
                .contains("fetched 1, ingested 1 into " + DB)
                .contains("cp_388-2016-012-0-0: 23 rows, 52 sensors, 292 values, 2 positions (4 no-fix values left out)");
        assertThat(cli("use " + DB, "SELECT vehicle, lat, lon, source FROM positions ORDER BY time_utc")).as(out()).isZero();
        assertThat(out()).contains("cp_388").contains("39.8477").contains("-70.7722").contains("dead-reckoned")
                .contains("2 rows");

        // the result exports with numbers as numbers
        Path json = dir.resolve("positions.json");
        Path csv = dir.resolve("positions.csv");
        assertThat(cli("use " + DB, "SELECT vehicle, lat, lon, source FROM positions ORDER BY time_utc",
                "export json " + json, "export csv " + csv)).as(out()).isZero();
        assertThat(out()).contains("exported 2 rows as json").contains("exported 2 rows as csv");
        try {
            assertThat(Files.readString(json)).containsPattern("\\{\"VEHICLE\":\"cp_388\",\"LAT\":39\\.8477\\d*,\"LON\":-70\\.7722");
            assertThat(Files.readString(csv)).startsWith("VEHICLE,LAT,LON,SOURCE\r\ncp_388,39.8477");
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    @Order(2)
    void theSameFileUnderAnotherNameIsStoredOnce() {
        assertThat(cli("use " + serial, "ymodem:get CP388.DBA")).as(out()).isZero();
        assertThat(out()).contains("cp_388-2016-012-0-0: stored already");
        assertThat(cli("use " + DB, "SELECT COUNT(*) FROM data_file")).isZero();
        assertThat(out()).containsPattern("(?m)^\\s*1\\s*$");
    }

    @Test
    @Order(3)
    void theBrokenFileIsRefusedWithNothingStored() {
        // the download worked, the ingest did not: the fetch is OK (issue 32), the refused file a note, the file stored
        assertThat(cli("use " + serial, "ymodem:get short_header.mrg")).as(out()).isZero();
        assertThat(out()).contains("received short_header.mrg").contains("fetched 1, ingested 0 into ")
                .contains("note: ").doesNotContain("DATABASE_ERROR");
        assertThat(sys.downloadDir().resolve(org.ripv.server.files.FileStore.folderFor(serial)).resolve("short_header.mrg"))
                .exists();
        assertThat(out()).contains("1 not ingested").contains("short_header.mrg: refused, nothing stored: line 11: the file"
                + " ends in the header after 10 of 14 tag lines");
        assertThat(cli("use " + DB, "SELECT COUNT(*) FROM data_file")).isZero();
        assertThat(out()).containsPattern("(?m)^\\s*1\\s*$");
    }

    @Test
    @Order(4)
    void tenMegabytesOfGarbageNamedMrgAreRefusedAndTheServicesStayUp() throws Exception {
        byte[] garbage = new byte[10 << 20];
        new Random(13).nextBytes(garbage);
        Files.write(sys.downloadDir().resolve("GARBAGE.mrg"), garbage);
        cli("use " + DB, "ingest GARBAGE.mrg");
        assertThat(out()).contains("GARBAGE.mrg: refused, nothing stored: line 1: not a DBA file");
        assertThat(cli("use " + DB, "ingest NO_SUCH.mrg")).isNotZero();
        assertThat(out()).contains("NO_SUCH.mrg");
        assertThat(cli("use " + DB, "SELECT COUNT(*) FROM data_file", "use " + serial, "dir")).as(out()).isZero();
        assertThat(out()).containsPattern("(?m)^\\s*1\\s*$").contains("CP388.DBA");
    }

    @Test
    @Order(5)
    void automaticIngestCanBeTurnedOffPerVehicle() throws Exception {
        Files.writeString(sys.dataDir().resolve("ingest.properties"), "vehicle.unit_363 = off\n");
        assertThat(cli("use " + serial, "ymodem:get unit_363_2013_245_6_6.mrg")).as(out()).isZero();
        assertThat(out()).contains("received unit_363_2013_245_6_6.mrg").doesNotContain("ingest");
        assertThat(cli("use " + DB, "ingest unit_363_2013_245_6_6.mrg")).as(out()).isZero();
        assertThat(out()).contains("unit_363-2013-245-6-6: 657 rows, 29 sensors");
        Files.delete(sys.dataDir().resolve("ingest.properties"));
    }

    static final String VIS = "<DataVisServer>::<localhost>TTY1";
    static final String VIS_FOLDER = org.ripv.server.files.FileStore.folderFor(VIS);

    @Test
    @Order(6)
    void plotsFromTheDatabase() throws Exception {
        assertThat(cli("use " + VIS, "vis:track cp_388", "?dlfiles")).as(out()).isZero();
        assertThat(out()).contains("plotted 2 rows").contains("track-cp_388.jpg");
        assertThat(jpeg(sys.downloadDir().resolve(VIS_FOLDER + "/track-cp_388.jpg")).getWidth()).isEqualTo(800);

        assertThat(cli("use " + VIS, "vis:track unit_363 since=2013-09-05T03:00:00Z")).as(out()).isZero();
        assertThat(out()).contains("track-unit_363.jpg");
        assertThat(cli("use " + VIS, "vis:depth unit_363", "vis:profile unit_363 sci_water_temp",
                "vis:sql SELECT time_utc, depth FROM depths WHERE vehicle = 'unit_363' ORDER BY time_utc")).as(out()).isZero();
        assertThat(out()).contains("depth-unit_363.jpg").contains("profile-unit_363-sci_water_temp.jpg")
                .contains("sql-plot.jpg");
        jpeg(sys.downloadDir().resolve(VIS_FOLDER + "/depth-unit_363.jpg"));

        // a downloaded DBA file plotted directly
        assertThat(cli("use " + VIS, "vis:file unit_363_2013_245_6_6.mrg x=m_present_time y=m_depth")).as(out()).isZero();
        assertThat(out()).contains("unit_363_2013_245_6_6-m_depth.jpg");
        jpeg(sys.downloadDir().resolve(VIS_FOLDER + "/unit_363_2013_245_6_6-m_depth.jpg"));
        assertThat(cli("use " + VIS, "vis:file short_header.mrg x=m_present_time y=m_depth")).isNotZero();
        assertThat(out()).contains("not a usable DBA file: line 11");

        // bad requests get clear errors, and nothing else breaks
        assertThat(cli("use " + VIS, "vis:track nobody")).isNotZero();
        assertThat(out()).contains("no Slocum data for 'nobody' yet");
        assertThat(cli("use " + VIS, "vis:track x';DROP")).isNotZero();
        assertThat(out()).contains("is not a vehicle name");
        assertThat(cli("use " + VIS, "vis:sql SELECT vehicle, lat FROM positions")).isNotZero();
        assertThat(out()).contains("not a number");
        assertThat(cli("use " + DB, "SELECT COUNT(*) FROM positions WHERE vehicle = 'cp_388'")).as(out()).isZero();
        assertThat(out()).containsPattern("(?m)^\\s*2\\s*$");
    }
}
