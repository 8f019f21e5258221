package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.UpdateCount;

/**
 * The DatabaseServer on its embedded default, driven in-process through the same
 * {@code accept} path the RMI adapter uses: first start seeds, second reuses; queries, updates,
 * bad SQL, a timeout, a truncated result and a reader's write each get the right reply, and the
 * service keeps serving after all of them.
 */
class DatabaseServerTest {
    @TempDir
    static Path data;
    private static DatabaseServer service;
    private static ServiceHarness client;
    private static final String TTY = "TTY1";
    private static final List<String> READER = List.of(DatabaseHandler.READER_ROLE);

    @BeforeAll
    static void start() throws Exception {
        DatabaseTarget db = EmbeddedDatabase.prepare(data, TTY);
        service = new DatabaseServer("testhost", List.of(db), new QueryLimits(500, 2, QueryLimits.DEFAULT_MAX_RESULT_CHARS));
        service.start();
        client = new ServiceHarness(service);
    }

    @AfterAll
    static void stop() {
        if (service != null) {
            service.stop();
        }
    }

    private static TableResult table(OutgoingServiceMessage r) {
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().serviceId()).isEqualTo(Ids.SID_DATABASE);
        assertThat(r.footer().result()).isInstanceOf(TableResult.class);
        return (TableResult) r.footer().result();
    }

    @Test
    void describesItself() {
        assertThat(service.descriptor().panel()).isEqualTo("DAB");
        assertThat(service.name().toString()).isEqualTo("<DatabaseServer>::<testhost>");
        List<MailboxStatus> boxes = service.mailboxes();
        assertThat(boxes).extracting(MailboxStatus::address).containsExactly("<DatabaseServer>::<testhost>TTY1");
        assertThat(boxes.get(0).available()).isTrue();
        assertThat(service.descriptor().toString()).doesNotContain(service.targets().get(0).password());
    }

    @Test
    void selectMissionsReturnsTheFourMissions() throws Exception {
        TableResult t = table(client.send(TTY, "SELECT * FROM mission ORDER BY mission_id;"));
        assertThat(t.columns()).containsExactly("MISSION_ID", "VEHICLE_ID", "NAME", "DESCRIPTION", "STARTT", "ENDT");
        assertThat(t.types()).containsExactly("INTEGER", "INTEGER", "VARCHAR", "VARCHAR", "TIMESTAMP", "TIMESTAMP");
        assertThat(t.rows()).hasSize(4);
        assertThat(t.truncated()).isFalse();
        assertThat(t.rows().get(0)[2]).isEqualTo("BATS-0402");
        assertThat(t.rows().get(0)[5]).startsWith("2002-04-05");
        // three missions are still under way: SQL NULL travels as null
        assertThat(t.rows().subList(1, 4)).allSatisfy(row -> assertThat(row[5]).isNull());
        assertThat(t.query()).isEqualTo("SELECT * FROM mission ORDER BY mission_id");
    }

    @Test
    void joinsAndAggregatesWork() throws Exception {
        TableResult t = table(client.send(TTY, "SELECT v.name, COUNT(*) AS readings FROM sensor_data d"
                + " JOIN leg l ON d.leg_id = l.leg_id JOIN mission m ON l.mission_id = m.mission_id"
                + " JOIN vehicle v ON m.vehicle_id = v.vehicle_id WHERE d.sensor_id = 3 GROUP BY v.name ORDER BY v.name"));
        assertThat(t.columns()).containsExactly("NAME", "READINGS");
        assertThat(t.rows()).extracting(r -> r[0]).containsExactly("Challenger", "Gulfstream", "Sargasso", "St. David's");
        assertThat(t.rows()).allSatisfy(r -> assertThat(Long.parseLong(r[1])).isGreaterThan(300));
    }

    @Test
    void badSqlAnswersWithTheDatabasesMessageAndTheServiceKeepsServing() throws Exception {
        OutgoingServiceMessage r = client.send(TTY, "SELEC * FROM mission");
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.DATABASE_ERROR);
        assertThat(r.footer().replyText()).contains("SQLState 42X01").contains("SELEC");

        r = client.send(TTY, "SELECT * FROM no_such_table");
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.DATABASE_ERROR);
        assertThat(r.footer().replyText()).contains("NO_SUCH_TABLE").contains("42X05");

        r = client.send(TTY, "   ");
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        r = client.send(TTY, "SELECT 1 FROM vehicle; DELETE FROM vehicle");
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(r.footer().replyText()).contains("one SQL statement");

        assertThat(table(client.send(TTY, "SELECT COUNT(*) FROM vehicle")).rows().get(0)[0]).isEqualTo("4");
    }

    @Test
    void aLongCrossJoinTimesOutClearly() throws Exception {
        long started = System.nanoTime();
        OutgoingServiceMessage r = client.send(TTY,
                "SELECT COUNT(*) FROM sensor_data a, sensor_data b, sensor_data c WHERE a.value + b.value > c.value");
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.TIMEOUT);
        // embedded Derby's limit is the service's own (RunningStatement), not the driver's XCL52
        assertThat(r.footer().replyText()).contains("query timeout of 2 s");
        assertThat((System.nanoTime() - started) / 1_000_000_000L).isLessThan(60);
        assertThat(table(client.send(TTY, "SELECT COUNT(*) FROM sensor")).rows().get(0)[0]).isEqualTo("3");
    }

    @Test
    void aLargeResultIsTruncatedAtMaxRows() throws Exception {
        OutgoingServiceMessage r = client.send(TTY, "SELECT * FROM sensor_data");
        TableResult t = table(r);
        assertThat(t.rows()).hasSize(500);
        assertThat(t.truncated()).isTrue();
        assertThat(r.footer().replyText()).contains("truncated").contains("500");

        TableResult exact = table(client.send(TTY, "SELECT * FROM sensor_data FETCH FIRST 500 ROWS ONLY"));
        assertThat(exact.rows()).hasSize(500);
        assertThat(exact.truncated()).isFalse();
    }

    @Test
    void theOwnerMayWriteAndGetsTheCount() throws Exception {
        OutgoingServiceMessage r = client.send(TTY, "INSERT INTO sensor (sensor_id, name, units, raw_units)"
                + " VALUES (40, 'oxygen', 'umol/kg', 'Hz')");
        assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        assertThat(r.footer().result()).isEqualTo(new UpdateCount(1));
        assertThat(r.footer().replyText()).startsWith("1 row changed");
        r = client.send(TTY, "UPDATE sensor SET description = 'optode' WHERE sensor_id = 40");
        assertThat(r.footer().result()).isEqualTo(new UpdateCount(1));
        r = client.send(TTY, "DELETE FROM sensor WHERE sensor_id = 40");
        assertThat(r.footer().result()).isEqualTo(new UpdateCount(1));
        // constraints hold through the service too
        r = client.send(TTY, "INSERT INTO mission (mission_id, vehicle_id, name) VALUES (77, 99, 'ghost')");
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.DATABASE_ERROR);
        assertThat(r.footer().replyText()).contains("23503");
    }

    @Test
    void aReaderReadsButCannotWriteInTheDatabaseItself() throws Exception {
        TableResult t = table(client.send(TTY, "SELECT name FROM vehicle ORDER BY vehicle_id", "bob", READER));
        assertThat(t.rows()).extracting(row -> row[0]).containsExactly("Sargasso", "Gulfstream", "Challenger", "St. David's");

        for (String write : List.of("INSERT INTO vehicle (vehicle_id, name) VALUES (9, 'intruder')",
                "DELETE FROM sensor_data", "DROP TABLE ripv.sensor_data", "CREATE TABLE mine (x INTEGER)",
                "UPDATE mission SET endt = CURRENT_TIMESTAMP")) {
            OutgoingServiceMessage r = client.send(TTY, write, "bob", READER);
            assertThat(r.status()).as(write).isEqualTo(Status.ERROR);
            assertThat(r.footer().errorCode()).as(write + ": " + r.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(r.footer().replyText()).contains("SQLState");
        }
        // nothing changed, and the reader is still served
        assertThat(table(client.send(TTY, "SELECT COUNT(*) FROM vehicle", "bob", READER)).rows().get(0)[0]).isEqualTo("4");
        assertThat(table(client.send(TTY, "SELECT COUNT(*) FROM sensor_data")).rows().get(0)[0]).isNotEqualTo("0");
    }

    @Test
    void theDatabaseRefusesConnectionsWithoutCredentials() {
        String url = service.targets().get(0).url();
        assertThatThrownBy(() -> DriverManager.getConnection(url).close()).isInstanceOf(SQLException.class)
                .satisfies(e -> assertThat(((SQLException) e).getSQLState()).isEqualTo("08004"));
        assertThatThrownBy(() -> DriverManager.getConnection(url, "MALLORY", "guess").close()).isInstanceOf(SQLException.class);
    }

    @Test
    void credentialsAreKeptPrivate() throws Exception {
        Path credentials = data.resolve(EmbeddedDatabase.CREDENTIALS);
        assertThat(credentials).exists();
        if (Files.getFileAttributeView(credentials, java.nio.file.attribute.PosixFileAttributeView.class) != null) {
            assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(credentials))).isEqualTo("rw-------");
        }
    }

    @Test
    void rowsCarryNullsAsNull() throws Exception {
        TableResult t = table(client.send(TTY, "SELECT leg_id, endt FROM leg WHERE endt IS NULL ORDER BY leg_id"));
        assertThat(t.rows()).extracting(r -> r[0]).containsExactly("7", "11", "14");
        assertThat(t.rows()).allSatisfy(r -> assertThat(Arrays.asList(r)).containsNull());
    }
}
