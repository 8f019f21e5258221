package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.DriverManager;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * One DatabaseServer with three databases, so three MailBoxes: a Derby network server database
 * with NATIVE users (TTY1), an in-memory embedded database without users (TTY2), and a database
 * that is down (TTY3). Each MailBox answers from its own database; the one that is down says so
 * and does not disturb the others.
 */
@ResourceLock("derby.network") // one Derby network server at a time in this JVM
class NetworkAndSeveralDatabasesTest {
    private static DerbyNetwork network;
    private static DatabaseServer service;
    private static ServiceHarness client;

    @BeforeAll
    static void start() throws Exception {
        network = DerbyNetwork.start();
        String networkUrl = network.url("memory:netVehicles");
        EmbeddedDatabase.install(networkUrl, "ownerSecret", "readerSecret", true);

        String memoryUrl = "jdbc:derby:memory:plainVehicles";
        try (Connection c = DriverManager.getConnection(memoryUrl + ";create=true")) {
            SqlScript.run(c, SqlScript.resource("vehicleDB.sql"), "vehicleDB.sql");
            c.createStatement().execute("INSERT INTO vehicle (vehicle_id, name) VALUES (1, 'Only')");
        }
        List<String> h = DatabaseServer.handles(3);
        service = new DatabaseServer("multi", List.of(
                new DatabaseTarget(h.get(0), "org.apache.derby.jdbc.ClientDriver", networkUrl, "RIPV", "ownerSecret",
                        "READER", "readerSecret", "RIPV"),
                DatabaseTarget.of(h.get(1), memoryUrl, null, null),
                DatabaseTarget.of(h.get(2), "jdbc:derby://localhost:1/nothingHere", "x", "y")),
                new QueryLimits(1000, 5, QueryLimits.DEFAULT_MAX_RESULT_CHARS));
        service.start();
        client = new ServiceHarness(service);
    }

    @AfterAll
    static void stop() throws Exception {
        if (service != null) {
            service.stop();
        }
        if (network != null) {
            network.close();
        }
    }

    @Test
    void oneMailBoxPerDatabaseNamedPerAppendixA() {
        assertThat(DatabaseServer.handles(3)).containsExactly("TTY1", "TTY2", "TTY3");
        List<MailboxStatus> boxes = service.mailboxes();
        assertThat(boxes).extracting(MailboxStatus::address).containsExactlyInAnyOrder(
                "<DatabaseServer>::<multi>TTY1", "<DatabaseServer>::<multi>TTY2", "<DatabaseServer>::<multi>TTY3");
        MailboxStatus down = boxes.stream().filter(b -> b.address().endsWith("TTY3")).findFirst().orElseThrow();
        assertThat(down.available()).isFalse();
        assertThat(down.detail()).contains("localhost:1");
    }

    @Test
    void eachMailBoxAnswersFromItsOwnDatabase() throws Exception {
        TableResult net = (TableResult) client.send("TTY1", "SELECT COUNT(*) FROM mission").footer().result();
        assertThat(net.rows().get(0)[0]).isEqualTo("4");
        TableResult mem = (TableResult) client.send("TTY2", "SELECT name FROM vehicle").footer().result();
        assertThat(mem.rows()).extracting(r -> r[0]).containsExactly("Only");
    }

    @Test
    void theReaderIsReadOnlyOverTheNetworkToo() throws Exception {
        List<String> reader = List.of(DatabaseHandler.READER_ROLE);
        TableResult t = (TableResult) client.send("TTY1", "SELECT name FROM mission WHERE endt IS NULL ORDER BY mission_id",
                "carol", reader).footer().result();
        assertThat(t.rows()).extracting(r -> r[0]).containsExactly("Hydrostation-S", "Eddy-Chase", "Shelf-Edge");
        OutgoingServiceMessage r = client.send("TTY1", "DELETE FROM sensor_data", "carol", reader);
        assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);
        r = client.send("TTY1", "CREATE TABLE carols (x INTEGER)", "carol", reader);
        assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.FORBIDDEN);
        // a database with no reader configured refuses readers outright
        r = client.send("TTY2", "SELECT * FROM vehicle", "carol", reader);
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(r.footer().replyText()).contains("--reader-user");
    }

    @Test
    void aDatabaseThatIsDownAnswersClearlyAndTheOthersKeepServing() throws Exception {
        OutgoingServiceMessage r = client.send("TTY3", "SELECT 1 FROM sysibm.sysdummy1");
        assertThat(r.status()).isEqualTo(Status.ERROR);
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.NOT_AVAILABLE);
        assertThat(r.footer().replyText()).contains("cannot connect to jdbc:derby://localhost:1/nothingHere");
        assertThat(client.send("TTY2", "SELECT 1 FROM sysibm.sysdummy1").status()).isEqualTo(Status.OK);
    }
}
