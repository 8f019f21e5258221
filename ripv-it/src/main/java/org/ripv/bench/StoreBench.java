package org.ripv.bench;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.Locale;
import java.util.Properties;
import java.util.concurrent.ThreadLocalRandom;
import org.ripv.messages.ConsoleEntry;
import org.ripv.server.session.Entries;
import org.ripv.server.session.Transcript;
import org.ripv.server.store.EmbeddedStateStore;
import org.ripv.server.store.StateStore;
import org.ripv.server.store.StateStores;
import org.ripv.server.store.StoreLocation;

/**
 * {@code ./ripv bench store [--entries N]}: transcript appends through the server's own path
 * ({@code Transcript}: a queue, one writer thread, batches of up to 4,096 entries into the state
 * store) into the embedded store's files and into PostgreSQL ({@code RIPV_PG_URL},
 * {@code RIPV_PG_USER}, {@code RIPV_PG_PASSWORD}; a schema of its own, dropped afterwards), against
 * the same run's baseline: the same rows inserted by direct JDBC, 4,096 per transaction with
 * batched multi-row inserts, into a bare table. Entries are offered in chunks of 50,000 and each
 * chunk waited for, so none is dropped (the count is checked).
 */
public final class StoreBench {
    private static final String BOX = "<SerialPortServer>::<bench>ru29";
    private static final int CHUNK = 50_000;

    private StoreBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int n = args.length >= 2 && args[0].equals("--entries") ? Integer.parseInt(args[1]) : 200_000;
        if (args.length > 0 && !(args.length == 2 && args[0].equals("--entries"))) {
            System.err.println("Usage: ripv bench store [--entries N]   (PostgreSQL from RIPV_PG_URL, RIPV_PG_USER, RIPV_PG_PASSWORD)");
            return 2;
        }
        Path dir = Files.createTempDirectory("ripv-store-bench");
        try (StateStore files = new EmbeddedStateStore(dir, 64L * 1024 * 1024)) {
            double rate = transcript(files, dir, n);
            report("embedded (files)", n, rate, files.readTranscript(BOX, 0, n + 1, false).lines().size() == n ? 1 : 0);
        }
        String url = System.getenv("RIPV_PG_URL");
        if (url == null || url.isBlank()) {
            System.out.println("PostgreSQL: skipped (set RIPV_PG_URL, RIPV_PG_USER, RIPV_PG_PASSWORD)");
            return 0;
        }
        Properties admin = new Properties();
        admin.setProperty("user", System.getenv().getOrDefault("RIPV_PG_USER", "postgres"));
        admin.setProperty("password", System.getenv().getOrDefault("RIPV_PG_PASSWORD", ""));
        String schema = "ripv_bench_" + Long.toString(ThreadLocalRandom.current().nextLong(1L << 40), 36).toLowerCase(Locale.ROOT);
        String schemaUrl = url + (url.contains("?") ? "&" : "?") + "currentSchema=" + schema;
        try (Connection c = DriverManager.getConnection(url, admin); Statement st = c.createStatement()) {
            st.execute("CREATE SCHEMA " + schema);
        }
        try {
            String pw = admin.getProperty("password");
            // Interleaved, best of two each: neither side pays alone for the JIT's warm-up or a busy moment.
            double jdbc = 0;
            double rate = 0;
            long stored = 0;
            try (StateStore pg = StateStores.open(new StoreLocation(schemaUrl, admin.getProperty("user"), pw.isEmpty() ? null : pw),
                    dir, 0)) {
                for (int run = 0; run < 2; run++) {
                    jdbc = Math.max(jdbc, jdbc(schemaUrl, admin, n));
                    rate = Math.max(rate, transcript(pg, dir, n));
                    try (Connection c = DriverManager.getConnection(schemaUrl, admin); Statement st = c.createStatement();
                         ResultSet rs = st.executeQuery("SELECT count(*) FROM ripv_transcript")) {
                        rs.next();
                        stored = rs.getLong(1);
                        st.execute("TRUNCATE ripv_transcript");
                    }
                    if (stored != n) {
                        break;
                    }
                }
            }
            System.out.printf(Locale.ROOT, "%-23s %,9.0f entries/s%n", "baseline, direct JDBC:", jdbc);
            report("PostgreSQL store", n, rate, stored == n ? 1 : 0);
            System.out.printf(Locale.ROOT, "PostgreSQL store / direct JDBC: %.2f (best of 2 each; %d cores, load average %.1f)%n",
                    rate / jdbc, Runtime.getRuntime().availableProcessors(),
                    ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        } finally {
            try (Connection c = DriverManager.getConnection(url, admin); Statement st = c.createStatement()) {
                st.execute("DROP SCHEMA IF EXISTS " + schema + " CASCADE");
            }
        }
        return 0;
    }

    private static void report(String what, int n, double rate, int ok) {
        System.out.printf(Locale.ROOT, "%-23s %,9.0f entries/s  (%,d entries%s)%n", what + ":", rate, n,
                ok > 0 ? ", all stored" : ", SOME MISSING");
    }

    private static ConsoleEntry entry(long t0, int i) {
        return new ConsoleEntry(t0 + i, BOX, ConsoleEntry.Kind.LINE, "", "behavior surface_2: SUBSTATE 2 ->3 : line " + i,
                null, null, null);
    }

    /** Entries per second through Transcript into {@code store}. */
    private static double transcript(StateStore store, Path dir, int n) throws Exception {
        long t0 = System.currentTimeMillis();
        try (Transcript t = new Transcript(dir.resolve("transcripts"), store, 90)) {
            long start = System.nanoTime();
            for (int i = 0; i < n; i++) {
                t.append(entry(t0, i));
                if ((i + 1) % CHUNK == 0) {
                    t.sync();
                }
            }
            t.sync();
            return n / ((System.nanoTime() - start) / 1e9);
        }
    }

    /** Entries per second by direct JDBC into a bare table of the same shape. */
    private static double jdbc(String url, Properties admin, int n) throws Exception {
        Properties p = new Properties();
        p.putAll(admin);
        p.setProperty("reWriteBatchedInserts", "true");
        long t0 = System.currentTimeMillis();
        try (Connection c = DriverManager.getConnection(url, p); Statement st = c.createStatement()) {
            st.execute("DROP TABLE IF EXISTS bare");
            st.execute("CREATE TABLE bare (seq BIGSERIAL PRIMARY KEY, mailbox TEXT NOT NULL, time_ms BIGINT NOT NULL, entry TEXT NOT NULL)");
            st.execute("CREATE INDEX ON bare (mailbox, seq)");
            st.execute("CREATE INDEX ON bare (time_ms)");
            c.setAutoCommit(false);
            long start = System.nanoTime();
            try (PreparedStatement ps = c.prepareStatement("INSERT INTO bare (mailbox, time_ms, entry) VALUES (?, ?, ?)")) {
                for (int i = 0; i < n; i++) {
                    ConsoleEntry e = entry(t0, i);
                    ps.setString(1, e.mailbox());
                    ps.setLong(2, e.time());
                    ps.setString(3, Entries.toJson(e));
                    ps.addBatch();
                    if ((i + 1) % 4096 == 0 || i == n - 1) {
                        ps.executeBatch();
                        c.commit();
                    }
                }
            }
            return n / ((System.nanoTime() - start) / 1e9);
        }
    }
}
