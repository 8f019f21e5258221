package org.ripv.server.store;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.ThreadLocalRandom;
import org.junit.jupiter.api.Assumptions;

/**
 * A PostgreSQL schema of a test's own in the database RIPV_PG_URL names (RIPV_PG_USER,
 * RIPV_PG_PASSWORD), dropped on close. Without RIPV_PG_URL the test is skipped with the reason,
 * or fails when RIPV_REQUIRE_TOOLS=1 (CI).
 */
public final class PgSchema implements AutoCloseable {
    private final String adminUrl;
    private final Properties admin;
    public final String name;

    private PgSchema(String adminUrl, Properties admin, String name) {
        this.adminUrl = adminUrl;
        this.admin = admin;
        this.name = name;
    }

    /** Whether a PostgreSQL server is given; skips (or, in CI, fails) the test when not. */
    public static void assumeAvailable() {
        String url = System.getenv("RIPV_PG_URL");
        if (url == null || url.isBlank()) {
            if ("1".equals(System.getenv("RIPV_REQUIRE_TOOLS"))) {
                throw new AssertionError("RIPV_REQUIRE_TOOLS=1 but no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER)");
            }
            Assumptions.abort("no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER, RIPV_PG_PASSWORD) to run this test");
        }
    }

    public static PgSchema create() throws SQLException {
        assumeAvailable();
        String url = System.getenv("RIPV_PG_URL");
        Properties admin = new Properties();
        admin.setProperty("user", System.getenv().getOrDefault("RIPV_PG_USER", "postgres"));
        admin.setProperty("password", System.getenv().getOrDefault("RIPV_PG_PASSWORD", ""));
        String name = "ripv_store_" + Long.toString(ThreadLocalRandom.current().nextLong(1L << 40), 36).toLowerCase(Locale.ROOT);
        try (Connection c = DriverManager.getConnection(url, admin); Statement st = c.createStatement()) {
            st.execute("CREATE SCHEMA " + name);
        }
        return new PgSchema(url, admin, name);
    }

    /** The test's schema as the store sees it: the URL with currentSchema, and the credentials. */
    public StoreLocation location() {
        String sep = adminUrl.contains("?") ? "&" : "?";
        return new StoreLocation(adminUrl + sep + "currentSchema=" + name, admin.getProperty("user"),
                admin.getProperty("password").isEmpty() ? null : admin.getProperty("password"));
    }

    /** Runs SQL in the schema (for checks behind the store's back). */
    public Connection connect() throws SQLException {
        return DriverManager.getConnection(location().jdbcUrl(), admin);
    }

    @Override
    public void close() throws SQLException {
        try (Connection c = DriverManager.getConnection(adminUrl, admin); Statement st = c.createStatement()) {
            st.execute("DROP SCHEMA IF EXISTS " + name + " CASCADE");
        }
    }
}
