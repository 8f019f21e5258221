package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.ingest.DbaFiles;
import org.ripv.services.ingest.DbaIngest;

/**
 * A database made before POSITION_FIX existed (its positions view joined READING with itself) is
 * brought up to date on the first {@code ingest}: the same positions as the old view gave, then
 * new files' fixes on top, and the read-only user sees the new table and view.
 */
class SlocumUpgradeTest {
    /** The positions view of the first slocumDB.sql. */
    private static final String OLD_VIEW = """
            CREATE VIEW positions (vehicle, time_utc, lat, lon, source, file_id) AS
            SELECT la.vehicle, la.t, la.value, lo.value, CAST('gps' AS VARCHAR(16)), la.file_id
              FROM sensor_def sa
              JOIN reading la ON la.sensor_id = sa.sensor_id
              JOIN sensor_def so ON so.name = 'm_gps_lon'
              JOIN reading lo ON lo.file_id = la.file_id AND lo.row_no = la.row_no AND lo.sensor_id = so.sensor_id
             WHERE sa.name = 'm_gps_lat' AND la.value BETWEEN -90 AND 90 AND lo.value BETWEEN -180 AND 180
            UNION ALL
            SELECT la.vehicle, la.t, la.value, lo.value, CAST('dead-reckoned' AS VARCHAR(16)), la.file_id
              FROM sensor_def sa
              JOIN reading la ON la.sensor_id = sa.sensor_id
              JOIN sensor_def so ON so.name = 'm_lon'
              JOIN reading lo ON lo.file_id = la.file_id AND lo.row_no = la.row_no AND lo.sensor_id = so.sensor_id
             WHERE sa.name = 'm_lat' AND la.value BETWEEN -90 AND 90 AND lo.value BETWEEN -180 AND 180""";
    private static final String ALL = "SELECT vehicle, time_utc, lat, lon, source, file_id FROM positions"
            + " ORDER BY vehicle, time_utc, source";

    @TempDir
    Path data;

    @Test
    void anOlderDatabaseGetsPositionFixesWithTheSamePositions() throws Exception {
        DatabaseTarget target = EmbeddedDatabase.prepare(data, "TTY1");
        try (Connection c = DriverManager.getConnection(target.url(), target.user(), target.password())) {
            SqlScript.run(c, SqlScript.resource("slocumDB.sql"), "slocumDB.sql");
            DbaIngest ingest = new DbaIngest(c);
            ingest.ingest("cp.mrg", DbaFiles.read(DbaFiles.shared("cp_388_2016_012_0_0.mrg")), "test");
            ingest.ingest("unit.mrg", DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg")), "test");
            List<String> today = rows(c, ALL);
            // make it the older database: no POSITION_FIX, the self-join view
            try (Statement st = c.createStatement()) {
                st.execute("DROP VIEW positions");
                st.execute("DROP TABLE position_fix");
                st.execute(OLD_VIEW);
            }
            List<String> before = rows(c, ALL);
            assertThat(before).hasSize((int) (DbaFiles.count(DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg")))
                    .positionRows() + 2)).isEqualTo(today);

            IngestCommand command = new IngestCommand(target);
            command.ensureSchema(c);
            assertThat(rows(c, "SELECT COUNT(*) FROM position_fix")).containsExactly(Integer.toString(before.size()));
            assertThat(rows(c, ALL)).isEqualTo(before);
            // and the next file's fixes go in beside them
            byte[] next = DbaFiles.generate("later", 12, 100, 5);
            new DbaIngest(c).ingest("later.mrg", next, "test");
            assertThat(rows(c, "SELECT COUNT(*) FROM positions WHERE vehicle = 'later'"))
                    .containsExactly(Long.toString(DbaFiles.count(next).positionRows()));
            command.ensureSchema(c); // once is enough: nothing happens again
            assertThat(rows(c, "SELECT COUNT(*) FROM position_fix WHERE vehicle <> 'later'"))
                    .containsExactly(Integer.toString(before.size()));
        }
        // the read-only user may read the new table and the new view (the old view's grant went with it)
        try (Connection r = DriverManager.getConnection(target.url(), target.readerUser(), target.readerPassword());
             Statement st = r.createStatement()) {
            st.execute("SET SCHEMA " + target.schema());
            assertThat(rows(r, "SELECT COUNT(*) FROM positions WHERE vehicle = 'later'")).hasSize(1);
            assertThat(rows(r, "SELECT COUNT(*) FROM position_fix")).hasSize(1);
        }
    }

    /** The dives view before CYCLE: one row per file. */
    private static final String OLD_DIVES = "CREATE VIEW dives (vehicle, file_id, name, start_utc, end_utc, max_depth,"
            + " min_depth, depth_values) AS SELECT vehicle, file_id, dba_filename, first_time, last_time, max_depth,"
            + " min_depth, depth_count FROM data_file WHERE depth_count > 0";

    @Test
    void anOlderDatabaseGetsCyclesAndAFileAgainIsMergedNotStoredTwice() throws Exception {
        DatabaseTarget target = EmbeddedDatabase.prepare(data, "TTY1");
        byte[] cp = DbaFiles.read(DbaFiles.shared("cp_388_2016_012_0_0.mrg"));
        try (Connection c = DriverManager.getConnection(target.url(), target.user(), target.password())) {
            SqlScript.run(c, SqlScript.resource("slocumDB.sql"), "slocumDB.sql");
            new DbaIngest(c).ingest("cp.mrg", cp, "test");
            try (Statement st = c.createStatement()) { // the older database: no CYCLE, a dive per file
                st.execute("DROP VIEW dives");
                st.execute("DROP TABLE cycle");
                st.execute(OLD_DIVES);
            }
            List<String> readings = rows(c, "SELECT COUNT(*) FROM reading");
            new IngestCommand(target).ensureSchema(c);
            assertThat(rows(c, "SELECT COUNT(*) FROM cycle")).containsExactly("23");
            // the same rows in other bytes (a line end more): every cycle found, nothing stored twice
            byte[] again = java.util.Arrays.copyOf(cp, cp.length + 1);
            again[cp.length] = '\n';
            DbaIngest.Outcome o = new DbaIngest(c).ingest("cp-again.mrg", again, "test");
            assertThat(o.duplicate()).isFalse();
            assertThat(o.merged()).isEqualTo(23);
            assertThat(rows(c, "SELECT COUNT(*) FROM reading")).isEqualTo(readings);
            assertThat(rows(c, "SELECT COUNT(*) FROM dives")).containsExactly("1");
        }
    }

    private static List<String> rows(Connection c, String sql) throws Exception {
        List<String> out = new ArrayList<>();
        try (Statement st = c.createStatement(); ResultSet rs = st.executeQuery(sql)) {
            int n = rs.getMetaData().getColumnCount();
            while (rs.next()) {
                StringBuilder b = new StringBuilder();
                for (int i = 1; i <= n; i++) {
                    b.append(i > 1 ? "|" : "").append(rs.getString(i));
                }
                out.add(b.toString());
            }
        }
        return out;
    }
}
