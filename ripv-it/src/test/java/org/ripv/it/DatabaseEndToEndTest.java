package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.UpdateCount;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;

/**
 * The DatabaseServer through the whole stack: client socket, RIPVServer, RMI, service, embedded
 * Derby, and back. The permit file's {@code db-reader} role reaches the service and makes the
 * user's SQL run as the database's read-only user.
 */
class DatabaseEndToEndTest {
    static final Duration T = Duration.ofSeconds(60);
    static final String DB = "<DatabaseServer>::<localhost>TTY1";

    @TempDir
    static Path dir;
    static TestSystem sys;

    @BeforeAll
    static void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators").user("bob", "operators", "db-reader");
        DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1");
        sys.register(new DatabaseServer("localhost", List.of(db), new QueryLimits(1000, 3, QueryLimits.DEFAULT_MAX_RESULT_CHARS)));
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void selectMissionsComesBackAsATable() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        OutgoingServerMessage r = c.call(DB, "SELECT mission_id, name, endt FROM mission ORDER BY mission_id", Priority.NORMAL, T, null);
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().serviceId()).isEqualTo(Ids.SID_DATABASE);
        TableResult t = (TableResult) r.footer().result();
        assertThat(t.columns()).containsExactly("MISSION_ID", "NAME", "ENDT");
        assertThat(t.rows()).extracting(row -> row[1]).containsExactly("BATS-0402", "Hydrostation-S", "Eddy-Chase", "Shelf-Edge");
        assertThat(t.rows().get(0)[2]).isNotNull();
        assertThat(t.rows().get(3)[2]).isNull();
    }

    @Test
    void errorsComeBackClearlyAndTheServiceKeepsServing() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        OutgoingServerMessage bad = c.call(DB, "SELECT * FROM missions", Priority.NORMAL, T, null);
        assertThat(bad.footer().errorCode()).isEqualTo(ErrorCode.DATABASE_ERROR);
        assertThat(bad.footer().replyText()).contains("MISSIONS").contains("42X05");

        OutgoingServerMessage slow = c.call(DB, "SELECT COUNT(*) FROM sensor_data a, sensor_data b, sensor_data c",
                Priority.NORMAL, T, null);
        assertThat(slow.footer().errorCode()).as(slow.footer().replyText()).isEqualTo(ErrorCode.TIMEOUT);

        OutgoingServerMessage cut = c.call(DB, "SELECT * FROM sensor_data", Priority.NORMAL, T, null);
        assertThat(((TableResult) cut.footer().result()).rows()).hasSize(1000);
        assertThat(((TableResult) cut.footer().result()).truncated()).isTrue();

        OutgoingServerMessage ok = c.call(DB, "UPDATE vehicle SET description = 'back in the lab' WHERE vehicle_id = 1",
                Priority.NORMAL, T, null);
        assertThat(ok.footer().result()).isEqualTo(new UpdateCount(1));
    }

    @Test
    void aDbReaderIsReadOnlyInTheDatabase() throws Exception {
        ClientSocketHandler c = sys.login("bob");
        OutgoingServerMessage read = c.call(DB, "SELECT COUNT(*) FROM vehicle", Priority.NORMAL, T, null);
        assertThat(((TableResult) read.footer().result()).rows().get(0)[0]).isEqualTo("4");
        OutgoingServerMessage write = c.call(DB, "DELETE FROM sensor_data", Priority.NORMAL, T, null);
        assertThat(write.status()).isEqualTo(Status.ERROR);
        assertThat(write.footer().errorCode()).as(write.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);
    }
}
