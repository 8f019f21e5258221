package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/**
 * Issue 10: one reader's session state does not carry over to the next on the shared connection;
 * observers read whatever roles they were given; the database's files are owner-only.
 */
class DatabasePrivacyTest {
    @TempDir
    static Path data;
    private static DatabaseServer service;
    private static ServiceHarness client;
    private static final String TTY = "TTY1";

    @BeforeAll
    static void start() throws Exception {
        DatabaseTarget db = EmbeddedDatabase.prepare(data, TTY);
        service = new DatabaseServer("testhost", List.of(db), QueryLimits.defaults());
        service.start();
        client = new ServiceHarness(service);
    }

    @AfterAll
    static void stop() {
        if (service != null) {
            service.stop();
        }
    }

    @Test
    void setSchemaByOneReaderDoesNotCarryOverToTheNext() throws Exception {
        OutgoingServiceMessage set = client.send(TTY, "SET SCHEMA SYS", "rita", List.of("observers", "db-reader"));
        assertThat(set.status()).as(set.footer().replyText()).isEqualTo(Status.OK);
        OutgoingServiceMessage next = client.send(TTY, "SELECT COUNT(*) FROM vehicle", "sam", List.of("observers", "db-reader"));
        assertThat(next.status()).as(next.footer().replyText()).isEqualTo(Status.OK);
        assertThat(((TableResult) next.footer().result()).rows().get(0)[0]).isEqualTo("4");
        // the owner connection too
        client.send(TTY, "SET SCHEMA SYS", "otto", List.of("operators"));
        OutgoingServiceMessage op = client.send(TTY, "SELECT COUNT(*) FROM vehicle", "olaf", List.of("operators"));
        assertThat(op.status()).as(op.footer().replyText()).isEqualTo(Status.OK);
    }

    @Test
    void observersWithoutDbReaderStillOnlyRead() throws Exception {
        for (List<String> roles : List.of(List.of("observers"), List.<String>of(), List.of("scientists"))) {
            OutgoingServiceMessage r = client.send(TTY, "DELETE FROM sensor_data WHERE 1 = 0", "olga", roles);
            assertThat(r.status()).as(roles + ": " + r.footer().replyText()).isEqualTo(Status.ERROR);
            assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
            OutgoingServiceMessage q = client.send(TTY, "SELECT COUNT(*) FROM vehicle", "olga", roles);
            assertThat(q.status()).as(q.footer().replyText()).isEqualTo(Status.OK);
        }
        assertThat(DatabaseHandler.readsOnly(List.of("operators"))).isFalse();
        assertThat(DatabaseHandler.readsOnly(List.of("db-writer"))).isFalse();
        assertThat(DatabaseHandler.readsOnly(List.of("operators", "db-reader"))).isTrue();
        OutgoingServiceMessage w = client.send(TTY, "DELETE FROM sensor_data WHERE 1 = 0", "otto", List.of("operators"));
        assertThat(w.status()).as(w.footer().replyText()).isEqualTo(Status.OK);
    }

    @Test
    void theDatabaseFilesAreOwnerOnly() throws Exception {
        client.send(TTY, "SELECT COUNT(*) FROM vehicle");
        try (Stream<Path> all = Files.walk(data)) {
            for (Path p : (Iterable<Path>) all::iterator) {
                String mode = PosixFilePermissions.toString(Files.getPosixFilePermissions(p));
                assertThat(mode).as(data.relativize(p).toString()).isEqualTo(Files.isDirectory(p) ? "rwx------" : "rw-------");
            }
        }
    }
}
