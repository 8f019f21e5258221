package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.Statement;
import java.util.List;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.ThreadLocalRandom;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfEnvironmentVariable;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/**
 * The schema, the sample data and the DatabaseServer on PostgreSQL. Runs when a server is
 * given by the environment, and is skipped (with the reason) otherwise:
 * <pre>
 * RIPV_PG_URL=jdbc:postgresql://127.0.0.1:5432/postgres   a database to connect to first
 * RIPV_PG_USER=postgres  RIPV_PG_PASSWORD=...             a user that may create databases and roles
 * </pre>
 * The test creates a database and a read-only role of its own and drops both afterwards.
 */
@EnabledIfEnvironmentVariable(named = "RIPV_PG_URL", matches = ".+",
        disabledReason = "no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER, RIPV_PG_PASSWORD) to run this test")
class PostgresTest {
    private static String adminUrl;
    private static Properties admin;
    private static String dbName;
    private static String readerRole;
    private static String dbUrl;

    @BeforeAll
    static void createDatabase() throws Exception {
        adminUrl = System.getenv("RIPV_PG_URL");
        admin = new Properties();
        admin.setProperty("user", System.getenv().getOrDefault("RIPV_PG_USER", "postgres"));
        admin.setProperty("password", System.getenv().getOrDefault("RIPV_PG_PASSWORD", ""));
        String suffix = Long.toString(ThreadLocalRandom.current().nextLong(1L << 40), 36).toLowerCase(Locale.ROOT);
        dbName = "ripv_test_" + suffix;
        readerRole = "ripv_reader_" + suffix;
        try (Connection c = DriverManager.getConnection(adminUrl, admin); Statement st = c.createStatement()) {
            st.execute("CREATE DATABASE " + dbName);
            st.execute("CREATE ROLE " + readerRole + " LOGIN PASSWORD 'readerSecret'");
        }
        dbUrl = adminUrl.replaceFirst("/[^/?]*(\\?|$)", "/" + dbName + "$1");
    }

    @AfterAll
    static void dropDatabase() throws Exception {
        if (dbName == null) {
            return;
        }
        try (Connection c = DriverManager.getConnection(adminUrl, admin); Statement st = c.createStatement()) {
            st.execute("DROP DATABASE IF EXISTS " + dbName + " WITH (FORCE)");
            st.execute("DROP ROLE IF EXISTS " + readerRole);
        }
    }

    @Test
    void schemaDataAndServiceWorkOnPostgres() throws Exception {
        try (Connection c = DriverManager.getConnection(dbUrl, admin)) {
            SchemaTest.loadAndCheck(c);
            try (Statement st = c.createStatement()) {
                // the read-only user of docs/database.md
                st.execute("GRANT CONNECT ON DATABASE " + dbName + " TO " + readerRole);
                st.execute("GRANT USAGE ON SCHEMA public TO " + readerRole);
                st.execute("GRANT SELECT ON ALL TABLES IN SCHEMA public TO " + readerRole);
                st.execute("REVOKE CREATE ON SCHEMA public FROM PUBLIC");
                st.execute("ALTER ROLE " + readerRole + " SET default_transaction_read_only = on");
            }
        }
        DatabaseServer service = new DatabaseServer("pg", List.of(new DatabaseTarget("TTY1", "org.postgresql.Driver", dbUrl,
                admin.getProperty("user"), admin.getProperty("password"), readerRole, "readerSecret", null)),
                new QueryLimits(100, 2, QueryLimits.DEFAULT_MAX_RESULT_CHARS));
        service.start();
        try {
            ServiceHarness client = new ServiceHarness(service);
            OutgoingServiceMessage r = client.send("TTY1", "SELECT * FROM mission ORDER BY mission_id");
            TableResult t = (TableResult) r.footer().result();
            assertThat(t.columns()).containsExactly("mission_id", "vehicle_id", "name", "description", "startt", "endt");
            assertThat(t.types()).containsExactly("int4", "int4", "varchar", "varchar", "timestamp", "timestamp");
            assertThat(t.rows()).hasSize(4);
            assertThat(t.rows().get(1)[5]).isNull();

            t = (TableResult) client.send("TTY1", "SELECT * FROM sensor_data").footer().result();
            assertThat(t.rows()).hasSize(100);
            assertThat(t.truncated()).isTrue();

            r = client.send("TTY1", "SELEC 1");
            assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.DATABASE_ERROR);
            assertThat(r.footer().replyText()).contains("SQLState 42601");

            r = client.send("TTY1", "SELECT COUNT(*) FROM sensor_data a, sensor_data b, sensor_data c");
            assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.TIMEOUT);

            List<String> reader = List.of(DatabaseHandler.READER_ROLE);
            t = (TableResult) client.send("TTY1", "SELECT COUNT(*) FROM vehicle", "bob", reader).footer().result();
            assertThat(t.rows().get(0)[0]).isEqualTo("4");
            for (String write : List.of("DELETE FROM sensor_data", "CREATE TABLE mine (x INTEGER)")) {
                r = client.send("TTY1", write, "bob", reader);
                assertThat(r.footer().errorCode()).as(write + ": " + r.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);
            }
            assertThat(client.send("TTY1", "SELECT COUNT(*) FROM sensor_data").status()).isEqualTo(Status.OK);
        } finally {
            service.stop();
        }
    }
}
