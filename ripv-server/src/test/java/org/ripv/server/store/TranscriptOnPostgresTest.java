package org.ripv.server.store;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.Statement;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.server.session.Transcript;

/**
 * The server's transcript writer on PostgreSQL when the database refuses writes for a while (here:
 * the store's user loses INSERT on the table for 2 s, as during a fail-over): the batch is retried
 * and nothing is lost, in order. Needs RIPV_PG_URL with a user that may create roles.
 */
class TranscriptOnPostgresTest {
    static final String BOX = "<SerialPortServer>::<shore>ru29";

    @TempDir
    Path dir;

    @Test
    void aDatabaseThatRefusesWritesForAWhileLosesNoEntry() throws Exception {
        try (PgSchema schema = PgSchema.create()) {
            String role = schema.name + "_w";
            try (Connection c = schema.connect(); Statement st = c.createStatement()) {
                st.execute("CREATE ROLE " + role + " LOGIN PASSWORD 'writer-pass'");
                st.execute("GRANT USAGE, CREATE ON SCHEMA " + schema.name + " TO " + role);
            }
            try {
                StoreLocation asRole = new StoreLocation(schema.location().jdbcUrl(), role, "writer-pass");
                long t0 = Instant.parse("2026-11-23T10:00:00Z").toEpochMilli();
                try (StateStore store = StateStores.open(asRole, dir, 0);
                     Transcript t = new Transcript(dir.resolve("transcripts"), store, 90)) {
                    t.append(ConsoleEntry.line(BOX, "before"));
                    t.sync();
                    try (Connection c = schema.connect(); Statement st = c.createStatement()) {
                        st.execute("REVOKE INSERT ON ripv_transcript FROM " + role);
                    }
                    for (int i = 0; i < 1000; i++) {
                        t.append(new ConsoleEntry(t0 + i, BOX, ConsoleEntry.Kind.LINE, "", "during " + i, null, null, null));
                    }
                    Thread.sleep(2000); // the writer is retrying meanwhile
                    try (Connection c = schema.connect(); Statement st = c.createStatement()) {
                        st.execute("GRANT INSERT ON ripv_transcript TO " + role);
                    }
                    t.append(ConsoleEntry.line(BOX, "after"));
                    long end = System.nanoTime() + 20_000_000_000L;
                    Transcript.Page p;
                    do {
                        p = t.history(BOX, null, 0);
                    } while (p.entries().size() < 1002 && System.nanoTime() < end);
                    List<String> texts = p.entries().stream().map(ConsoleEntry::text).toList();
                    assertThat(texts).hasSize(1002);
                    assertThat(texts.get(0)).isEqualTo("before");
                    assertThat(texts.subList(1, 1001)).isEqualTo(java.util.stream.IntStream.range(0, 1000).mapToObj(i -> "during " + i).toList());
                    assertThat(texts.get(1001)).isEqualTo("after");
                }
            } finally {
                try (Connection c = schema.connect(); Statement st = c.createStatement()) {
                    st.execute("DROP OWNED BY " + role + " CASCADE");
                    st.execute("DROP ROLE IF EXISTS " + role);
                }
            }
        }
    }
}
