package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.SQLIntegrityConstraintViolationException;
import java.sql.Statement;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The scripts of {@code sql/} load into Derby embedded (on disk and in memory) and over the
 * Derby network server, and their constraints hold. PostgreSQL is in {@link PostgresTest}.
 */
@ResourceLock("derby.network") // one Derby network server at a time in this JVM
class SchemaTest {
    private static DerbyNetwork network;

    @BeforeAll
    static void startNetworkServer() throws Exception {
        network = DerbyNetwork.start();
    }

    @AfterAll
    static void stopNetworkServer() throws Exception {
        if (network != null) {
            network.close();
        }
    }

    @Test
    void scriptsSplitIntoStatements() throws Exception {
        assertThat(SqlScript.split(SqlScript.resource("vehicleDB.sql"))).hasSize(8);
        assertThat(SqlScript.split("SELECT ';' FROM t; -- a; comment\n/* x; */ SELECT 2;")).containsExactly(
                "SELECT ';' FROM t", "SELECT 2");
        assertThat(SqlScript.split("INSERT INTO v VALUES (1, 'St. David''s; x')")).containsExactly(
                "INSERT INTO v VALUES (1, 'St. David''s; x')");
        assertThatThrownBy(() -> SqlScript.split("SELECT 'open")).hasMessageContaining("unterminated string");
    }

    @Test
    void loadsIntoEmbeddedDerbyOnDisk(@TempDir Path dir) throws Exception {
        String url = "jdbc:derby:" + dir.resolve("db");
        try (Connection c = DriverManager.getConnection(url + ";create=true")) {
            loadAndCheck(c);
        }
        shutdown(url);
    }

    @Test
    void loadsIntoDerbyInMemory() throws Exception {
        String url = "jdbc:derby:memory:schemaTest";
        try (Connection c = DriverManager.getConnection(url + ";create=true")) {
            loadAndCheck(c);
        }
        drop(url);
    }

    @Test
    void gliderVariantLoadsToo() throws Exception {
        String url = "jdbc:derby:memory:gliderTest";
        try (Connection c = DriverManager.getConnection(url + ";create=true"); Statement st = c.createStatement()) {
            SqlScript.run(c, SqlScript.resource("gliderDB.sql"), "gliderDB.sql");
            st.execute("INSERT INTO glider (glider_id, name) VALUES (7, 'we07')");
            st.execute("INSERT INTO mission (mission_id, glider_id, name) VALUES (1, 7, 'trial')");
            assertThatThrownBy(() -> st.execute("INSERT INTO mission (mission_id, glider_id, name) VALUES (2, 8, 'x')"))
                    .isInstanceOf(SQLIntegrityConstraintViolationException.class);
            assertThatThrownBy(() -> st.execute("SELECT * FROM vehicle")).hasMessageContaining("VEHICLE");
        }
        drop(url);
    }

    @Test
    void loadsOverTheDerbyNetworkServer() throws Exception {
        String url = network.url("memory:networkSchemaTest");
        try (Connection c = DriverManager.getConnection(url + ";create=true")) {
            loadAndCheck(c);
        }
    }

    /** Loads both scripts and checks the data and constraints; shared with {@link PostgresTest}. */
    static void loadAndCheck(Connection c) throws Exception {
        SqlScript.run(c, SqlScript.resource("vehicleDB.sql"), "vehicleDB.sql");
        SqlScript.run(c, SqlScript.resource("sample-data.sql"), "sample-data.sql");
        try (Statement st = c.createStatement()) {
            assertThat(count(st, "SELECT COUNT(*) FROM vehicle")).isEqualTo(4);
            assertThat(count(st, "SELECT COUNT(*) FROM mission")).isEqualTo(4);
            assertThat(count(st, "SELECT COUNT(*) FROM mission WHERE endt IS NULL")).isEqualTo(3);
            assertThat(count(st, "SELECT COUNT(*) FROM sensor")).isEqualTo(3);
            assertThat(count(st, "SELECT COUNT(*) FROM sensor_data")).isGreaterThan(5_000);
            assertThat(count(st, "SELECT COUNT(*) FROM vehicle_data")).isGreaterThan(1_000);
            // every unfinished mission has exactly one open leg
            assertThat(count(st, "SELECT COUNT(*) FROM leg l JOIN mission m ON l.mission_id = m.mission_id"
                    + " WHERE m.endt IS NULL AND l.endt IS NULL")).isEqualTo(3);
            // readings are plausible for Bermuda: temperatures of 15-22 degC, pressures of 0-210 dbar
            try (ResultSet rs = st.executeQuery("SELECT MIN(value), MAX(value) FROM sensor_data WHERE sensor_id = 1")) {
                rs.next();
                assertThat(rs.getDouble(1)).isBetween(15.0, 22.0);
                assertThat(rs.getDouble(2)).isBetween(15.0, 22.0);
            }
            try (ResultSet rs = st.executeQuery("SELECT MIN(value), MAX(value) FROM sensor_data WHERE sensor_id = 3")) {
                rs.next();
                assertThat(rs.getDouble(1)).isBetween(0.0, 5.0);
                assertThat(rs.getDouble(2)).isBetween(140.0, 210.0);
            }

            // a mission of an unknown vehicle is refused by the foreign key
            assertThatThrownBy(() -> st.execute(
                    "INSERT INTO mission (mission_id, vehicle_id, name) VALUES (99, 42, 'ghost')"))
                    .isInstanceOf(SQLException.class)
                    .satisfies(e -> assertThat(((SQLException) e).getSQLState()).isEqualTo("23503"));
            // a sensor reading without a value is refused by NOT NULL
            assertThatThrownBy(() -> st.execute("INSERT INTO sensor_data (leg_id, sensor_id, t, value, raw_value)"
                    + " VALUES (1, 1, CAST('2002-04-02 13:00:00' AS TIMESTAMP), NULL, 3000)"))
                    .isInstanceOf(SQLException.class)
                    .satisfies(e -> assertThat(((SQLException) e).getSQLState()).isIn("23502", "23000"));
            // a duplicate primary key is refused
            assertThatThrownBy(() -> st.execute("INSERT INTO vehicle (vehicle_id, name) VALUES (1, 'twin')"))
                    .isInstanceOf(SQLException.class)
                    .satisfies(e -> assertThat(((SQLException) e).getSQLState()).isIn("23505"));
            // a vehicle without a name is refused
            assertThatThrownBy(() -> st.execute("INSERT INTO vehicle (vehicle_id) VALUES (5)"))
                    .isInstanceOf(SQLException.class);
        }
    }

    static long count(Statement st, String sql) throws SQLException {
        try (ResultSet rs = st.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }

    static void shutdown(String url) {
        try {
            DriverManager.getConnection(url + ";shutdown=true").close();
        } catch (SQLException expected) {
            assertThat(expected.getSQLState()).isEqualTo("08006");
        }
    }

    static void drop(String url) {
        try {
            DriverManager.getConnection(url + ";drop=true").close();
        } catch (SQLException expected) {
            assertThat(expected.getSQLState()).isIn("08006", "08004");
        }
    }
}
