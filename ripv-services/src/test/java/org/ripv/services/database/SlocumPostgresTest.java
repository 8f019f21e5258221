package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.condition.EnabledIfEnvironmentVariable;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.services.ingest.DbaFiles;

/**
 * The Slocum schema and views (sql/slocumDB.sql) on PostgreSQL, through the DatabaseServer: the
 * shared files ingested with the counts of an independent count, the views a pilot queries
 * (positions, latest, depths, dives) and the queries vis:track sends, the broken file refused with
 * nothing stored, a file stored once, the read-only role; and the views' plans (EXPLAIN ANALYZE)
 * use the indexes. Runs when {@code RIPV_PG_URL} names a server (as {@link PostgresTest}), in a
 * database of its own that it drops afterwards; skipped otherwise. With {@code -Dripv.plans.pg=FILE}
 * the plans are written out for docs/database.md.
 */
@EnabledIfEnvironmentVariable(named = "RIPV_PG_URL", matches = ".+",
        disabledReason = "no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER, RIPV_PG_PASSWORD) to run this test")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class SlocumPostgresTest {
    private static final AtomicLong IDS = new AtomicLong(5_000_000);
    private static String adminUrl;
    private static Properties admin;
    private static String dbName;
    private static String readerRole;
    private static String dbUrl;
    private static DatabaseServer service;
    private static ServiceHarness sql;

    @BeforeAll
    static void start() throws Exception {
        adminUrl = System.getenv("RIPV_PG_URL");
        admin = new Properties();
        admin.setProperty("user", System.getenv().getOrDefault("RIPV_PG_USER", "postgres"));
        admin.setProperty("password", System.getenv().getOrDefault("RIPV_PG_PASSWORD", ""));
        String suffix = Long.toString(ThreadLocalRandom.current().nextLong(1L << 40), 36).toLowerCase(Locale.ROOT);
        dbName = "ripv_slocum_" + suffix;
        readerRole = "ripv_slocum_reader_" + suffix;
        try (Connection c = DriverManager.getConnection(adminUrl, admin); Statement st = c.createStatement()) {
            st.execute("CREATE DATABASE " + dbName);
            st.execute("CREATE ROLE " + readerRole + " LOGIN PASSWORD 'readerSecret'");
        }
        dbUrl = adminUrl.replaceFirst("/[^/?]*(\\?|$)", "/" + dbName + "$1");
        try (Connection c = DriverManager.getConnection(dbUrl, admin); Statement st = c.createStatement()) {
            st.execute("GRANT CONNECT ON DATABASE " + dbName + " TO " + readerRole);
            st.execute("GRANT USAGE ON SCHEMA public TO " + readerRole);
            st.execute("ALTER ROLE " + readerRole + " SET default_transaction_read_only = on");
        }
        service = new DatabaseServer("pg", List.of(new DatabaseTarget("TTY1", "org.postgresql.Driver", dbUrl,
                admin.getProperty("user"), admin.getProperty("password"), readerRole, "readerSecret", null)),
                QueryLimits.defaults());
        service.start();
        sql = new ServiceHarness(service);
    }

    @AfterAll
    static void stop() throws Exception {
        if (service != null) {
            service.stop();
        }
        if (dbName != null) {
            try (Connection c = DriverManager.getConnection(adminUrl, admin); Statement st = c.createStatement()) {
                st.execute("DROP DATABASE IF EXISTS " + dbName + " WITH (FORCE)");
                st.execute("DROP ROLE IF EXISTS " + readerRole);
            }
        }
    }

    @Test
    @Order(1)
    void theSharedFilesGoInAndTheViewsAnswerOnPostgres() throws Exception {
        byte[] cpFile = DbaFiles.read(DbaFiles.shared("cp_388_2016_012_0_0.mrg"));
        byte[] unitFile = DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg"));
        DbaFiles.Count cp = DbaFiles.count(cpFile);
        DbaFiles.Count unit = DbaFiles.count(unitFile);
        OutgoingServiceMessage r = ingest(List.of(DatabaseHandler.OPERATORS_ROLE), new Attachment("cp.mrg", cpFile),
                new Attachment("unit_363_2013_245_6_6.mrg", unitFile));
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().replyText()).isEqualTo("cp_388-2016-012-0-0: 23 rows, 52 sensors, " + cp.values()
                + " values, 2 positions (" + cp.noFix() + " no-fix values left out)\n"
                + "unit_363-2013-245-6-6: 657 rows, 29 sensors, " + unit.values() + " values, " + unit.positionRows()
                + " positions" + (unit.noFix() > 0 ? " (" + unit.noFix() + " no-fix values left out)" : ""));
        assertThat(count("SELECT COUNT(*) FROM reading")).isEqualTo(cp.values() + unit.values());

        // positions: decimal degrees, UTC, gps or dead-reckoned, one row per fix
        assertThat(count("SELECT COUNT(*) FROM positions WHERE vehicle = 'unit_363'")).isEqualTo(unit.positionRows());
        assertThat(count("SELECT COUNT(*) FROM positions WHERE vehicle = 'unit_363' AND source = 'gps'")).isPositive();
        TableResult pos = table("SELECT lat, lon, source, time_utc FROM positions WHERE vehicle = 'cp_388' ORDER BY time_utc");
        assertThat(pos.rows()).hasSize(2);
        assertThat(pos.rows().get(0)).containsExactly("39.84772", "-70.772256667", "dead-reckoned", "2016-01-13 17:20:11.24094");
        assertThat(count("SELECT COUNT(*) FROM positions WHERE vehicle = 'unit_363'"
                + " AND (lat < 50 OR lat > 50.5 OR lon > -144 OR lon < -145)")).isZero();

        // what vis:track sends (org.ripv.server.dataloop.PlotRequests): the newest fix, then the points up to it
        TableResult newest = table("SELECT time_utc, source FROM positions WHERE vehicle = 'unit_363'"
                + " ORDER BY time_utc DESC FETCH FIRST 1 ROWS ONLY");
        assertThat(newest.rows()).hasSize(1);
        TableResult points = table("SELECT lon, lat FROM positions WHERE vehicle = 'unit_363'"
                + " AND time_utc >= CAST('2013-09-01 00:00:00' AS TIMESTAMP)"
                + " AND time_utc <= CAST('" + newest.rows().get(0)[0] + "' AS TIMESTAMP) ORDER BY time_utc DESC");
        assertThat(points.rows()).hasSize((int) unit.positionRows());
        assertThat(points.types()).containsExactly("float8", "float8");

        // latest: each sensor's last value; m_depth's is the file's last m_depth
        assertThat(count("SELECT COUNT(*) FROM latest WHERE vehicle = 'unit_363'")).isEqualTo(29);
        String[] lines = new String(unitFile, StandardCharsets.US_ASCII).split("\n");
        int depthCol = List.of(lines[14].trim().split(" ")).indexOf("m_depth");
        String lastDepth = null;
        long depthValues = 0;
        for (int i = 17; i < lines.length; i++) {
            String cell = lines[i].trim().split(" ")[depthCol];
            if (!cell.equals("NaN")) {
                lastDepth = cell;
                depthValues++;
            }
        }
        TableResult latestDepth = table("SELECT value FROM latest WHERE vehicle = 'unit_363' AND sensor = 'm_depth'");
        assertThat(Double.parseDouble(latestDepth.rows().get(0)[0])).isEqualTo(Double.parseDouble(lastDepth));
        // depths and dives
        assertThat(count("SELECT COUNT(*) FROM depths WHERE vehicle = 'unit_363' AND source = 'm_depth'")).isEqualTo(depthValues);
        assertThat(count("SELECT COUNT(*) FROM dives WHERE vehicle = 'unit_363' AND max_depth > 900")).isEqualTo(1);
        assertThat(count("SELECT depth_values FROM dives WHERE vehicle = 'unit_363'")).isEqualTo(depthValues);
        // what vis:depth and vis:profile send
        assertThat(table("SELECT time_utc, depth FROM depths WHERE vehicle = 'unit_363' AND source = 'm_depth'"
                + " ORDER BY time_utc DESC").rows()).hasSize((int) depthValues);
        assertThat(table("SELECT r.value, d.depth FROM sensor_def s JOIN reading r ON r.sensor_id = s.sensor_id"
                + " JOIN depths d ON d.file_id = r.file_id AND d.row_no = r.row_no WHERE s.name = 'm_pitch'"
                + " AND r.vehicle = 'unit_363' ORDER BY r.t DESC").rows()).isNotEmpty();

        // the read-only role reads the views and may not ingest
        OutgoingServiceMessage asReader = sql.send("TTY1", "SELECT COUNT(*) FROM positions", "bob",
                List.of(DatabaseHandler.READER_ROLE));
        assertThat(asReader.status()).as(asReader.footer().replyText()).isEqualTo(Status.OK);
        assertThat(((TableResult) asReader.footer().result()).rows().get(0)[0])
                .isEqualTo(Long.toString(unit.positionRows() + 2));
        assertThat(ingest(List.of(DatabaseHandler.READER_ROLE), new Attachment("x.mrg", cpFile)).footer().errorCode())
                .isEqualTo(ErrorCode.FORBIDDEN);
    }

    @Test
    @Order(2)
    void refusedFilesStoreNothingAndAFileIsStoredOnce() throws Exception {
        long files = count("SELECT COUNT(*) FROM data_file");
        long readings = count("SELECT COUNT(*) FROM reading");
        long fixes = count("SELECT COUNT(*) FROM position_fix");
        OutgoingServiceMessage r = ingest(List.of(DatabaseHandler.OPERATORS_ROLE),
                new Attachment("short_header.mrg", DbaFiles.read(DbaFiles.shared("short_header.mrg"))));
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().replyText()).isEqualTo("short_header.mrg: refused, nothing stored: line 11: the file ends"
                + " in the header after 10 of 14 tag lines");
        // a bad row after several batches went to the database: all rolled back
        String good = new String(DbaFiles.generate("pgbad", 30, 3000, 4), StandardCharsets.US_ASCII);
        int cut = good.lastIndexOf(" \n", good.length() - 3);
        r = ingest(List.of(DatabaseHandler.OPERATORS_ROLE), new Attachment("bad.mrg",
                (good.substring(0, cut) + " 7 \n").getBytes(StandardCharsets.US_ASCII)));
        assertThat(r.footer().replyText()).contains("line 3016: the row has more values than the 30 sensors");
        assertThat(count("SELECT COUNT(*) FROM data_file")).isEqualTo(files);
        assertThat(count("SELECT COUNT(*) FROM reading")).isEqualTo(readings);
        assertThat(count("SELECT COUNT(*) FROM position_fix")).isEqualTo(fixes);

        byte[] twice = DbaFiles.generate("pgtwice", 12, 30, 9);
        r = ingest(List.of(DatabaseHandler.OPERATORS_ROLE), new Attachment("a.mrg", twice), new Attachment("b.mrg", twice));
        assertThat(r.footer().replyText()).contains("pgtwice-2024-100-1-0: 30 rows, 12 sensors")
                .contains("pgtwice-2024-100-1-0: stored already");
        assertThat(count("SELECT COUNT(*) FROM data_file WHERE vehicle = 'pgtwice'")).isEqualTo(1);
        assertThat(count("SELECT COUNT(*) FROM positions WHERE vehicle = 'pgtwice'"))
                .isEqualTo(DbaFiles.count(twice).positionRows());
    }

    @Test
    @Order(3)
    void theViewsPlansUseTheIndexes() throws Exception {
        for (int i = 0; i < 5; i++) {
            OutgoingServiceMessage r = ingest(List.of(DatabaseHandler.OPERATORS_ROLE),
                    new Attachment("plan" + i + ".mrg", DbaFiles.generate("plan" + i, 40, 2000, i)));
            assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        }
        ingest(List.of(DatabaseHandler.OPERATORS_ROLE), new Attachment("unit.mrg", // stored already when run after the first test
                DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg"))));
        Map<String, String> queries = new LinkedHashMap<>();
        queries.put("positions", "SELECT * FROM positions WHERE vehicle = 'unit_363'");
        queries.put("track: newest fix", "SELECT time_utc, source FROM positions WHERE vehicle = 'unit_363'"
                + " ORDER BY time_utc DESC FETCH FIRST 1 ROWS ONLY");
        queries.put("track: points", "SELECT lon, lat FROM positions WHERE vehicle = 'unit_363'"
                + " AND time_utc <= CAST('2013-09-05 13:45:50.906' AS TIMESTAMP) ORDER BY time_utc DESC");
        queries.put("latest", "SELECT * FROM latest WHERE vehicle = 'unit_363'");
        queries.put("depth", "SELECT time_utc, depth FROM depths WHERE vehicle = 'unit_363' AND source = 'm_depth'"
                + " ORDER BY time_utc DESC");
        queries.put("dives", "SELECT * FROM dives WHERE vehicle = 'unit_363'");
        StringBuilder all = new StringBuilder();
        Map<String, String> plans = new LinkedHashMap<>();
        try (Connection c = DriverManager.getConnection(dbUrl, admin); Statement st = c.createStatement()) {
            st.execute("VACUUM ANALYZE"); // statistics, and the visibility map an index-only scan needs
            for (Map.Entry<String, String> q : queries.entrySet()) {
                StringBuilder plan = new StringBuilder();
                try (ResultSet rs = st.executeQuery("EXPLAIN (ANALYZE, COSTS OFF, TIMING OFF, SUMMARY OFF) " + q.getValue())) {
                    while (rs.next()) {
                        plan.append(rs.getString(1)).append('\n');
                    }
                }
                plans.put(q.getKey(), plan.toString());
                all.append("== ").append(q.getKey()).append(": ").append(q.getValue()).append('\n').append(plan).append('\n');
            }
            assertThat(count("SELECT COUNT(*) FROM reading")).isGreaterThan(100_000);
        }
        String out = System.getProperty("ripv.plans.pg");
        if (out != null) {
            Files.writeString(Path.of(out), all);
        }
        assertThat(plans.get("track: points")).contains("Index Only Scan using position_fix_vehicle_t on position_fix")
                .doesNotContain("Sort").doesNotContain("reading");
        assertThat(plans.get("track: newest fix")).contains("position_fix_vehicle_t").doesNotContain("Seq Scan");
        assertThat(plans.get("positions")).contains("position_fix_vehicle_t").doesNotContain("Seq Scan");
        assertThat(plans.get("depth")).contains("reading_sensor_vehicle_t").doesNotContain("Seq Scan on reading");
        assertThat(plans.get("latest")).doesNotContain("reading");
        assertThat(plans.get("dives")).doesNotContain("reading");
    }

    private static OutgoingServiceMessage ingest(List<String> roles, Attachment... files) throws InterruptedException {
        StringBuilder cmd = new StringBuilder("ingest");
        for (Attachment a : files) {
            cmd.append(' ').append(a.name());
        }
        long id = IDS.incrementAndGet();
        BlockingQueue<OutgoingServiceMessage> mine = new LinkedBlockingQueue<>();
        service.replyTo(mine::add);
        try {
            service.accept(new IncomingServiceMessage(new Header(id, new IdBadge("123456", "alice"), roles,
                    service.name().toString(), service.name().mailbox("TTY1").toString(), cmd.toString(), Priority.NORMAL,
                    Attachment.bundle(List.of(files)))));
            while (true) {
                OutgoingServiceMessage r = mine.poll(120, TimeUnit.SECONDS);
                assertThat(r).as("a reply to " + cmd).isNotNull();
                if (r.header().messageId() == id && r.status().isFinal()) {
                    return r;
                }
            }
        } finally {
            sql = new ServiceHarness(service); // takes the replies back
        }
    }

    private static long count(String query) throws InterruptedException {
        return Long.parseLong(table(query).rows().get(0)[0]);
    }

    private static TableResult table(String query) throws InterruptedException {
        OutgoingServiceMessage r = sql.send("TTY1", query);
        assertThat(r.status()).as(query + ": " + r.footer().replyText()).isEqualTo(Status.OK);
        return (TableResult) r.footer().result();
    }
}
