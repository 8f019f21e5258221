package org.ripv.bench;

import static org.ripv.bench.BenchTools.inScratchDirectory;
import static org.ripv.bench.BenchTools.intOption;
import static org.ripv.bench.BenchTools.median;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.ResultSetMetaData;
import java.sql.Statement;
import java.sql.Timestamp;
import java.time.Duration;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TablePages;
import org.ripv.messages.TableResult;
import org.ripv.server.RIPVServer;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;

/**
 * The DatabaseServer benchmark (issue 4; a measurement, not a timed test): one query of
 * 100,000 rows, three ways, in the same run and on the same embedded Derby database:
 * <ol>
 *   <li><b>direct JDBC</b>: execute, walk the forward-only cursor, read every cell as text;</li>
 *   <li><b>service</b>: the same SQL handed to the DatabaseServer in-process
 *       ({@code accept} → MailBox → handler → {@link TableResult});</li>
 *   <li><b>end to end</b>: a real client over a socket → RIPVServer → RMI → DatabaseServer →
 *       Derby → RMI → server → socket → client, until the client holds the table.</li>
 * </ol>
 * Each path's time ends once every cell of its rows has been taken from the table: the client
 * keeps a query's pages packed until a row of them is read.
 * Prints the medians, the ratio to direct JDBC, the whole process's mean CPU per query and its ratio ({@link CpuClock}), the table's serialized size (it must fit one
 * 16 MiB socket frame) and the heap's peak. Run:
 * <pre>
 * mvn -q -B -DskipTests package -pl ripv-it -am
 * java -Xmx1g -cp ripv-it/target/ripv-it.jar org.ripv.bench.DatabaseBench [--rows 100000] [--runs 5]
 * </pre>
 */
public final class DatabaseBench {
    private static final String MAILBOX = "TTY1";

    private DatabaseBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int rows = intOption(args, "--rows", 100_000);
        int runs = intOption(args, "--runs", 5);
        int warmups = intOption(args, "--warmup", 2);
        inScratchDirectory("ripv-dbbench", dir -> run(dir, rows, runs, warmups));
        return 0; // RMI and the server's threads are non-daemon
    }

    private static void run(Path dir, int rows, int runs, int warmups) throws Exception {
        DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), MAILBOX);
        fill(db, rows);
        String sql = "SELECT leg_id, sensor_id, t, value, raw_value FROM bench_readings";
        QueryLimits limits = new QueryLimits(rows, 600, 64L * 1024 * 1024);
        System.out.printf(Locale.ROOT, "DatabaseBench: %,d rows of (INTEGER, INTEGER, TIMESTAMP, DOUBLE, DOUBLE), %d runs after %d warm-ups, %s%n",
                rows, runs, warmups, System.getProperty("java.vm.name") + " " + System.getProperty("java.version"));

        // All three paths are set up first and then measured in turn, round after round, so
        // that JIT warm-up and the load of a shared machine fall on all of them alike.
        double[] direct = new double[runs];
        double[] inProcess = new double[runs];
        double[] endToEnd = new double[runs];
        // time to the first row each path hands over (issue 38: the rows come in pages)
        double[] directFirst = new double[runs];
        double[] inProcessFirst = new double[runs];
        double[] endToEndFirst = new double[runs];
        AtomicLong firstPage = new AtomicLong();
        long[] cpu = new long[3]; // CPU nanoseconds of the whole process per path, over the measured runs
        double[] directCpu = new double[runs]; // the same per round, ms: how far one round strays
        double[] endToEndCpu = new double[runs];
        long serialized = 0;
        Map<String, Double> breakdown = Map.of();
        double allocated = -1;

        // 2. a service of its own, not connected to a server, for the in-process path
        DatabaseServer local = new DatabaseServer("localhost", List.of(db), limits);
        local.start();
        BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
        local.replyTo(replies::add);
        String localMailbox = local.name().mailbox(MAILBOX).toString();

        // 3. a real server, the service registered over RMI, a client on a socket
        RIPVServer server = BenchTools.serverWithOperator(dir.resolve("server"));
        DatabaseServer service = new DatabaseServer("localhost", List.of(db), limits);
        ServiceConnector connector = ServiceConnector.connect(service, new ServiceOptions("localhost", server.registryPort(),
                Files.readString(server.secretFile()).trim(), 0, Duration.ofSeconds(1)));
        resetPeaks();
        try (Connection c = DriverManager.getConnection(db.url(), db.user(), db.password());
             ClientSocketHandler client = ClientSocketHandler.connect("localhost", server.port())) {
            if (!connector.awaitRegistered(Duration.ofSeconds(30))) {
                throw new IllegalStateException("the DatabaseServer did not register");
            }
            client.login(BenchTools.USER, BenchTools.PASSWORD.toCharArray());
            client.addListener(new ClientSocketHandler.Listener() {
                @Override
                public void onReply(OutgoingServerMessage reply) {
                    firstPage.compareAndSet(0, System.nanoTime()); // a result small enough for one reply
                }

                @Override
                public void onPage(OutgoingServerMessage page) {
                    firstPage.compareAndSet(0, System.nanoTime());
                }
            });
            String mailbox = service.name().mailbox(MAILBOX).toString();
            for (int i = -warmups; i < runs; i++) {
                long c0 = CpuClock.processCpuNanos();
                long t0 = System.nanoTime();
                long[] firstRow = new long[1];
                check(directQuery(c, sql, firstRow), rows);
                long directFirstRow = firstRow[0];
                long t1 = System.nanoTime();
                long c1 = CpuClock.processCpuNanos();
                TableResult t = inProcess(local, localMailbox, sql, replies, firstRow);
                check(read(t.rows()), rows);
                long t2 = System.nanoTime();
                long c2 = CpuClock.processCpuNanos();
                long inProcessFirstRow = firstRow[0];
                t = null;
                firstPage.set(0);
                OutgoingServerMessage r = client.call(mailbox, sql, Priority.NORMAL, Duration.ofMinutes(5), null);
                if (r.status() != Status.OK) {
                    throw new IllegalStateException("end to end failed: " + r.footer().replyText());
                }
                TableResult e = (TableResult) r.footer().result();
                check(read(e.rows()), rows);
                long t3 = System.nanoTime();
                long c3 = CpuClock.processCpuNanos();
                if (i >= 0) {
                    direct[i] = (t1 - t0) / 1e6;
                    inProcess[i] = (t2 - t1) / 1e6;
                    endToEnd[i] = (t3 - t2) / 1e6;
                    directFirst[i] = (directFirstRow - t0) / 1e6;
                    inProcessFirst[i] = (inProcessFirstRow - t1) / 1e6;
                    endToEndFirst[i] = (firstPage.get() - t2) / 1e6;
                    cpu[0] += c1 - c0;
                    cpu[1] += c2 - c1;
                    cpu[2] += c3 - c2;
                    directCpu[i] = (c1 - c0) / 1e6;
                    endToEndCpu[i] = (c3 - c2) / 1e6;
                } else {
                    serialized = serializedSize(e);
                }
            }
            // Where an end-to-end query's CPU goes, by kind of thread: more queries of that path
            // alone, outside the figures above (reading every thread's clock costs CPU itself).
            CpuClock where = CpuClock.start();
            for (int i = 0; i < runs; i++) {
                OutgoingServerMessage r = client.call(mailbox, sql, Priority.NORMAL, Duration.ofMinutes(5), null);
                check(read(((TableResult) r.footer().result()).rows()), rows);
            }
            breakdown = where.microsPerThreadKind(runs);
            allocated = where.bytesAllocatedPer(runs);
        } finally {
            connector.close();
            service.stop();
            server.stop();
            local.stop();
        }
        long peakHeap = peakHeap();

        double d = median(direct);
        double s = median(inProcess);
        double e = median(endToEnd);
        double[] cpuMs = {cpu[0] / 1e6 / runs, cpu[1] / 1e6 / runs, cpu[2] / 1e6 / runs};
        System.out.println(CpuClock.machineLine());
        System.out.printf(Locale.ROOT, "%-40s %10s %14s %8s %12s %9s%n", "path", "median ms", "rows/s", "ratio", "cpu ms/query", "cpu ratio");
        line("direct JDBC (read every cell as text)", d, rows, d, cpuMs[0], cpuMs[0]);
        line("service in-process (accept -> TableResult)", s, rows, d, cpuMs[1], cpuMs[0]);
        line("end to end (client -> server -> RMI -> service)", e, rows, d, cpuMs[2], cpuMs[0]);
        System.out.println(CpuClock.ratioLine("end to end", cpuMs[2] * 1e3, cpuMs[0] * 1e3, e / d));
        System.out.printf(Locale.ROOT, "first row, median ms: direct JDBC %.1f; service in-process %.1f; end to end %.1f"
                + " (the rows travel in pages: %d rows first, then pages twice as large, up to 512 Ki characters)%n",
                median(directFirst), median(inProcessFirst), median(endToEndFirst), 100);
        System.out.printf(Locale.ROOT, "the whole TableResult serialized: %,d bytes (%.1f MiB); it travels in pages, none larger than about 1 MiB%n",
                serialized, serialized / 1048576.0);
        System.out.printf(Locale.ROOT, "peak heap during service and end-to-end runs (server, service and client in one JVM): %,d MiB of %,d MiB%n",
                peakHeap >> 20, Runtime.getRuntime().maxMemory() >> 20);
        System.out.printf(Locale.ROOT, "where the end-to-end CPU goes, ms per query (%d more queries of that path alone, %.0f MiB allocated per query;"
                + " the service's inbox reads the cursor, its outbox sends the pages over RMI, RMI TCP Connection is the"
                + " server taking them, ripv-socket-writer the server's TLS socket, ripv-client-reader the client):%n", runs,
                allocated / 1048576.0);
        breakdown.forEach((kind, micros) -> {
            if (micros >= 500) {
                System.out.printf(Locale.ROOT, "  %8.1f  %s%n", micros / 1e3, kind);
            }
        });
        System.out.printf(Locale.ROOT, "raw: direct %s; service %s; end to end %s; end to end, first row %s%n", Arrays.toString(direct),
                Arrays.toString(inProcess), Arrays.toString(endToEnd), Arrays.toString(endToEndFirst));
        System.out.printf(Locale.ROOT, "raw CPU ms per round: direct %s; end to end %s%n", Arrays.toString(directCpu),
                Arrays.toString(endToEndCpu));
    }

    /** The same work as the handler minus the service: the cursor read into String rows. */
    private static int directQuery(Connection c, String sql, long[] firstRow) throws Exception {
        try (Statement st = c.createStatement(ResultSet.TYPE_FORWARD_ONLY, ResultSet.CONCUR_READ_ONLY);
             ResultSet rs = st.executeQuery(sql)) {
            ResultSetMetaData md = rs.getMetaData();
            int n = md.getColumnCount();
            List<String[]> out = new ArrayList<>();
            firstRow[0] = 0;
            while (rs.next()) {
                if (firstRow[0] == 0) {
                    firstRow[0] = System.nanoTime();
                }
                String[] row = new String[n];
                for (int i = 0; i < n; i++) {
                    row[i] = rs.getString(i + 1);
                }
                out.add(row);
            }
            return read(out);
        }
    }

    /** The service in-process: its pages joined as a client joins them; {@code firstRow[0]} when the first rows came. */
    private static TableResult inProcess(DatabaseServer service, String mailbox, String sql,
                                         BlockingQueue<OutgoingServiceMessage> replies, long[] firstRow) throws Exception {
        service.accept(new IncomingServiceMessage(new Header(1, new IdBadge("123456", "bench"), List.of(),
                service.name().toString(), mailbox, sql, Priority.NORMAL, null)));
        TablePages pages = new TablePages();
        firstRow[0] = 0;
        while (true) {
            OutgoingServiceMessage r = replies.poll(5, TimeUnit.MINUTES);
            if (firstRow[0] == 0) {
                firstRow[0] = System.nanoTime();
            }
            if (r != null && TablePages.isPage(r.footer())) {
                pages.add((TableResult) r.footer().result());
                continue;
            }
            if (r == null || r.status() != Status.OK) {
                throw new IllegalStateException("service failed: " + (r == null ? "no reply" : r.footer().replyText()));
            }
            return pages.join((TableResult) r.footer().result());
        }
    }

    /**
     * Takes every cell of the rows a path handed over, as their user would (a client holds a
     * query's pages packed until a row of them is read: TablePages), the same for all three paths;
     * the number of rows. It looks at each cell's reference only, not at its text, so that it adds
     * to the floor no more than the least a reader of the rows does.
     */
    private static int read(List<String[]> rows) {
        long cells = 0;
        int n = 0;
        for (String[] row : rows) {
            for (String cell : row) {
                if (cell != null) {
                    cells++;
                }
            }
            n++;
        }
        if (cells == 0 && n > 0) {
            throw new IllegalStateException("rows without values");
        }
        return n;
    }

    private static void fill(DatabaseTarget db, int rows) throws Exception {
        try (Connection c = DriverManager.getConnection(db.url(), db.user(), db.password())) {
            c.setAutoCommit(false);
            try (Statement st = c.createStatement()) {
                st.execute("CREATE TABLE bench_readings (leg_id INTEGER NOT NULL, sensor_id INTEGER NOT NULL,"
                        + " t TIMESTAMP NOT NULL, value DOUBLE PRECISION NOT NULL, raw_value DOUBLE PRECISION NOT NULL)");
                // The in-process path asks with no roles, so it reads as the reader (DatabaseHandler.readsOnly),
                // which holds SELECT only on what it is granted, like the six seeded tables.
                st.execute("GRANT SELECT ON bench_readings TO " + db.readerUser());
            }
            LocalDateTime start = LocalDateTime.of(2002, 4, 2, 13, 0);
            try (PreparedStatement ps = c.prepareStatement("INSERT INTO bench_readings VALUES (?, ?, ?, ?, ?)")) {
                for (int i = 0; i < rows; i++) {
                    ps.setInt(1, 1 + i / 10_000);
                    ps.setInt(2, 1 + i % 3);
                    ps.setTimestamp(3, Timestamp.valueOf(start.plusSeconds(80L * (i / 3))));
                    double v = 20.5 - (i % 997) * 0.0025;
                    ps.setDouble(4, v);
                    ps.setDouble(5, 2800 + 165 * v);
                    ps.addBatch();
                    if (i % 5000 == 4999) {
                        ps.executeBatch();
                    }
                }
                ps.executeBatch();
            }
            c.commit();
        }
    }

    private static long serializedSize(TableResult t) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream(8 << 20);
        try (ObjectOutputStream out = new ObjectOutputStream(b)) {
            out.writeObject(t);
        }
        return b.size();
    }

    private static void resetPeaks() {
        System.gc();
        for (MemoryPoolMXBean p : ManagementFactory.getMemoryPoolMXBeans()) {
            if (p.getType() == MemoryType.HEAP) {
                p.resetPeakUsage();
            }
        }
    }

    private static long peakHeap() {
        long sum = 0;
        for (MemoryPoolMXBean p : ManagementFactory.getMemoryPoolMXBeans()) {
            if (p.getType() == MemoryType.HEAP) {
                sum += p.getPeakUsage().getUsed();
            }
        }
        return sum;
    }

    private static void line(String what, double ms, int rows, double base, double cpuMs, double cpuBase) {
        System.out.printf(Locale.ROOT, "%-40s %10.1f %,14.0f %7.2fx %12.1f %8.2fx%n", what, ms, rows / (ms / 1000), ms / base,
                cpuMs, cpuMs / cpuBase);
    }

    private static void check(int got, int want) {
        if (got != want) {
            throw new IllegalStateException("expected " + want + " rows, got " + got);
        }
    }
}
