package org.ripv.bench;

import static org.ripv.bench.BenchTools.inScratchDirectory;
import static org.ripv.bench.BenchTools.intOption;
import static org.ripv.bench.BenchTools.median;
import static org.ripv.bench.BenchTools.stringOption;

import com.sun.management.OperatingSystemMXBean;
import java.io.ByteArrayInputStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.Statement;
import java.sql.Timestamp;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Calendar;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TimeZone;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.RIPVServer;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import org.ripv.services.bench.SyntheticDba;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.ingest.DbaIngest;
import org.ripv.services.ingest.DbaReader;

/**
 * {@code ./ripv bench ingest} (issue 13; a measurement, not a timed test), on embedded Derby:
 * <ol>
 *   <li>{@code ingest} of a 1.2 MB, 2,136-sensor DBA file and of a 100,000-row, 30-sensor one
 *       through the DatabaseServer in-process (attachment, strict parse, SHA-256, sensors, batch
 *       inserts, commit), in values stored per second, against <b>direct JDBC</b>: the same
 *       values, parsed beforehand, batch-inserted into the same schema in one transaction;</li>
 *   <li>{@code vis:track} of 100,000 positions end to end: client socket → RIPVServer → RMI →
 *       DatabaseServer query → server → RMI → DataVisServer built-in worker → JPEG back at the client.</li>
 * </ol>
 * Options: {@code --runs N} (default 2, of the 100,000-row file), {@code --wide-runs N} (default 7: a run of the
 * 2,136-sensor file takes about a second, and a median of two is at the mercy of a shared machine),
 * {@code --track-runs N} (default 3), {@code --rows N} (rows of the long file and positions of the track, default
 * 100,000), {@code --wide-sensors N} (sensors of the wide file, default 2,136, as a real glider's; {@code --short}
 * takes fewer: the same path, a smaller file), {@code --only wide|long|track}
 * (one part; {@code --track-only} is {@code --only track}).
 */
public final class IngestBench {
    private static final Calendar UTC = Calendar.getInstance(TimeZone.getTimeZone("UTC"));

    private IngestBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int runs = intOption(args, "--runs", 2);
        int wideRuns = intOption(args, "--wide-runs", Math.max(runs, 7));
        int trackRuns = intOption(args, "--track-runs", 3);
        int rows = intOption(args, "--rows", 100_000);
        int wideSensors = intOption(args, "--wide-sensors", 2136);
        if (wideSensors < 4 || wideSensors > 10_000) {
            throw new IllegalArgumentException("--wide-sensors must be 4 to 10000 (time, position and depth come first), not " + wideSensors);
        }
        String only = Arrays.asList(args).contains("--track-only") ? "track" : stringOption(args, "--only", "all");
        if (!List.of("all", "wide", "long", "track").contains(only)) {
            throw new IllegalArgumentException("--only wide, long or track, not " + only);
        }
        inScratchDirectory("ripv-ingestbench", dir -> {
            if (only.equals("track")) {
                DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1");
                track(dir, db, new QueryLimits(200_000, 600, 64L * 1024 * 1024), trackRuns, rows);
            } else {
                run(dir, runs, wideRuns, trackRuns, only, rows, wideSensors);
            }
        });
        return 0;
    }

    private static void run(Path dir, int runs, int wideRuns, int trackRuns, String only, int rows, int wideSensors)
            throws Exception {
        DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1");
        QueryLimits limits = new QueryLimits(200_000, 600, 64L * 1024 * 1024);
        DatabaseServer local = new DatabaseServer("localhost", List.of(db), limits);
        local.start();
        BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
        local.replyTo(replies::add);
        System.out.printf(Locale.ROOT, "IngestBench: embedded Derby, %d run(s) of the wide file, %d of the long one, %s%n",
                wideRuns, runs,
                System.getProperty("java.vm.name") + " " + System.getProperty("java.version"));
        byte[] wide = only.equals("long") ? null : SyntheticDba.generate("wide", wideSensors, 140, 0.03, false, 1);
        byte[] long30 = only.equals("wide") ? null : SyntheticDba.generate("long", 30, rows, 0.5, false, 2);
        System.out.printf(Locale.ROOT, "%-34s %9s %10s %10s %12s %7s%n", "file", "values", "ingest ms", "direct ms",
                "ingest v/s", "ratio");
        try (Connection c = DriverManager.getConnection(db.url(), db.user(), db.password())) {
            // creates the schema too; no larger than the measured file (--short runs 500 rows)
            ingest(local, replies, "warm-up.mrg", SyntheticDba.generate("warmup", 40, Math.min(2000, rows), 0.5, false, 3));
            clear(c);
            if (wide != null) {
                measure(c, local, replies, String.format(Locale.ROOT, "%,d sensors, %.2f MB", wideSensors, wide.length / 1e6),
                        wide, wideRuns);
            }
            if (long30 != null) {
                measure(c, local, replies, String.format(Locale.ROOT, "30 sensors, %,d rows", rows), long30, runs);
            }
        } finally {
            local.stop();
        }
        if (only.equals("all")) {
            track(dir, db, limits, trackRuns, rows);
        }
    }

    private static void measure(Connection c, DatabaseServer local, BlockingQueue<OutgoingServiceMessage> replies,
                                String what, byte[] file, int runs) throws Exception {
        measure(c, local, replies, what, file, ".mrg", file, runs);
    }

    /**
     * As above for a file of any kind the ingest takes ({@code ext}: {@code .mrg}, {@code .sbd},
     * {@code .scd}); the baseline inserts the values of {@code dba}, the same rows as DBA text.
     */
    static void measure(Connection c, DatabaseServer local, BlockingQueue<OutgoingServiceMessage> replies,
                        String what, byte[] file, String ext, byte[] dba, int runs) throws Exception {
        ingest(local, replies, "warm-up-" + what.length() + ext, file); // its sensors are known, the JIT is warm
        clear(c);
        Parsed p = parse(c, dba);
        double[] viaService = new double[runs];
        double[] direct = new double[runs];
        double[] viaServiceCpu = new double[runs];
        double[] directCpu = new double[runs];
        for (int i = 0; i < runs; i++) {
            // every other run the baseline goes first, so drift (a checkpoint, the JIT, other load) falls on both alike
            for (int k = 0; k < 2; k++) {
                boolean service = (k == 0) == (i % 2 == 0);
                long t0 = System.nanoTime();
                long cpu0 = cpuNanos();
                if (service) {
                    String text = ingest(local, replies, "bench-" + i + ext, file);
                    viaService[i] = (System.nanoTime() - t0) / 1e6;
                    viaServiceCpu[i] = (cpuNanos() - cpu0) / 1e6;
                    if (!text.contains(p.values.length + " values")) {
                        throw new IllegalStateException("the ingest stored something else than the " + p.values.length
                                + " values parsed: " + text);
                    }
                } else {
                    directInsert(c, p);
                    direct[i] = (System.nanoTime() - t0) / 1e6;
                    directCpu[i] = (cpuNanos() - cpu0) / 1e6;
                }
                clear(c);
            }
        }
        double s = median(viaService);
        double d = median(direct);
        System.out.printf(Locale.ROOT, "%-34s %,9d %10.0f %10.0f %,12.0f %6.2fx  (CPU %.0f / %.0f ms = %.2fx; %.2f MB;"
                        + " raw ingest %s, direct %s)%n",
                what, p.values.length, s, d, p.values.length / (s / 1000), s / d, median(viaServiceCpu), median(directCpu),
                median(viaServiceCpu) / median(directCpu), file.length / 1e6, rounded(viaService), rounded(direct));
        System.out.println("  " + CpuClock.ratioLine("ingest per value", median(viaServiceCpu) * 1e3 / p.values.length,
                median(directCpu) * 1e3 / p.values.length, s / d) + "; " + CpuClock.machineLine());
    }

    /** The whole process's CPU time: every thread of the path measured, none of the waiting. */
    private static long cpuNanos() {
        return ((OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    private static String rounded(double[] ms) {
        StringBuilder b = new StringBuilder("[");
        for (double m : ms) {
            b.append(b.length() > 1 ? ", " : "").append(Math.round(m));
        }
        return b.append(']').toString();
    }

    /** The file's values with their row, sensor id and time, read before the clock starts. */
    private record Parsed(int[] rowNo, int[] sensor, double[] time, double[] values, String vehicle) {}

    private static Parsed parse(Connection c, byte[] file) throws Exception {
        Map<String, Integer> ids = new HashMap<>();
        try (Statement st = c.createStatement(); ResultSet rs = st.executeQuery("SELECT sensor_id, name, unit FROM sensor_def")) {
            while (rs.next()) {
                ids.put(rs.getString(2) + "/" + rs.getString(3), rs.getInt(1));
            }
        }
        List<int[]> meta = new ArrayList<>();
        List<double[]> vals = new ArrayList<>();
        String vehicle;
        try (DbaReader r = new DbaReader(new ByteArrayInputStream(file))) {
            vehicle = r.header().vehicle();
            int[] sensorIds = r.header().sensors().stream().mapToInt(s -> ids.get(s.name() + "/" + s.unit())).toArray();
            double[] row = new double[sensorIds.length];
            while (r.next(row)) {
                double t = r.time(row);
                for (int i = 0; i < row.length; i++) {
                    if (!Double.isNaN(row[i])) {
                        meta.add(new int[] {(int) r.rows(), sensorIds[i]});
                        vals.add(new double[] {t, row[i]});
                    }
                }
            }
        }
        int n = meta.size();
        int[] rowNo = new int[n];
        int[] sensor = new int[n];
        double[] time = new double[n];
        double[] values = new double[n];
        for (int i = 0; i < n; i++) {
            rowNo[i] = meta.get(i)[0];
            sensor[i] = meta.get(i)[1];
            time[i] = vals.get(i)[0];
            values[i] = vals.get(i)[1];
        }
        return new Parsed(rowNo, sensor, time, values, vehicle);
    }

    /** The baseline: one DATA_FILE row and every value batch-inserted, one transaction. */
    private static void directInsert(Connection c, Parsed p) throws Exception {
        c.setAutoCommit(false);
        long fileId;
        try (PreparedStatement st = c.prepareStatement("INSERT INTO data_file (vehicle, name, sensor_count, row_count,"
                + " value_count, position_count, sha256, ingested) VALUES (?, 'direct', 0, 0, 0, 0, ?, ?)",
                Statement.RETURN_GENERATED_KEYS)) {
            st.setString(1, p.vehicle);
            st.setString(2, DbaIngest.sha256(Long.toString(System.nanoTime()).getBytes(StandardCharsets.US_ASCII)));
            st.setTimestamp(3, Timestamp.from(Instant.now()), UTC);
            st.executeUpdate();
            try (ResultSet k = st.getGeneratedKeys()) {
                k.next();
                fileId = k.getLong(1);
            }
        }
        try (PreparedStatement ins = c.prepareStatement(
                "INSERT INTO reading (file_id, row_no, sensor_id, vehicle, t, value) VALUES (?, ?, ?, ?, ?, ?)")) {
            ins.setLong(1, fileId);
            ins.setString(4, p.vehicle);
            for (int i = 0; i < p.values.length; i++) {
                if (i == 0 || p.rowNo[i] != p.rowNo[i - 1]) { // a row's values share its row number and time
                    ins.setInt(2, p.rowNo[i]);
                    long micros = Math.round(p.time[i] * 1e6);
                    ins.setTimestamp(5, Timestamp.from(Instant.ofEpochSecond(Math.floorDiv(micros, 1_000_000L),
                            Math.floorMod(micros, 1_000_000L) * 1000)), UTC);
                }
                ins.setInt(3, p.sensor[i]);
                ins.setDouble(6, p.values[i]);
                ins.addBatch();
                if (i % 5000 == 4999) {
                    ins.executeBatch();
                }
            }
            ins.executeBatch();
        }
        c.commit();
        c.setAutoCommit(true);
    }

    static void clear(Connection c) throws Exception {
        try (Statement st = c.createStatement()) {
            st.execute("TRUNCATE TABLE reading");
            st.execute("TRUNCATE TABLE cycle"); // else the next run's cycles are all merges into these
            st.execute("TRUNCATE TABLE position_fix");
            st.execute("DELETE FROM data_file");
        }
    }

    static String ingest(DatabaseServer service, BlockingQueue<OutgoingServiceMessage> replies, String name,
                                 byte[] file) throws Exception {
        service.accept(new IncomingServiceMessage(new Header(1, new IdBadge("123456", "bench"), List.of("operators"),
                service.name().toString(), service.name().mailbox("TTY1").toString(), "ingest " + name, Priority.NORMAL,
                Attachment.bundle(List.of(new Attachment(name, file))))));
        while (true) {
            OutgoingServiceMessage r = replies.poll(10, TimeUnit.MINUTES);
            if (r == null) {
                throw new IllegalStateException("no reply to ingest " + name);
            }
            if (r.status().isFinal()) {
                if (r.status() != Status.OK) {
                    throw new IllegalStateException("ingest failed: " + r.footer().replyText());
                }
                return r.footer().replyText();
            }
        }
    }

    /** vis:track of 100,000 positions through the whole system. */
    private static void track(Path dir, DatabaseTarget db, QueryLimits limits, int runs, int rows) throws Exception {
        Path serverDir = dir.resolve("server");
        RIPVServer server = BenchTools.serverWithOperator(serverDir);
        ServiceOptions options = new ServiceOptions("localhost", server.registryPort(),
                Files.readString(server.secretFile()).trim(), 0, Duration.ofSeconds(1));
        DatabaseServer dbService = new DatabaseServer("localhost", List.of(db), limits);
        DataVisServer vis = new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis")));
        ServiceConnector c1 = ServiceConnector.connect(dbService, options);
        ServiceConnector c2 = ServiceConnector.connect(vis, options);
        try (ClientSocketHandler client = ClientSocketHandler.connect("localhost", server.port())) {
            if (!c1.awaitRegistered(Duration.ofSeconds(30)) || !c2.awaitRegistered(Duration.ofSeconds(30))) {
                throw new IllegalStateException("the services did not register");
            }
            client.login(BenchTools.USER, BenchTools.PASSWORD.toCharArray());
            String dbBox = dbService.name().mailbox("TTY1").toString();
            String visBox = vis.name().mailbox("TTY1").toString();
            byte[] file = SyntheticDba.generate("track", 4, rows, 1.0, true, 4);
            Path dl = serverDir.resolve("download");
            Files.createDirectories(dl);
            Files.write(dl.resolve("track.mrg"), file);
            OutgoingServerMessage in = client.call(dbBox, "ingest track.mrg", Priority.NORMAL, Duration.ofMinutes(10), null);
            if (in.status() != Status.OK) {
                throw new IllegalStateException("ingest of the track failed: " + in.footer().replyText());
            }
            double[] ms = new double[runs];
            double[] cpu = new double[runs];
            String text = "";
            for (int i = -1; i < runs; i++) {
                long t0 = System.nanoTime();
                long cpu0 = cpuNanos();
                OutgoingServerMessage r = client.call(visBox, "vis:track track", Priority.NORMAL, Duration.ofMinutes(5), null);
                long t1 = System.nanoTime();
                long cpu1 = cpuNanos();
                if (r.status() != Status.OK) {
                    throw new IllegalStateException("vis:track failed: " + r.footer().replyText());
                }
                text = r.footer().replyText();
                if (i >= 0) {
                    ms[i] = (t1 - t0) / 1e6;
                    cpu[i] = (cpu1 - cpu0) / 1e6;
                }
            }
            System.out.printf(Locale.ROOT, "vis:track of %,d positions end to end: median %.0f ms (target < 1000 ms;"
                    + " raw %s); CPU of client, server and both services: median %.0f ms %s%n",
                    rows, median(ms), rounded(ms), median(cpu), rounded(cpu));
            System.out.println("  last reply: " + text);
        } finally {
            c1.close();
            c2.close();
            dbService.stop();
            vis.stop();
            server.stop();
        }
    }
}
