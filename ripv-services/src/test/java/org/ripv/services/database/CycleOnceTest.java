package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.ThreadLocalRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.ingest.DbaIngest;
import org.ripv.services.ingest.Lz4Blocks;
import org.ripv.services.ingest.SensorListCache;
import org.ripv.services.ingest.SlocumBinaryFiles;
import org.ripv.services.ingest.SlocumBinaryReader;
import org.ripv.services.ingest.SlocumData;
import org.ripv.services.ingest.SlocumEncoder;
import org.ripv.services.ingest.SlocumSensor;

/**
 * Each cycle is stored once (issue 22): a segment's {@code .sbd}, the same file again, its
 * compressed form, and later its {@code .dbd} (made here from the real {@code .sbd} with one
 * sensor more and m_depth corrected) give one CYCLE and one value per sensor per cycle, the
 * {@code .dbd}'s values kept; the DBA text of a {@code .tbd} and then the {@code .tbd} itself
 * likewise. On Derby always, and on PostgreSQL when {@code RIPV_PG_URL} names a server.
 */
class CycleOnceTest {
    static final String SEGMENT = "rosie_713-2019-166-0-157";
    @TempDir
    Path tmp;

    @Test
    void onDerby() throws Exception {
        try (Connection c = DriverManager.getConnection("jdbc:derby:" + tmp.resolve("db") + ";create=true")) {
            check(c);
        }
    }

    @Test
    void onPostgres() throws Exception {
        String url = System.getenv("RIPV_PG_URL");
        assumeTrue(url != null && !url.isBlank(), "no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER, RIPV_PG_PASSWORD) to run this test");
        Properties admin = new Properties();
        admin.setProperty("user", System.getenv().getOrDefault("RIPV_PG_USER", "postgres"));
        admin.setProperty("password", System.getenv().getOrDefault("RIPV_PG_PASSWORD", ""));
        String db = "ripv_cycles_" + Long.toString(ThreadLocalRandom.current().nextLong(1L << 40), 36).toLowerCase(Locale.ROOT);
        try (Connection c = DriverManager.getConnection(url, admin); Statement st = c.createStatement()) {
            st.execute("CREATE DATABASE " + db);
        }
        try {
            try (Connection c = DriverManager.getConnection(url.replaceFirst("/[^/?]*(\\?|$)", "/" + db + "$1"), admin)) {
                check(c);
            }
        } finally {
            try (Connection c = DriverManager.getConnection(url, admin); Statement st = c.createStatement()) {
                st.execute("DROP DATABASE " + db);
            }
        }
    }

    void check(Connection c) throws Exception {
        SqlScript.run(c, SqlScript.resource("slocumDB.sql"), "slocumDB.sql");
        Path raw = SlocumData.dir().resolve("realtime_raw");
        SensorListCache cache = SlocumData.cache();
        byte[] sbd = Files.readAllBytes(raw.resolve(SEGMENT + ".sbd"));
        DbaIngest ingest = new DbaIngest(c);

        DbaIngest.Outcome first = binary(ingest, SEGMENT + ".sbd", sbd, cache);
        assertThat(first.merged()).isZero();
        assertThat(first.rows()).isEqualTo(365);
        long values = count(c, "SELECT COUNT(*) FROM reading");
        long fixes = count(c, "SELECT COUNT(*) FROM position_fix");
        long depths = count(c, "SELECT COUNT(*) FROM reading r JOIN sensor_def s ON s.sensor_id = r.sensor_id WHERE s.name = 'm_depth'");
        assertThat(count(c, "SELECT COUNT(*) FROM cycle")).isEqualTo(365);

        // the same bytes under another name: stored already
        assertThat(binary(ingest, "again-" + SEGMENT + ".sbd", sbd, cache).duplicate()).isTrue();
        // the compressed form: every cycle is there already, nothing is added
        DbaIngest.Outcome packed = binary(ingest, SEGMENT + ".scd", Lz4Blocks.compress(sbd, 8192), cache);
        assertThat(packed.duplicate()).isFalse();
        assertThat(packed.merged()).isEqualTo(365);
        assertThat(count(c, "SELECT COUNT(*) FROM reading")).isEqualTo(values);
        assertThat(count(c, "SELECT COUNT(*) FROM position_fix")).isEqualTo(fixes);
        assertThat(count(c, "SELECT COUNT(*) FROM cycle")).isEqualTo(365);

        // the .dbd: one sensor more, m_depth corrected by half a metre; its values are the ones kept
        DbaIngest.Outcome full = binary(ingest, SEGMENT + ".dbd", dbd(sbd, cache), null);
        assertThat(full.merged()).isEqualTo(365);
        assertThat(count(c, "SELECT COUNT(*) FROM cycle")).isEqualTo(365);
        assertThat(count(c, "SELECT COUNT(*) FROM reading")).isEqualTo(values + 365);
        assertThat(count(c, "SELECT COUNT(*) FROM reading r JOIN sensor_def s ON s.sensor_id = r.sensor_id"
                + " WHERE s.name = 'x_dbd_only'")).isEqualTo(365);
        assertThat(count(c, "SELECT COUNT(*) FROM reading r JOIN sensor_def s ON s.sensor_id = r.sensor_id"
                + " WHERE s.name = 'm_depth'")).isEqualTo(depths);
        assertThat(count(c, "SELECT COUNT(*) FROM (SELECT vehicle, time_utc, source FROM positions GROUP BY vehicle, time_utc, source"
                + " HAVING COUNT(*) > 1) x")).isZero();
        assertThat(count(c, "SELECT COUNT(*) FROM position_fix")).isEqualTo(fixes);
        assertThat(count(c, "SELECT COUNT(*) FROM dives WHERE name = '" + SEGMENT + "'")).isEqualTo(1);
        List<Double> dbdDepths = column(sbd, cache, "m_depth", 0.5);
        assertThat(doubles(c, "SELECT r.value FROM reading r JOIN sensor_def s ON s.sensor_id = r.sensor_id"
                + " WHERE s.name = 'm_depth' ORDER BY r.t")).containsExactlyElementsOf(dbdDepths);
        assertThat(doubles(c, "SELECT value FROM latest WHERE sensor = 'm_depth'"))
                .containsExactly(dbdDepths.get(dbdDepths.size() - 1));

        // DBA text first, then the binary file it was printed from: one cycle each
        byte[] text = Files.readAllBytes(SlocumData.dir().resolve("expected").resolve(SEGMENT + ".tbd.dbd2asc.txt"));
        DbaIngest.Outcome dba = ingest.ingest(SEGMENT + ".tbd.asc", text, "test");
        long cycles = count(c, "SELECT COUNT(*) FROM cycle");
        long readings = count(c, "SELECT COUNT(*) FROM reading");
        DbaIngest.Outcome tbd = binary(ingest, SEGMENT + ".tbd", Files.readAllBytes(raw.resolve(SEGMENT + ".tbd")), cache);
        assertThat(tbd.merged()).isEqualTo(tbd.rows()).isEqualTo(dba.rows());
        assertThat(count(c, "SELECT COUNT(*) FROM cycle")).isEqualTo(cycles);
        assertThat(count(c, "SELECT COUNT(*) FROM reading")).isEqualTo(readings);
    }

    /**
     * Binary cycles go into the database as decoded, not through DBA text: a double keeps all its
     * digits (dbd2asc's text has 15), a float is its own shortest decimal (the text has 6).
     */
    @Test
    void binaryValuesAreStoredAsDecodedNotAsTheirDbaText() throws Exception {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        Map<String, String> tags = new java.util.LinkedHashMap<>();
        tags.put("full_filename", "exact_1-2024-001-0-0");
        tags.put("filename_extension", "sbd");
        SlocumEncoder e = SlocumEncoder.start(out, tags, List.of(new SlocumSensor("m_present_time", "timestamp", 8),
                new SlocumSensor("m_depth", "m", 4), new SlocumSensor("x_exact", "nodim", 8)));
        e.cycle(new double[] {1.7e9, 1234.5678f, 0.12345678901234568});
        e.end();
        byte[] file = out.toByteArray();
        try (Connection c = DriverManager.getConnection("jdbc:derby:" + tmp.resolve("exact") + ";create=true")) {
            SqlScript.run(c, SqlScript.resource("slocumDB.sql"), "slocumDB.sql");
            binary(new DbaIngest(c), "exact.sbd", file, null);
            assertThat(doubles(c, "SELECT value FROM latest WHERE sensor = 'x_exact'")).containsExactly(0.12345678901234568);
            assertThat(doubles(c, "SELECT value FROM latest WHERE sensor = 'm_depth'")).containsExactly(1234.5677); // the float 1234.5677490234375; the text would say 1234.57
        }
    }

    static DbaIngest.Outcome binary(DbaIngest ingest, String name, byte[] data, SensorListCache cache) throws Exception {
        return ingest.ingest(name, DbaIngest.sha256(data), () -> SlocumBinaryFiles.cycles(name, data, cache), "test");
    }

    /** The .dbd of the .sbd: the same cycles, m_depth + 0.5, and a sensor the .sbd does not carry. */
    static byte[] dbd(byte[] sbd, SensorListCache cache) throws Exception {
        int depth;
        try (SlocumBinaryReader r = new SlocumBinaryReader(new ByteArrayInputStream(sbd), "x.sbd", cache)) {
            depth = indexOf(r.sensors(), "m_depth");
            int extra = r.sensors().size();
            return SlocumEncoder.recode(sbd, cache, "dbd", List.of(new SlocumSensor("x_dbd_only", "nodim", 8)), (row, n) -> {
                row[depth] = Double.isNaN(row[depth]) ? Double.NaN : (float) (row[depth] + 0.5);
                row[extra] = n;
            });
        }
    }

    /** A 4-byte sensor's values plus {@code plus} as the ingest stores them (the float's shortest decimal), NaNs left out. */
    static List<Double> column(byte[] file, SensorListCache cache, String sensor, double plus) throws Exception {
        List<Double> out = new ArrayList<>();
        try (SlocumBinaryReader r = new SlocumBinaryReader(new ByteArrayInputStream(file), "x.sbd", cache)) {
            int i = indexOf(r.sensors(), sensor);
            double[] row = new double[r.sensors().size()];
            while (r.next(row)) {
                if (!Double.isNaN(row[i])) {
                    out.add(Double.parseDouble(Float.toString((float) (row[i] + plus))));
                }
            }
        }
        return out;
    }

    static int indexOf(List<SlocumSensor> sensors, String name) {
        for (int i = 0; i < sensors.size(); i++) {
            if (sensors.get(i).name().equals(name)) {
                return i;
            }
        }
        throw new AssertionError(name + " not among " + sensors);
    }

    static long count(Connection c, String sql) throws Exception {
        try (Statement st = c.createStatement(); ResultSet rs = st.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    static List<Double> doubles(Connection c, String sql) throws Exception {
        List<Double> out = new ArrayList<>();
        try (Statement st = c.createStatement(); ResultSet rs = st.executeQuery(sql)) {
            while (rs.next()) {
                out.add(rs.getDouble(1));
            }
        }
        return out;
    }
}
