package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.Priority;
import org.ripv.server.ServerConfig;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.ingest.SlocumEncoder;
import org.ripv.services.ingest.SlocumSensor;

/**
 * Issue 33 item 7: one sensor-list cache served every vehicle and the first writer won, never
 * checked. A file from vehicle A that claimed vehicle B's {@code sensor_list_crc} with its own list
 * had that list kept as {@code CRC.cac}, and B's files then decoded with A's list. Now a list is
 * kept and used only when it has the CRC it is filed under, as the glider computes it (checked
 * here against the real rosie_713 files and their caches in /work/shared/data/slocum-binary).
 */
class SensorCachePoisonAttackTest {
    static final Duration T = Duration.ofSeconds(60);
    static final String DB = "<DatabaseServer>::<localhost>TTY1";
    static final Path DATA = Path.of("/work/shared/data/slocum-binary");
    /** rosie_713's flight computer list, which its .sbd files name. */
    static final String B = "6b016a2e";

    @TempDir
    static Path dir;
    static TestSystem sys;

    @BeforeAll
    static void start() throws Exception {
        Assumptions.assumeTrue(Files.isDirectory(DATA), "needs " + DATA);
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("otto", "operators");
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                QueryLimits.defaults()));
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    /** Vehicle A's .sbd carrying its own list (latitude and longitude in each other's place) under B's CRC. */
    static byte[] poisoned() throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        Map<String, String> tags = new LinkedHashMap<>();
        tags.put("full_filename", "vehicle_a-2019-166-0-1");
        tags.put("filename_extension", "sbd");
        SlocumEncoder e = SlocumEncoder.start(out, tags, List.of(new SlocumSensor("m_present_time", "timestamp", 8),
                new SlocumSensor("m_lon", "lat", 8), new SlocumSensor("m_lat", "lon", 8)));
        e.cycle(new double[] {1.56e9, 4400.0, -6300.0});
        e.end();
        String text = new String(out.toByteArray(), StandardCharsets.ISO_8859_1)
                .replaceFirst("sensor_list_crc:    [0-9a-f]{8}", "sensor_list_crc:    " + B);
        return text.getBytes(StandardCharsets.ISO_8859_1);
    }

    static String ingest(ClientSocketHandler c, String name, byte[] data) throws Exception {
        Files.write(sys.downloadDir().resolve(name), data);
        return c.call(DB, "ingest " + name, Priority.NORMAL, T, p -> { }).footer().replyText();
    }

    @Test
    void anotherVehiclesListUnderThisCrcIsNeverKeptNorUsed() throws Exception {
        ClientSocketHandler otto = sys.login("otto");
        ingest(otto, "vehicle_a-2019-166-0-1.sbd", poisoned());
        // B's file is not decoded with A's list: it waits for B's own.
        byte[] real = Files.readAllBytes(DATA.resolve("realtime_raw/rosie_713-2019-166-0-156.sbd"));
        assertThat(ingest(otto, "rosie_713-2019-166-0-156.sbd", real)).contains("waiting for the sensor list " + B + ".cac");
        // A forged cache file under B's name is refused.
        String forged = "s: T    0    0 8 m_present_time timestamp\ns: T    1    1 8 m_lon lat\ns: T    2    2 8 m_lat lon\n";
        assertThat(ingest(otto, B + ".cac", forged.getBytes(StandardCharsets.ISO_8859_1)))
                .contains("does not hold the sensor list with CRC " + B).contains("refused");
        // B's real cache file is taken, and B's file is ingested with it.
        String taken = ingest(otto, B.toUpperCase() + ".CAC", Files.readAllBytes(DATA.resolve("cac/" + B + ".cac")));
        assertThat(taken).contains("sensor list " + B + " kept in the cache").contains("rosie_713-2019-166-0-156.sbd (waited for " + B);
        assertThat(taken).doesNotContain("refused");
        otto.close();
    }
}
