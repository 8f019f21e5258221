package org.ripv.server.store;

import java.io.IOException;
import java.sql.BatchUpdateException;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.Properties;

/**
 * The state in PostgreSQL tables, so that it outlives the server's host and a standby server can
 * take over (docs/operations.md, "The state store"). The tables are made on first use (in the
 * URL's {@code currentSchema}, else {@code public}), under an advisory lock so that two servers
 * starting at once do not race. Every change is one transaction; a transcript batch is one
 * multi-row insert.
 * <pre>
 * ripv_transcript(seq, mailbox, time_ms, entry)    transcripts, in append order
 * ripv_document(kind, mailbox, body)               workflow queues, fetched-file lists, subscriptions
 * ripv_receipt(mailbox, name, body)                receipts
 * ripv_audit(seq, time_ms, warn, line)             the audit trail
 * ripv_surfacing(seq, mailbox, time_ms, record)    call records, one per surfacing
 * </pre>
 *
 * <p>Longer than 400 lines for one job: it is {@link StateStore} in PostgreSQL, one short method per kind
 * of record over the tables above.
 */
public final class PostgresStateStore implements StateStore {
    /** The advisory lock key that guards schema creation ("RIPV" in ASCII). */
    static final long SCHEMA_LOCK = 0x52495056L;
    private static final String QUEUE = "queue";
    private static final String FETCHED = "fetched";
    private static final String VEHICLE_STATE = "vehicle-state";
    private static final String SUBSCRIPTIONS = "subscriptions";

    private static final String[] SCHEMA = {
        "CREATE TABLE IF NOT EXISTS ripv_transcript (seq BIGSERIAL PRIMARY KEY, mailbox TEXT NOT NULL,"
                + " time_ms BIGINT NOT NULL, entry TEXT NOT NULL)",
        "CREATE INDEX IF NOT EXISTS ripv_transcript_mailbox ON ripv_transcript (mailbox, seq)",
        "CREATE INDEX IF NOT EXISTS ripv_transcript_time ON ripv_transcript (time_ms)",
        "CREATE TABLE IF NOT EXISTS ripv_document (kind TEXT NOT NULL, mailbox TEXT NOT NULL, body TEXT NOT NULL,"
                + " updated TIMESTAMPTZ NOT NULL DEFAULT now(), PRIMARY KEY (kind, mailbox))",
        "CREATE TABLE IF NOT EXISTS ripv_receipt (mailbox TEXT NOT NULL, name TEXT NOT NULL, body TEXT NOT NULL,"
                + " PRIMARY KEY (mailbox, name))",
        "CREATE TABLE IF NOT EXISTS ripv_audit (seq BIGSERIAL PRIMARY KEY, time_ms BIGINT NOT NULL, warn BOOLEAN NOT NULL,"
                + " line TEXT NOT NULL)",
        "CREATE TABLE IF NOT EXISTS ripv_surfacing (seq BIGSERIAL PRIMARY KEY, mailbox TEXT NOT NULL, time_ms BIGINT NOT NULL,"
                + " record TEXT NOT NULL)",
        "CREATE INDEX IF NOT EXISTS ripv_surfacing_mailbox ON ripv_surfacing (mailbox, seq)",
    };

    private final PgConnections db;

    private PostgresStateStore(PgConnections db) {
        this.db = db;
    }

    /**
     * Connects, and makes the tables when they are missing.
     *
     * @throws IOException when the database cannot be reached or the user may not create the tables
     */
    public static PostgresStateStore open(StoreLocation where) throws IOException {
        if (where.isEmbedded()) {
            throw new IllegalArgumentException("no JDBC URL");
        }
        Properties props = new Properties();
        if (where.user() != null) {
            props.setProperty("user", where.user());
        }
        if (where.password() != null) {
            props.setProperty("password", where.password());
        }
        props.setProperty("reWriteBatchedInserts", "true"); // a transcript batch becomes a few multi-row inserts
        props.setProperty("connectTimeout", "5");
        props.setProperty("socketTimeout", "30");
        props.setProperty("tcpKeepAlive", "true");
        props.setProperty("ApplicationName", "RIPVServer");
        PgConnections db = new PgConnections(where.jdbcUrl(), props, 4);
        PostgresStateStore store = new PostgresStateStore(db);
        try {
            db.transaction(c -> {
                try (Statement st = c.createStatement()) {
                    if (schemaPresent(st)) {
                        return null; // a user with rights on the tables only need not be allowed to create
                    }
                    st.execute("SELECT pg_advisory_xact_lock(" + SCHEMA_LOCK + ")");
                    for (String sql : SCHEMA) {
                        st.execute(sql);
                    }
                }
                return null;
            });
        } catch (SQLException e) {
            db.close();
            throw new IOException("cannot use the state database " + store.describe() + ": " + e.getMessage(), e);
        }
        return store;
    }

    /** Whether every table and index is there already (in the URL's schema, else public). */
    private static boolean schemaPresent(Statement st) throws SQLException {
        StringBuilder q = new StringBuilder("SELECT true");
        for (String name : new String[] {"ripv_transcript", "ripv_transcript_mailbox", "ripv_transcript_time", "ripv_document",
            "ripv_receipt", "ripv_audit", "ripv_surfacing", "ripv_surfacing_mailbox"}) {
            q.append(" AND to_regclass('").append(name).append("') IS NOT NULL");
        }
        try (ResultSet rs = st.executeQuery(q.toString())) {
            return rs.next() && rs.getBoolean(1);
        }
    }

    /**
     * A connection of its own to the state database, outside the store's transactions (for a
     * session advisory lock held for as long as the connection lives, as a standby needs). The
     * caller closes it.
     */
    public Connection openConnection() throws SQLException {
        return db.open();
    }

    /** A JDBC URL with any password parameter blanked, for messages. */
    static String withoutSecrets(String jdbcUrl) {
        return jdbcUrl == null ? null : jdbcUrl.replaceAll("(?i)(password=)[^&]*", "$1***");
    }

    /** PostgreSQL text cannot hold NUL; a stored text never needs one. */
    private static String text(String s) {
        return s == null || s.indexOf(0) < 0 ? s : s.replace((char) 0, (char) 0xFFFD);
    }

    /** Deletes a MailBox's rows but its newest: {@code sql} takes the MailBox twice, then the offset. */
    private static void keepNewest(Connection c, String sql, String mailbox, int offset) throws SQLException {
        try (PreparedStatement ps = c.prepareStatement(sql)) {
            ps.setString(1, text(mailbox));
            ps.setString(2, text(mailbox));
            ps.setInt(3, Math.max(0, offset));
            ps.executeUpdate();
        }
    }

    /** A MailBox's newest {@code n} texts, oldest first: {@code sql} takes the MailBox and n, newest first. */
    private static List<String> lastOf(Connection c, String sql, String mailbox, int n) throws SQLException {
        List<String> out = new ArrayList<>();
        try (PreparedStatement ps = c.prepareStatement(sql)) {
            ps.setString(1, text(mailbox));
            ps.setInt(2, Math.max(0, n));
            try (ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    out.add(rs.getString(1));
                }
            }
        }
        Collections.reverse(out);
        return out;
    }

    /** Sets one row's parameters. */
    @FunctionalInterface
    private interface Row<T> {
        void bind(PreparedStatement ps, T item) throws SQLException;
    }

    /** Inserts every item as a row, in one batch (nothing for none). */
    private <T> void insertAll(String what, String sql, List<T> items, Row<T> row) throws IOException {
        if (items.isEmpty()) {
            return;
        }
        run(what, c -> {
            try (PreparedStatement ps = c.prepareStatement(sql)) {
                for (T item : items) {
                    row.bind(ps, item);
                    ps.addBatch();
                }
                ps.executeBatch();
            }
            return null;
        });
    }

    private <T> T run(String what, PgConnections.Work<T> work) throws IOException {
        try {
            return db.transaction(work);
        } catch (SQLException e) {
            throw new IOException("state database " + describe() + ": could not " + what + ": " + reason(e), e);
        }
    }

    /**
     * What went wrong, short: a failed batch's own message repeats every row's values (transcript
     * text, in the log), so its first cause stands for it.
     */
    static String reason(SQLException e) {
        SQLException cause = e instanceof BatchUpdateException && e.getNextException() != null ? e.getNextException() : e;
        String m = String.valueOf(cause.getMessage());
        return (m.length() > 300 ? m.substring(0, 300) + "..." : m) + (cause.getSQLState() == null ? "" : " (SQLSTATE " + cause.getSQLState() + ")");
    }

    // ---- transcripts ----

    @Override
    public void appendTranscript(List<TranscriptLine> lines) throws IOException {
        insertAll("append " + lines.size() + " transcript lines", "INSERT INTO ripv_transcript (mailbox, time_ms, entry) VALUES (?, ?, ?)",
                lines, (ps, l) -> {
                    ps.setString(1, text(l.mailbox()));
                    ps.setLong(2, l.time());
                    ps.setString(3, text(l.json()));
                });
    }

    @Override
    public TranscriptPage readTranscript(String mailbox, long sinceMillis, int limit, boolean newest) throws IOException {
        int n = Math.max(1, limit);
        return run("read the transcript of " + mailbox, c -> {
            List<String> out = new ArrayList<>();
            try (PreparedStatement ps = c.prepareStatement("SELECT entry FROM ripv_transcript WHERE mailbox = ? AND time_ms >= ?"
                    + " ORDER BY seq " + (newest ? "DESC" : "ASC") + " LIMIT ?")) {
                ps.setString(1, text(mailbox));
                ps.setLong(2, sinceMillis);
                ps.setInt(3, n + 1);
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        out.add(rs.getString(1));
                    }
                }
            }
            boolean more = out.size() > n;
            if (more) {
                out.remove(out.size() - 1);
            }
            if (newest) {
                Collections.reverse(out);
            }
            return new TranscriptPage(List.copyOf(out), more, 0);
        });
    }

    @Override
    public void pruneTranscripts(LocalDate oldestKept) throws IOException {
        long before = oldestKept.atStartOfDay(ZoneOffset.UTC).toInstant().toEpochMilli();
        run("prune transcripts", c -> {
            try (PreparedStatement ps = c.prepareStatement("DELETE FROM ripv_transcript WHERE time_ms < ?")) {
                ps.setLong(1, before);
                return ps.executeUpdate();
            }
        });
    }

    // ---- documents: queues, fetched lists, subscriptions ----

    private void saveDocument(String kind, String mailbox, String body) throws IOException {
        run("save the " + kind + " of " + mailbox, c -> {
            try (PreparedStatement ps = c.prepareStatement("INSERT INTO ripv_document (kind, mailbox, body) VALUES (?, ?, ?)"
                    + " ON CONFLICT (kind, mailbox) DO UPDATE SET body = EXCLUDED.body, updated = now()")) {
                ps.setString(1, kind);
                ps.setString(2, text(mailbox));
                ps.setString(3, text(body));
                return ps.executeUpdate();
            }
        });
    }

    private List<Stored> loadDocuments(String kind, String mailbox) throws IOException {
        return run("read the " + kind + " documents", c -> {
            List<Stored> out = new ArrayList<>();
            try (PreparedStatement ps = c.prepareStatement("SELECT mailbox, body FROM ripv_document WHERE kind = ?"
                    + (mailbox == null ? "" : " AND mailbox = ?") + " ORDER BY mailbox")) {
                ps.setString(1, kind);
                if (mailbox != null) {
                    ps.setString(2, text(mailbox));
                }
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        out.add(new Stored("ripv_document " + kind + " '" + rs.getString(1) + "' in " + describe(), rs.getString(2)));
                    }
                }
            }
            return out;
        });
    }

    @Override
    public void saveQueue(String mailbox, String document) throws IOException {
        saveDocument(QUEUE, mailbox, document);
    }

    @Override
    public List<Stored> loadQueues() throws IOException {
        return loadDocuments(QUEUE, null);
    }

    @Override
    public void saveVehicleState(String mailbox, String json) throws IOException {
        saveDocument(VEHICLE_STATE, mailbox, json);
    }

    @Override
    public Optional<String> loadVehicleState(String mailbox) throws IOException {
        return loadDocuments(VEHICLE_STATE, mailbox).stream().findFirst().map(Stored::text);
    }

    @Override
    public void saveFetched(String mailbox, String document) throws IOException {
        saveDocument(FETCHED, mailbox, document);
    }

    @Override
    public Optional<String> loadFetched(String mailbox) throws IOException {
        return loadDocuments(FETCHED, mailbox).stream().findFirst().map(Stored::text);
    }

    @Override
    public void saveSubscriptions(String document) throws IOException {
        saveDocument(SUBSCRIPTIONS, "", document);
    }

    @Override
    public Optional<Stored> loadSubscriptions() throws IOException {
        return loadDocuments(SUBSCRIPTIONS, "").stream().findFirst();
    }

    // ---- call records ----

    @Override
    public void appendSurfacing(String mailbox, long time, String json, int keep) throws IOException {
        run("keep a call record of " + mailbox, c -> {
            try (PreparedStatement ps = c.prepareStatement("INSERT INTO ripv_surfacing (mailbox, time_ms, record) VALUES (?, ?, ?)")) {
                ps.setString(1, text(mailbox));
                ps.setLong(2, time);
                ps.setString(3, text(json));
                ps.executeUpdate();
            }
            keepNewest(c, "DELETE FROM ripv_surfacing WHERE mailbox = ? AND seq <"
                    + " (SELECT seq FROM ripv_surfacing WHERE mailbox = ? ORDER BY seq DESC OFFSET ? LIMIT 1)", mailbox, keep - 1);
            return null;
        });
    }

    @Override
    public List<String> lastSurfacings(String mailbox, int n) throws IOException {
        return run("read the call records of " + mailbox,
                c -> lastOf(c, "SELECT record FROM ripv_surfacing WHERE mailbox = ? ORDER BY seq DESC LIMIT ?", mailbox, n));
    }

    @Override
    public List<String> surfacingMailboxes() throws IOException {
        return run("list the MailBoxes with call records", c -> {
            List<String> out = new ArrayList<>();
            try (PreparedStatement ps = c.prepareStatement("SELECT DISTINCT mailbox FROM ripv_surfacing");
                 ResultSet rs = ps.executeQuery()) {
                while (rs.next()) {
                    out.add(rs.getString(1));
                }
            }
            return out;
        });
    }

    // ---- receipts ----

    @Override
    public void saveReceipt(String mailbox, String name, String text, int keep) throws IOException {
        run("save a receipt of " + mailbox, c -> {
            try (PreparedStatement ps = c.prepareStatement("INSERT INTO ripv_receipt (mailbox, name, body) VALUES (?, ?, ?)"
                    + " ON CONFLICT (mailbox, name) DO UPDATE SET body = EXCLUDED.body")) {
                ps.setString(1, text(mailbox));
                ps.setString(2, text(name));
                ps.setString(3, text(text));
                ps.executeUpdate();
            }
            keepNewest(c, "DELETE FROM ripv_receipt WHERE mailbox = ? AND name IN"
                    + " (SELECT name FROM ripv_receipt WHERE mailbox = ? ORDER BY name DESC OFFSET ?)", mailbox, keep);
            return null;
        });
    }

    @Override
    public List<String> lastReceipts(String mailbox, int n) throws IOException {
        return run("read the receipts of " + mailbox,
                c -> lastOf(c, "SELECT body FROM ripv_receipt WHERE mailbox = ? ORDER BY name DESC LIMIT ?", mailbox, n));
    }

    // ---- audit trail ----

    @Override
    public void appendAudit(List<AuditRecord> records) throws IOException {
        insertAll("append to the audit trail", "INSERT INTO ripv_audit (time_ms, warn, line) VALUES (?, ?, ?)", records, (ps, r) -> {
            ps.setLong(1, r.time());
            ps.setBoolean(2, r.warn());
            ps.setString(3, text(r.line()));
        });
    }

    @Override
    public List<AuditRecord> readAudit(long sinceMillis, int last) throws IOException {
        return run("read the audit trail", c -> {
            List<AuditRecord> out = new ArrayList<>();
            try (PreparedStatement ps = c.prepareStatement("SELECT time_ms, warn, line FROM ripv_audit WHERE time_ms >= ?"
                    + " ORDER BY seq DESC LIMIT ?")) {
                ps.setLong(1, sinceMillis);
                ps.setInt(2, Math.max(0, last));
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        out.add(new AuditRecord(rs.getLong(1), rs.getBoolean(2), rs.getString(3)));
                    }
                }
            }
            Collections.reverse(out);
            return out;
        });
    }

    @Override
    public String describe() {
        return withoutSecrets(db.url());
    }

    @Override
    public void close() {
        db.close();
    }
}
