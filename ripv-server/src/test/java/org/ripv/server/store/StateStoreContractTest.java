package org.ripv.server.store;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.Statement;
import java.time.Instant;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.ripv.server.store.StateStore.AuditRecord;
import org.ripv.server.store.StateStore.Stored;
import org.ripv.server.store.StateStore.TranscriptLine;
import org.ripv.server.store.StateStore.TranscriptPage;

/**
 * What every {@link StateStore} must do, run against both: the embedded store in a temporary
 * data directory, and PostgreSQL in a schema of the test's own (RIPV_PG_URL; skipped without it,
 * a failure in CI). Each test reopens the store to show that what it kept outlives the process's
 * objects.
 */
class StateStoreContractTest {
    enum Kind { EMBEDDED, POSTGRES }

    static final String A = "<SerialPortServer>::<shore>ru29";
    static final String B = "<SerialPortServer>::<../../etc>passwd \"quoted\" ünï";
    static final long T0 = Instant.parse("2026-11-23T10:00:00Z").toEpochMilli();

    @TempDir
    Path dataDir;
    private PgSchema schema;
    private final List<StateStore> open = new ArrayList<>();

    @AfterEach
    void closeAll() throws Exception {
        open.forEach(StateStore::close);
        if (schema != null) {
            schema.close();
        }
    }

    private StateStore open(Kind kind) throws Exception {
        StateStore s;
        if (kind == Kind.EMBEDDED) {
            s = StateStores.open(StoreLocation.embedded(), dataDir, 1 << 20);
        } else {
            if (schema == null) {
                schema = PgSchema.create();
            }
            s = StateStores.open(schema.location(), dataDir, 8192);
        }
        open.add(s);
        return s;
    }

    /** Closes a store and opens the same one again. */
    private StateStore reopen(Kind kind, StateStore s) throws Exception {
        s.close();
        open.remove(s);
        return open(kind);
    }

    private static String json(long time, String mailbox, String text) {
        return "{\"time\":\"" + Instant.ofEpochMilli(time) + "\",\"mailbox\":\"" + mailbox.replace("\"", "\\\"")
                + "\",\"kind\":\"LINE\",\"text\":\"" + text + "\"}";
    }

    private static TranscriptLine line(long time, String mailbox, String text) {
        return new TranscriptLine(mailbox, time, json(time, mailbox, text));
    }

    private static List<String> texts(TranscriptPage p) {
        return p.lines().stream().map(l -> l.replaceAll(".*\"text\":\"([^\"]*)\".*", "$1")).toList();
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void transcriptsKeepOrderPerMailboxAndReadFirstLastAndSince(Kind kind) throws Exception {
        StateStore s = open(kind);
        List<TranscriptLine> batch = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            batch.add(line(T0 + i, i % 3 == 0 ? B : A, "line" + i));
        }
        s.appendTranscript(batch.subList(0, 150));
        s.appendTranscript(batch.subList(150, 300));
        s.appendTranscript(List.of());
        s = reopen(kind, s);

        TranscriptPage first = s.readTranscript(A, 0, 5, false);
        assertThat(texts(first)).containsExactly("line1", "line2", "line4", "line5", "line7");
        assertThat(first.more()).isTrue();
        TranscriptPage last = s.readTranscript(A, 0, 3, true);
        assertThat(texts(last)).containsExactly("line296", "line298", "line299");
        assertThat(last.more()).isTrue();
        TranscriptPage since = s.readTranscript(B, T0 + 290, 100, false);
        assertThat(texts(since)).containsExactly("line291", "line294", "line297");
        assertThat(since.more()).isFalse();
        assertThat(s.readTranscript(B, 0, 1000, false).lines()).hasSize(100);
        assertThat(s.readTranscript("<X>::<nobody>", 0, 10, true).lines()).isEmpty();
        assertThat(first.unreadable()).isZero();
    }

    /**
     * A transcript is in the order entries were appended, not by their times: entries stamped in
     * the same millisecond, or by a service whose clock is behind the server's, keep their order
     * (StateStoreRestartTest reads the newest two after a restart).
     */
    @ParameterizedTest
    @EnumSource(Kind.class)
    void entriesOfTheSameOrAnEarlierTimeStayInTheOrderTheyWereAppended(Kind kind) throws Exception {
        StateStore s = open(kind);
        s.appendTranscript(List.of(line(T0 + 5, A, "first"), line(T0 + 5, A, "second"), line(T0 + 1, A, "third")));
        s.appendTranscript(List.of(line(T0 + 5, A, "fourth"), line(T0, A, "fifth")));
        s = reopen(kind, s);

        assertThat(texts(s.readTranscript(A, 0, 10, false))).containsExactly("first", "second", "third", "fourth", "fifth");
        assertThat(texts(s.readTranscript(A, 0, 2, true))).containsExactly("fourth", "fifth");
        assertThat(texts(s.readTranscript(A, 0, 4, true))).containsExactly("second", "third", "fourth", "fifth");
        assertThat(texts(s.readTranscript(A, T0 + 5, 10, false))).containsExactly("first", "second", "fourth");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void aVehiclesCallStateIsReplacedWholeAndOutlivesTheStore(Kind kind) throws Exception {
        StateStore s = open(kind);
        assertThat(s.loadVehicleState(A)).isEmpty();
        s.saveVehicleState(A, "{\"state\":\"DIVED\",\"calls\":3}\n");
        s.saveVehicleState(A, "{\"state\":\"ON_CALL\",\"calls\":4}\n");
        s.saveVehicleState(B, "{\"state\":\"LOST\"}\n");
        s = reopen(kind, s);
        assertThat(s.loadVehicleState(A)).contains("{\"state\":\"ON_CALL\",\"calls\":4}\n");
        assertThat(s.loadVehicleState(B)).contains("{\"state\":\"LOST\"}\n");
        if (kind == Kind.EMBEDDED) {
            // where earlier versions kept it, so an upgraded server finds its vehicles' states
            assertThat(dataDir.resolve("transcripts")).isDirectoryRecursivelyContaining("glob:**/state.json");
        }
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void aLargeTranscriptBatchIsStoredWholeInOrder(Kind kind) throws Exception {
        StateStore s = open(kind);
        List<TranscriptLine> batch = new ArrayList<>();
        for (int i = 0; i < 20_000; i++) {
            batch.add(line(T0 + i / 10, A, "n" + i));
        }
        for (int i = 0; i < batch.size(); i += 4096) {
            s.appendTranscript(batch.subList(i, Math.min(batch.size(), i + 4096)));
        }
        s = reopen(kind, s);
        assertThat(texts(s.readTranscript(A, 0, 2, true))).containsExactly("n19998", "n19999");
        assertThat(texts(s.readTranscript(A, T0 + 1000, 2, false))).containsExactly("n10000", "n10001");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void pruningDeletesWholeOldDaysOnly(Kind kind) throws Exception {
        StateStore s = open(kind);
        long old = Instant.parse("2026-01-01T12:00:00Z").toEpochMilli();
        long recent = Instant.parse("2026-11-20T00:00:00Z").toEpochMilli();
        s.appendTranscript(List.of(line(old, A, "old"), line(recent, A, "recent"), line(recent + 1, B, "other")));
        s = reopen(kind, s); // nothing open for writing
        s.pruneTranscripts(LocalDate.parse("2026-11-20"));
        assertThat(texts(s.readTranscript(A, 0, 10, false))).containsExactly("recent");
        assertThat(texts(s.readTranscript(B, 0, 10, false))).containsExactly("other");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void workflowQueuesAreReplacedWholeAndSurvive(Kind kind) throws Exception {
        StateStore s = open(kind);
        assertThat(s.loadQueues()).isEmpty();
        s.saveQueue(A, "mailbox=" + A + "\ncount=1\n");
        s.saveQueue(B, "mailbox=B\ncount=0\n");
        s.saveQueue(A, "mailbox=" + A + "\ncount=2\nentry.0.source=send dir\n");
        s = reopen(kind, s);
        assertThat(s.loadQueues()).extracting(Stored::text)
                .containsExactlyInAnyOrder("mailbox=" + A + "\ncount=2\nentry.0.source=send dir\n", "mailbox=B\ncount=0\n");
        assertThat(s.loadQueues()).allSatisfy(q -> assertThat(q.where()).isNotBlank());
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void fetchedListsArePerMailbox(Kind kind) throws Exception {
        StateStore s = open(kind);
        assertThat(s.loadFetched(A)).isEmpty();
        s.saveFetched(A, "A.DBD=100\n");
        s.saveFetched(A, "A.DBD=100\nB.DBD=7\n");
        s.saveFetched(B, "X=1\n");
        s = reopen(kind, s);
        assertThat(s.loadFetched(A)).contains("A.DBD=100\nB.DBD=7\n");
        assertThat(s.loadFetched(B)).contains("X=1\n");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void receiptsAreReplacedByNameAndOnlyTheNewestKept(Kind kind) throws Exception {
        StateStore s = open(kind);
        for (int i = 0; i < 6; i++) {
            s.saveReceipt(A, String.format("%013d-1-%d.txt", 1000 + i, i), "receipt " + i + " running", 4);
        }
        s.saveReceipt(A, String.format("%013d-1-%d.txt", 1005, 5), "receipt 5 done", 4);
        s.saveReceipt(B, "0000000000001-2-1.txt", "other", 4);
        s = reopen(kind, s);
        assertThat(s.lastReceipts(A, 10)).containsExactly("receipt 2 running", "receipt 3 running", "receipt 4 running",
                "receipt 5 done");
        assertThat(s.lastReceipts(A, 2)).containsExactly("receipt 4 running", "receipt 5 done");
        assertThat(s.lastReceipts(B, 2)).containsExactly("other");
        assertThat(s.lastReceipts("<X>::<none>", 2)).isEmpty();
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void callRecordsAreKeptInOrderAndOnlyTheNewest(Kind kind) throws Exception {
        StateStore s = open(kind);
        for (int i = 0; i < 25; i++) {
            s.appendSurfacing(A, T0 + i, "{\"n\":" + i + ",\"text\":\"ünï \\\"q\\\"\"}", 10);
        }
        s.appendSurfacing(B, T0, "{\"n\":\"other\"}", 10);
        s = reopen(kind, s);
        List<String> last = s.lastSurfacings(A, 100);
        assertThat(last.size()).isBetween(10, 20); // the newest 10 at least; at most twice that before they are cut
        assertThat(last.get(last.size() - 1)).isEqualTo("{\"n\":24,\"text\":\"ünï \\\"q\\\"\"}");
        assertThat(s.lastSurfacings(A, 3)).extracting(x -> x.substring(0, 8)).containsExactly("{\"n\":22,", "{\"n\":23,", "{\"n\":24,");
        assertThat(s.lastSurfacings(B, 3)).containsExactly("{\"n\":\"other\"}");
        assertThat(s.lastSurfacings("<X>::<none>", 3)).isEmpty();
        assertThat(s.surfacingMailboxes()).containsExactlyInAnyOrder(A, B); // a restarted server knows whose calls it kept
        assertThatThrownBy(() -> open(Kind.EMBEDDED).appendSurfacing(A, T0, "{}\n{}", 10))
                .isInstanceOf(IllegalArgumentException.class);
    }

    /**
     * Records kept before the store wrote {@code KEY.mailbox} beside them (issue 35's caveat): a
     * restarted server still knows whose they are, from the transcripts, and names them for next time.
     */
    @Test
    void callRecordsKeptBeforeTheirMailboxFileAreFoundFromTheTranscripts() throws Exception {
        StateStore s = open(Kind.EMBEDDED);
        String c = "<SerialPortServer>::<shore>no-transcript";
        String d = "<SerialPortServer>::<shore>huge-line";
        for (String m : List.of(A, B, c, d)) {
            s.appendSurfacing(m, T0, "{\"n\":1}", 10);
        }
        s.appendTranscript(List.of(line(T0, A, "call"), line(T0 + 1, B, "call")));
        // a hostile transcript whose first line names its MailBox only after a megabyte
        s.appendTranscript(List.of(new TranscriptLine(d, T0, "{\"time\":\"" + Instant.ofEpochMilli(T0) + "\",\"text\":\""
                + "x".repeat(1 << 20) + "\",\"mailbox\":\"" + d + "\"}")));
        Path records = dataDir.resolve("surfacings");
        try (var files = Files.list(records)) { // as the version before wrote them: records only
            for (Path p : files.filter(p -> p.toString().endsWith(".mailbox")).toList()) {
                Files.delete(p);
            }
        }
        s = reopen(Kind.EMBEDDED, s);
        assertThat(s.surfacingMailboxes()).containsExactlyInAnyOrder(A, B);
        assertThat(s.lastSurfacings(A, 3)).containsExactly("{\"n\":1}");
        try (var files = Files.list(records)) { // named now: the next start reads them without looking
            assertThat(files.filter(p -> p.toString().endsWith(".mailbox")).count()).isEqualTo(2);
        }
        s = reopen(Kind.EMBEDDED, s);
        assertThat(s.surfacingMailboxes()).containsExactlyInAnyOrder(A, B);
        s.appendSurfacing(c, T0 + 1, "{\"n\":2}", 10); // its next call names it
        assertThat(s.surfacingMailboxes()).containsExactlyInAnyOrder(A, B, c);
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void subscriptionsAreOneDocument(Kind kind) throws Exception {
        StateStore s = open(kind);
        assertThat(s.loadSubscriptions()).isEmpty();
        s.saveSubscriptions("{\"id\":\"n1\"}\n{\"id\":\"n2\"}\n");
        s.saveSubscriptions("{\"id\":\"n2\"}\n");
        s = reopen(kind, s);
        assertThat(s.loadSubscriptions()).get().extracting(Stored::text).isEqualTo("{\"id\":\"n2\"}\n");
        s.saveSubscriptions("");
        assertThat(s.loadSubscriptions()).get().extracting(Stored::text).isEqualTo("");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void theAuditTrailKeepsOrderLevelAndTime(Kind kind) throws Exception {
        StateStore s = open(kind);
        long now = System.currentTimeMillis();
        s.appendAudit(List.of(new AuditRecord(now - 2000, true, "login-failed user=mallory address=10.0.0.9"),
                new AuditRecord(now - 1000, false, "login user=alice address=127.0.0.1")));
        s.appendAudit(List.of(new AuditRecord(now, true, "permit-denied user=olga command=GO")));
        s = reopen(kind, s);
        assertThat(s.readAudit(0, 10)).extracting(AuditRecord::line).containsExactly("login-failed user=mallory address=10.0.0.9",
                "login user=alice address=127.0.0.1", "permit-denied user=olga command=GO");
        assertThat(s.readAudit(0, 10)).extracting(AuditRecord::warn).containsExactly(true, false, true);
        assertThat(s.readAudit(now - 1000, 10)).extracting(AuditRecord::time).containsExactly(now - 1000, now);
        assertThat(s.readAudit(0, 1)).extracting(AuditRecord::line).containsExactly("permit-denied user=olga command=GO");
    }

    @ParameterizedTest
    @EnumSource(Kind.class)
    void theAuditTrailTakesLinesFromAnyThreadAndStoresThemInBatches(Kind kind) throws Exception {
        StateStore s = open(kind);
        try (AuditTrail trail = new AuditTrail(s)) {
            ExecutorService pool = Executors.newFixedThreadPool(4);
            List<Future<?>> done = new ArrayList<>();
            for (int t = 0; t < 4; t++) {
                int id = t;
                done.add(pool.submit(() -> {
                    for (int i = 0; i < 250; i++) {
                        trail.record(i % 2 == 0, "event thread=" + id + " n=" + i);
                    }
                }));
            }
            for (Future<?> f : done) {
                f.get();
            }
            pool.shutdown();
            trail.sync();
        }
        List<AuditRecord> all = s.readAudit(0, 5000);
        assertThat(all).hasSize(1000);
        assertThat(all).filteredOn(r -> r.line().startsWith("event thread=2 ")).extracting(AuditRecord::line)
                .startsWith("event thread=2 n=0", "event thread=2 n=1").endsWith("event thread=2 n=249");
    }

    /** Embedded: the files are the layout earlier versions wrote, owner-only, with no temporary files left. */
    @Test
    void embeddedKeepsTheDataDirectoryLayout() throws Exception {
        StateStore s = open(Kind.EMBEDDED);
        s.appendTranscript(List.of(line(T0, A, "x")));
        s.saveQueue(A, "mailbox=" + A + "\n");
        s.saveFetched(A, "F=1\n");
        s.saveReceipt(A, "0000000000001-1-1.txt", "r", 10);
        s.saveSubscriptions("{}\n");
        s.appendAudit(List.of(new AuditRecord(T0, false, "login user=alice")));
        s.close();
        String key = DataFiles.key(A);
        assertThat(EmbeddedStateStore.transcriptDir(dataDir.resolve("transcripts"), A).resolve("2026-11-23.jsonl")).exists();
        assertThat(dataDir.resolve("workflows/queues/" + key + ".properties")).hasContent("mailbox=" + A);
        assertThat(dataDir.resolve("workflows/fetched/" + key + ".properties")).hasContent("F=1");
        assertThat(dataDir.resolve("workflows/receipts/" + key + "/0000000000001-1-1.txt")).hasContent("r");
        assertThat(dataDir.resolve("notify/subscriptions.jsonl")).hasContent("{}");
        assertThat(dataDir.resolve("audit/2026-11-23.log")).hasContent("2026-11-23T10:00:00Z INFO login user=alice");
        assertThat(Files.getPosixFilePermissions(dataDir.resolve("notify/subscriptions.jsonl")))
                .containsExactlyInAnyOrder(java.nio.file.attribute.PosixFilePermission.OWNER_READ,
                        java.nio.file.attribute.PosixFilePermission.OWNER_WRITE);
        try (Stream<Path> all = Files.walk(dataDir)) {
            assertThat(all.map(p -> p.getFileName().toString())).noneMatch(n -> n.endsWith(".tmp"));
        }
        // A hostile MailBox name stays inside the data directory.
        assertThat(EmbeddedStateStore.transcriptDir(dataDir.resolve("transcripts"), B).getParent())
                .isEqualTo(dataDir.resolve("transcripts"));
        assertThatThrownBy(() -> open(Kind.EMBEDDED).saveReceipt(A, "../../escape.txt", "x", 10))
                .isInstanceOf(IllegalArgumentException.class);
    }

    /** PostgreSQL: a batch that fails part-way stores none of it. */
    @Test
    void postgresStoresNothingOfAFailedBatch() throws Exception {
        StateStore s = open(Kind.POSTGRES);
        s.appendTranscript(List.of(line(T0, A, "before")));
        List<TranscriptLine> bad = List.of(line(T0 + 1, A, "one"), line(T0 + 2, A, "two"), new TranscriptLine(null, T0 + 3, "{}"));
        assertThatThrownBy(() -> s.appendTranscript(bad)).isInstanceOf(IOException.class).hasMessageContaining("transcript");
        assertThat(texts(s.readTranscript(A, 0, 10, false))).containsExactly("before");
        assertThatThrownBy(() -> s.appendAudit(List.of(new AuditRecord(T0, false, "ok"), new AuditRecord(T0, false, null))))
                .isInstanceOf(IOException.class);
        assertThat(s.readAudit(0, 10)).isEmpty();
        // NUL, which PostgreSQL text cannot hold, does not fail a batch
        s.appendTranscript(List.of(line(T0 + 4, A, "nul\u0000here")));
        assertThat(s.readTranscript(A, 0, 10, true).lines()).hasSize(2);
    }

    /** PostgreSQL: servers starting together make the tables once, and share what they store. */
    @Test
    void postgresServersStartingTogetherShareOneSchema() throws Exception {
        open(Kind.POSTGRES).close(); // the schema exists; drop its tables to race the creation
        try (Connection c = schema.connect(); Statement st = c.createStatement()) {
            st.execute("DROP TABLE ripv_transcript, ripv_document, ripv_receipt, ripv_audit, ripv_surfacing");
        }
        ExecutorService pool = Executors.newFixedThreadPool(4);
        List<Future<StateStore>> opened = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            opened.add(pool.submit((Callable<StateStore>) () -> StateStores.open(schema.location(), dataDir, 8192)));
        }
        List<StateStore> stores = new ArrayList<>();
        for (Future<StateStore> f : opened) {
            stores.add(f.get());
        }
        pool.shutdown();
        open.addAll(stores);
        stores.get(0).saveQueue(A, "from the first");
        assertThat(stores.get(3).loadQueues()).extracting(Stored::text).containsExactly("from the first");
        try (Connection c = schema.connect(); Statement st = c.createStatement();
             ResultSet rs = st.executeQuery("SELECT count(*) FROM information_schema.tables WHERE table_schema = '"
                     + schema.name + "' AND table_name LIKE 'ripv_%'")) {
            rs.next();
            assertThat(rs.getInt(1)).isEqualTo(5);
        }
        assertThat(stores.get(0).describe()).doesNotContain("password=" + System.getenv().getOrDefault("RIPV_PG_PASSWORD", "x"));
    }

    /** PostgreSQL: a connection the server drops (a restart, a cut) is replaced, and the transaction tried again. */
    @Test
    void postgresReplacesABrokenConnection() throws Exception {
        open(Kind.POSTGRES).close();
        StoreLocation tagged = new StoreLocation(schema.location().jdbcUrl() + "&ApplicationName=" + schema.name,
                schema.location().user(), schema.location().password());
        StateStore s = StateStores.open(tagged, dataDir, 8192);
        open.add(s);
        s.appendTranscript(List.of(line(T0, A, "before")));
        s.saveQueue(A, "one");
        int killed;
        try (Connection c = schema.connect(); Statement st = c.createStatement();
             ResultSet rs = st.executeQuery("SELECT count(pg_terminate_backend(pid)) FROM pg_stat_activity WHERE application_name = '"
                     + schema.name + "'")) {
            rs.next();
            killed = rs.getInt(1);
        }
        assertThat(killed).isGreaterThanOrEqualTo(1);
        s.appendTranscript(List.of(line(T0 + 1, A, "after")));
        s.saveQueue(A, "two");
        assertThat(texts(s.readTranscript(A, 0, 10, false))).containsExactly("before", "after");
        assertThat(s.loadQueues()).extracting(Stored::text).containsExactly("two");
    }

    /**
     * PostgreSQL with the rights docs/operations.md names: a user that may only read and write the
     * tables uses them once they exist; before, it is told why it cannot make them.
     */
    @Test
    void postgresNeedsCreateOnlyForTheFirstStart() throws Exception {
        open(Kind.POSTGRES).close(); // the tables, made by the admin
        String role = schema.name + "_dml";
        try (Connection c = schema.connect(); Statement st = c.createStatement()) {
            st.execute("CREATE ROLE " + role + " LOGIN PASSWORD 'dml-pass'");
            st.execute("GRANT USAGE ON SCHEMA " + schema.name + " TO " + role);
            st.execute("GRANT SELECT, INSERT, UPDATE, DELETE ON ALL TABLES IN SCHEMA " + schema.name + " TO " + role);
            st.execute("GRANT USAGE ON ALL SEQUENCES IN SCHEMA " + schema.name + " TO " + role);
        }
        try {
            StateStore s = StateStores.open(new StoreLocation(schema.location().jdbcUrl(), role, "dml-pass"), dataDir, 0);
            open.add(s);
            s.appendTranscript(List.of(line(T0, A, "by the writer")));
            s.saveQueue(A, "q");
            s.saveReceipt(A, "0000000000001-1-1.txt", "r", 10);
            s.appendAudit(List.of(new AuditRecord(T0, false, "login user=alice")));
            s.pruneTranscripts(LocalDate.parse("2020-01-01"));
            assertThat(texts(s.readTranscript(A, 0, 10, false))).containsExactly("by the writer");
            try (Connection c = schema.connect(); Statement st = c.createStatement()) {
                st.execute("DROP TABLE ripv_audit");
            }
            assertThatThrownBy(() -> StateStores.open(new StoreLocation(schema.location().jdbcUrl(), role, "dml-pass"), dataDir, 0))
                    .isInstanceOf(IOException.class).hasMessageContaining("cannot use the state database")
                    .hasMessageContaining("permission denied");
        } finally {
            open.forEach(StateStore::close);
            open.clear();
            try (Connection c = schema.connect(); Statement st = c.createStatement()) {
                st.execute("DROP OWNED BY " + role + " CASCADE");
                st.execute("DROP ROLE " + role);
            }
        }
    }

    @Test
    void anUnreachableDatabaseIsAClearErrorAndNoPasswordIsShown() {
        StoreLocation nowhere = new StoreLocation("jdbc:postgresql://127.0.0.1:1/ripv?password=hunter2", "ripv", "hunter2");
        assertThatThrownBy(() -> StateStores.open(nowhere, dataDir, 8192)).isInstanceOf(IOException.class)
                .hasMessageContaining("cannot use the state database jdbc:postgresql://127.0.0.1:1/ripv?password=***")
                .hasMessageNotContaining("hunter2");
        assertThat(nowhere.toString()).doesNotContain("hunter2");
        assertThatThrownBy(() -> new StoreLocation("jdbc:derby:memory:x", null, null)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("--state-db takes a PostgreSQL JDBC URL");
    }
}
