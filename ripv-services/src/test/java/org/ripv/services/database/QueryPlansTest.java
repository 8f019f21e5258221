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
 * through the (sensor_id, vehicle, t) index and the primary key, never a full scan of READING.
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
            }
            Map<String, String> queries = new LinkedHashMap<>();
            queries.put("positions", "SELECT time_utc, lat, lon, source FROM positions WHERE vehicle = 'unit_363' ORDER BY time_utc DESC");
            // what vis:track sends (org.ripv.server.dataloop.PlotRequests.trackSql): the vehicle inside each branch
            queries.put("track", "SELECT time_utc, lat, lon, source FROM (SELECT la.t AS time_utc, la.value AS lat, lo.value AS lon,"
                    + " CAST('gps' AS VARCHAR(16)) AS source FROM sensor_def sa JOIN reading la ON la.sensor_id = sa.sensor_id"
                    + " AND la.vehicle = 'unit_363' JOIN sensor_def so ON so.name = 'm_gps_lon' JOIN reading lo ON"
                    + " lo.file_id = la.file_id AND lo.row_no = la.row_no AND lo.sensor_id = so.sensor_id"
                    + " WHERE sa.name = 'm_gps_lat' AND la.value BETWEEN -90 AND 90 AND lo.value BETWEEN -180 AND 180"
                    + " UNION ALL SELECT la.t AS time_utc, la.value AS lat, lo.value AS lon,"
                    + " CAST('dead-reckoned' AS VARCHAR(16)) AS source FROM sensor_def sa JOIN reading la ON la.sensor_id = sa.sensor_id"
                    + " AND la.vehicle = 'unit_363' JOIN sensor_def so ON so.name = 'm_lon' JOIN reading lo ON"
                    + " lo.file_id = la.file_id AND lo.row_no = la.row_no AND lo.sensor_id = so.sensor_id"
                    + " WHERE sa.name = 'm_lat' AND la.value BETWEEN -90 AND 90 AND lo.value BETWEEN -180 AND 180"
                    + ") p ORDER BY time_utc DESC");
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
            assertThat(plans.get("track")).contains("READING_SENSOR_VEHICLE_T").contains("READING_PK")
                    .doesNotContain("Table Scan ResultSet for READING");
            assertThat(plans.get("positions")).contains("READING_SENSOR_VEHICLE_T").doesNotContain("Table Scan ResultSet for READING");
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
