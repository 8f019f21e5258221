package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The batched seed gives the same rows as running the script statement by statement. */
class SeedLoaderTest {
    @Test
    void rowsSplitAtCommasOutsideLiterals() {
        assertThat(SeedLoader.tuples("(1, 'St. David''s, x', NULL), (2,'a)b', -1.5e3)")).containsExactly(
                List.of("1", "'St. David''s, x'", "NULL"), List.of("2", "'a)b'", "-1.5e3"));
        assertThatThrownBy(() -> SeedLoader.tuples("(1, 'open)")).hasMessageContaining("unterminated");
        assertThatThrownBy(() -> SeedLoader.tuples("(1) x (2)")).hasMessageContaining("between rows");
    }

    /**
     * Every row of the script arrives, with its literals intact (the script's own per-row counts,
     * quotes, NULLs and timestamps), without running the slow statement-by-statement path.
     */
    @Test
    void theSampleDataLoadsBatchedExactlyAsWritten() throws Exception {
        String script = SqlScript.resource("sample-data.sql");
        java.util.Map<String, Integer> expected = new java.util.HashMap<>();
        java.util.regex.Pattern insert = java.util.regex.Pattern.compile("(?is)INSERT\\s+INTO\\s+(\\w+)\\s*\\([^)]*\\)\\s*VALUES\\s*(.*)");
        for (String sql : SqlScript.split(script)) {
            java.util.regex.Matcher m = insert.matcher(sql);
            assertThat(m.matches()).as(sql).isTrue();
            expected.merge(m.group(1).toUpperCase(java.util.Locale.ROOT), SeedLoader.tuples(m.group(2)).size(), Integer::sum);
        }
        try (Connection c = DriverManager.getConnection("jdbc:derby:memory:seed-batched;create=true")) {
            c.setAutoCommit(false);
            SqlScript.run(c, SqlScript.resource("vehicleDB.sql"), "vehicleDB.sql");
            long rows = SeedLoader.run(c, script, "sample-data.sql");
            c.commit();
            assertThat(rows).isEqualTo(expected.values().stream().mapToLong(Integer::longValue).sum()).isGreaterThan(10_000);
            try (Statement st = c.createStatement()) {
                for (String table : EmbeddedDatabase.TABLES) {
                    try (ResultSet rs = st.executeQuery("SELECT COUNT(*) FROM " + table)) {
                        rs.next();
                        assertThat(rs.getInt(1)).as(table).isEqualTo(expected.getOrDefault(table, 0));
                    }
                }
                try (ResultSet rs = st.executeQuery("SELECT name FROM vehicle WHERE vehicle_id = 4")) {
                    rs.next();
                    assertThat(rs.getString(1)).isEqualTo("St. David's");
                }
                try (ResultSet rs = st.executeQuery("SELECT COUNT(*) FROM mission WHERE endt IS NULL")) {
                    rs.next();
                    assertThat(rs.getInt(1)).isEqualTo(3);
                }
                try (ResultSet rs = st.executeQuery("SELECT startt FROM mission WHERE mission_id = 2")) {
                    rs.next();
                    assertThat(rs.getTimestamp(1)).isEqualTo(java.sql.Timestamp.valueOf("2002-04-09 14:30:00"));
                }
            }
            c.commit();
        }
    }
}
