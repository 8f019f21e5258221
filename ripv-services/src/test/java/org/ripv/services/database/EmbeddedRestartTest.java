package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/** First start creates and seeds the embedded database; the second start reuses it as it was left. */
class EmbeddedRestartTest {
    @Test
    void firstStartSeedsSecondReuses(@TempDir Path data) throws Exception {
        DatabaseTarget first = EmbeddedDatabase.prepare(data, "TTY1");
        DatabaseServer service = new DatabaseServer("h", List.of(first), QueryLimits.defaults());
        service.start();
        ServiceHarness client = new ServiceHarness(service);
        assertThat(client.send("TTY1", "INSERT INTO vehicle (vehicle_id, name) VALUES (5, 'Spare')").status())
                .isEqualTo(Status.OK);
        service.stop();

        DatabaseTarget second = EmbeddedDatabase.prepare(data, "TTY1");
        assertThat(second.password()).isEqualTo(first.password());
        DatabaseServer again = new DatabaseServer("h", List.of(second), QueryLimits.defaults());
        again.start();
        try {
            TableResult t = (TableResult) new ServiceHarness(again).send("TTY1", "SELECT name FROM vehicle ORDER BY vehicle_id")
                    .footer().result();
            // the row written before the restart is still there: reused, not created again
            assertThat(t.rows()).extracting(r -> r[0]).containsExactly("Sargasso", "Gulfstream", "Challenger", "St. David's",
                    "Spare");
        } finally {
            again.stop();
        }
    }

    @Test
    void anUnfinishedFirstStartIsDoneAgain(@TempDir Path data) throws Exception {
        // a database directory without credentials: the first start died half way
        Files.createDirectories(data.resolve(EmbeddedDatabase.DATABASE_DIR).resolve("seg0"));
        DatabaseTarget db = EmbeddedDatabase.prepare(data, "TTY1");
        DatabaseServer service = new DatabaseServer("h", List.of(db), QueryLimits.defaults());
        service.start();
        try {
            TableResult t = (TableResult) new ServiceHarness(service).send("TTY1", "SELECT COUNT(*) FROM mission")
                    .footer().result();
            assertThat(t.rows().get(0)[0]).isEqualTo("4");
        } finally {
            service.stop();
        }
    }
}
