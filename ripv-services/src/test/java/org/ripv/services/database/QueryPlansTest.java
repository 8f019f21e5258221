package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.CallableStatement;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.LinkedHashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.ripv.services.ingest.DbaFiles;
import org.ripv.services.ingest.DbaIngest;

/**
 * The views' query plans on Derby (its runtime statistics): the pilot's queries reach READING
 * through the (sensor_id, vehicle, t) index, never a full scan of READING; a track is one range of
 * POSITION_FIX's covering index, newest first, without a sort.
 * With {@code -Dripv.plans=FILE} the plans are written out for docs/database.md.
 */
class QueryPlansTest {
    @Test
    void theViewsUseTheIndexes() throws Exception {
        try (Connection c = DriverManager.getConnection("jdbc:derby:memory:plans;create=true")) {
            SqlScript.run(c, SqlScript.resource("slocumDB.sql"), "slocumDB.sql");
            DbaIngest ingest = new DbaIngest(c);
            ingest.ingest("cp.mrg", DbaFiles.read(DbaFiles.shared("cp_388_2016_012_0_0.mrg")), "test");
            ingest.ingest("unit.mrg", DbaFiles.read(DbaFiles.shared("unit_363_2013_245_6_6.mrg")), "test");
            for (int i = 0; i < 5; i++) {
                ingest.ingest("gen" + i + ".mrg", DbaFiles.generate("gen" + i, 40, 2000, i), "test");
            }
            try (Statement st = c.createStatement()) {
                st.execute("CALL SYSCS_UTIL.SYSCS_UPDATE_STATISTICS('APP', 'READING', null)");
                st.execute("CALL SYSCS_UTIL.SYSCS_UPDATE_STATISTICS('APP', 'POSITION_FIX', null)");
            }
            Map<String, String> queries = new LinkedHashMap<>();
            queries.put("positions", "SELECT * FROM positions WHERE vehicle = 'unit_363'");
            // what vis:track sends (org.ripv.server.dataloop.PlotRequests): the newest fix, then the points up to it
            queries.put("track: newest fix", "SELECT time_utc, source FROM positions WHERE vehicle = 'unit_363'"
                    + " ORDER BY time_utc DESC FETCH FIRST 1 ROWS ONLY");
            queries.put("track", "SELECT lon, lat FROM positions WHERE vehicle = 'unit_363'"
                    + " AND time_utc <= CAST('2013-09-05 13:47:21.577' AS TIMESTAMP) ORDER BY time_utc DESC");
            queries.put("track since", "SELECT lon, lat FROM positions WHERE vehicle = 'unit_363'"
                    + " AND time_utc >= CAST('2013-09-05 12:00:00' AS TIMESTAMP)"
                    + " AND time_utc <= CAST('2013-09-05 13:47:21.577' AS TIMESTAMP) ORDER BY time_utc DESC");
            queries.put("latest", "SELECT * FROM latest WHERE vehicle = 'unit_363'");
            queries.put("depth", "SELECT time_utc, depth FROM depths WHERE vehicle = 'unit_363' AND source = 'm_depth'");
            queries.put("dives", "SELECT * FROM dives WHERE vehicle = 'unit_363'");
            StringBuilder all = new StringBuilder();
            Map<String, String> plans = new LinkedHashMap<>();
            for (Map.Entry<String, String> q : queries.entrySet()) {
                String plan = plan(c, q.getValue());
                plans.put(q.getKey(), plan);
                all.append("== ").append(q.getKey()).append(": ").append(q.getValue()).append('\n').append(plan).append('\n');
            }
            String out = System.getProperty("ripv.plans");
            if (out != null) {
                Files.writeString(Path.of(out), all);
            }
            // the track: one range of the covering index, newest first, no sort and no base rows
            assertThat(plans.get("track")).contains("Index Scan ResultSet for POSITION_FIX using index POSITION_FIX_VEHICLE_T")
                    .doesNotContain("Sort ResultSet").doesNotContain("READING").doesNotContain("Index Row to Base Row")
                    .doesNotContain("Table Scan");
            assertThat(plans.get("track: newest fix")).contains("POSITION_FIX_VEHICLE_T").doesNotContain("Sort ResultSet")
                    .doesNotContain("Index Row to Base Row");
            assertThat(plans.get("track since")).contains("POSITION_FIX_VEHICLE_T").doesNotContain("Sort ResultSet")
                    .doesNotContain("Index Row to Base Row")
                    .doesNotContain("Table Scan");
            assertThat(plans.get("positions")).contains("POSITION_FIX_VEHICLE_T").doesNotContain("READING")
                    .doesNotContain("Table Scan").doesNotContain("Index Row to Base Row");
            assertThat(plans.get("latest")).doesNotContain("ResultSet for READING");
            assertThat(plans.get("dives")).doesNotContain("ResultSet for READING");
            assertThat(plans.get("depth")).contains("READING_SENSOR_VEHICLE_T").doesNotContain("Table Scan ResultSet for READING");
        }
    }

    private static String plan(Connection c, String sql) throws Exception {
        try (Statement st = c.createStatement()) {
            st.execute("CALL SYSCS_UTIL.SYSCS_SET_RUNTIMESTATISTICS(1)");
            try (ResultSet rs = st.executeQuery(sql)) {
                while (rs.next()) {
                    // run it to the end: the statistics describe the whole execution
                }
            }
            try (CallableStatement cs = c.prepareCall("VALUES SYSCS_UTIL.SYSCS_GET_RUNTIMESTATISTICS()");
                 ResultSet rs = cs.executeQuery()) {
                rs.next();
                return rs.getString(1);
            } finally {
                st.execute("CALL SYSCS_UTIL.SYSCS_SET_RUNTIMESTATISTICS(0)");
            }
        }
    }
}
