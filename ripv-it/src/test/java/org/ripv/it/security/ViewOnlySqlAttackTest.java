package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.ServerConfig;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;

/**
 * Issue 33 item 6: with docs/web.md's view-only rules ({@code SELECT * FROM positions ORDER BY*})
 * a subquery in ORDER BY was a one-bit oracle on any table (it recovered
 * {@code data_file.ingested_by}), and a cross join of system tables ran 12–15 s a query. A view
 * user (role {@code db-views}) now runs one SELECT from one view, no parentheses, on the read-only
 * user under a 5 s limit; the data page's own queries still work.
 */
class ViewOnlySqlAttackTest {
    static final Duration T = Duration.ofSeconds(60);
    static final String DB = "<DatabaseServer>::<localhost>TTY1";

    @TempDir
    static Path dir;
    static TestSystem sys;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("otto", "operators").user("vera", "db-views");
        sys.rules("allow @operators * * *", "allow @db-views DatabaseServer * SELECT *");
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                QueryLimits.defaults()));
        Files.copy(Path.of("../ripv-services/src/test/resources/slocum/unit_363_2013_245_6_6.mrg"),
                sys.downloadDir().resolve("unit_363_2013_245_6_6.mrg"));
        ClientSocketHandler otto = sys.login("otto");
        OutgoingServerMessage r = otto.call(DB, "ingest unit_363_2013_245_6_6.mrg", Priority.NORMAL, T, p -> { });
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        otto.close();
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void aViewUserReadsTheViewsAndNothingElse() throws Exception {
        ClientSocketHandler vera = sys.login("vera");
        // The data page's own three queries.
        for (String ok : List.of("SELECT * FROM positions ORDER BY time_utc DESC FETCH FIRST 1000 ROWS ONLY",
                "SELECT * FROM latest ORDER BY vehicle, sensor", "SELECT * FROM dives ORDER BY start_utc DESC",
                // a track's points as the server's vis:track asks for them, as the user
                "SELECT lon, lat FROM positions WHERE vehicle = 'unit_363' AND time_utc <= CAST('2030-01-01 00:00:00' AS TIMESTAMP)"
                        + " ORDER BY time_utc DESC")) {
            OutgoingServerMessage r = vera.call(DB, ok, Priority.NORMAL, T, p -> { });
            assertThat(r.status()).as(ok + ": " + r.footer().replyText()).isEqualTo(Status.OK);
        }
        // The oracle: ORDER BY a subquery on another table; a cross join of system tables; a second table; a union.
        for (String attack : List.of(
                "SELECT * FROM positions ORDER BY (SELECT COUNT(*) FROM data_file WHERE ingested_by LIKE 'o%')",
                "SELECT * FROM positions ORDER BY CASE WHEN EXISTS (SELECT 1 FROM data_file) THEN 1 ELSE 0 END",
                "SELECT * FROM positions, sys.systables a, sys.syscolumns b, sys.syscolumns c ORDER BY 1",
                "SELECT * FROM positions JOIN data_file ON 1=1 ORDER BY 1",
                "SELECT * FROM positions UNION SELECT * FROM positions ORDER BY 1",
                "SELECT * FROM data_file ORDER BY 1",
                "SELECT * FROM \"SYS\".\"SYSTABLES\" ORDER BY 1",
                "SELECT * FROM positions ORDER BY 1 -- comment",
                "SELECT * FROM positions ORDER BY CAST((SELECT MAX(ingested_by) FROM data_file) AS VARCHAR(9))")) {
            long t0 = System.nanoTime();
            OutgoingServerMessage r = vera.call(DB, attack, Priority.NORMAL, T, p -> { });
            assertThat(r.status()).as(attack).isEqualTo(Status.ERROR);
            assertThat(r.footer().errorCode()).as(attack).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(r.footer().replyText()).as(attack).contains("view users (role db-views) may run one SELECT from one of the views");
            assertThat(Duration.ofNanos(System.nanoTime() - t0)).as("refused before it runs").isLessThan(Duration.ofSeconds(3));
        }
        vera.close();
    }
}
