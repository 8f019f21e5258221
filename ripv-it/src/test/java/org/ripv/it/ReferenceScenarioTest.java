package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/**
 * SPEC §10, the thesis's reference scenario, through the CLI against all three real services and
 * the permit file the server writes on first start: the operator team does everything; the
 * observer team lists and offloads the same files but is refused the upload to the glider and GO.
 */
class ReferenceScenarioTest {
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
    final ByteArrayOutputStream out = new ByteArrayOutputStream();
    final ByteArrayOutputStream err = new ByteArrayOutputStream();

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
    }

    int cli(String user, String... lines) {
        return InJvmCli.exec(out, err, InJvmCli.as(user, "localhost:" + sys.server().port(), "--timeout", "120"), lines);
    }

    String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    void bothTeamsThroughTheWholeSystem() throws Exception {
        sys = TestSystem.start(dir.resolve("server")); // the permit file comes from the server's template
        sys.user("otto", "operators").user("olga", "observers", "db-reader");
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), YMODEM);
        int port = glider.listen(0);
        LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(YMODEM);
        SerialPortServer serial = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
        sys.register(serial);
        DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1");
        sys.register(new DatabaseServer("localhost", List.of(db), new QueryLimits(1000, 10, QueryLimits.DEFAULT_MAX_RESULT_CHARS)));
        sys.register(new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))));
        String glider = "<SerialPortServer>::<localhost>" + serial.handles().get(0);

        // The operators upload a new binary and check the upload directory.
        byte[] binary = new byte[30_000];
        new Random(10).nextBytes(binary);
        Path local = dir.resolve("GLIDER.BIN");
        Files.write(local, binary);
        assertThat(cli("otto", "put " + local, "?ulfiles")).as(err()).isZero();
        assertThat(out()).contains("GLIDER.BIN");

        // dir on the glider, then offload the mission logs with YMODEM.
        assertThat(cli("otto", "use " + glider, "dir", "ymodem:get MISSION1.LOG MISSION2.LOG", "?dlfiles")).as(err()).isZero();
        assertThat(out()).contains("MISSION1.LOG").contains("MISSION2.LOG");
        assertThat(Files.readAllBytes(sys.downloaded("MISSION1.LOG")))
                .isEqualTo(Files.readAllBytes(this.glider.directory().resolve("MISSION1.LOG")));

        // Query the database for recent activity.
        assertThat(cli("otto", "use <DatabaseServer>::<localhost>TTY1",
                "SELECT m.name, v.name FROM mission m JOIN vehicle v ON m.vehicle_id = v.vehicle_id WHERE m.endt IS NULL"))
                .as(err()).isZero();
        assertThat(out()).contains("(3 rows)");

        // A data file to the DataVisServer, and the JPEG is back in the download directory.
        Path data = Path.of("..", "docs", "samples", "glider-temperature.dat");
        assertThat(cli("otto", "put " + data, "use <DataVisServer>::<localhost>TTY1", "vis:glider-temperature.dat")).as(err()).isZero();
        byte[] jpeg = Files.readAllBytes(sys.downloaded("glider-temperature.jpg"));
        assertThat(jpeg[0] & 0xff).isEqualTo(0xff);
        assertThat(jpeg[1] & 0xff).isEqualTo(0xd8);

        // Meanwhile the observers see the same files the operators offloaded (the template lets them
        // send nothing to the vehicle: issue 23, item 12)...
        assertThat(cli("olga", "?dlfiles")).as(err()).isZero();
        assertThat(out()).contains("MISSION2.LOG");
        assertThat(cli("olga", "use " + glider, "dir")).isEqualTo(1);
        assertThat(err()).contains("FORBIDDEN").contains("'dir'");
        // ...and may read the database, but not write it, nor upload to the glider, nor send GO.
        assertThat(cli("olga", "use <DatabaseServer>::<localhost>TTY1", "DELETE FROM sensor_data")).isEqualTo(1);
        assertThat(cli("olga", "use " + glider, "ymodem:put GLIDER.BIN")).isEqualTo(1);
        assertThat(err()).contains("FORBIDDEN").contains("olga").contains("ymodem:put GLIDER.BIN");
        assertThat(cli("olga", "use " + glider, "GO")).isEqualTo(1);
        assertThat(err()).contains("FORBIDDEN").contains("'GO'");
        assertThat(this.glider.directory().resolve("GLIDER.BIN")).doesNotExist();

        // The operators send the new binary to the glider and give GO.
        assertThat(cli("otto", "use " + glider, "ymodem:put GLIDER.BIN", "GO")).as(err()).isZero();
        assertThat(Files.readAllBytes(this.glider.directory().resolve("GLIDER.BIN"))).isEqualTo(binary);
        assertThat(out()).contains("submerging");
    }
}
