package org.ripv.bench;

import static org.ripv.bench.BenchTools.intOption;
import static org.ripv.bench.BenchTools.median;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.ingest.Lz4Blocks;
import org.ripv.services.ingest.SlocumBinaryFiles;
import org.ripv.services.ingest.SlocumBinaryReader;
import org.ripv.services.ingest.SlocumEncoder;
import org.ripv.services.ingest.SlocumSensor;

/**
 * {@code ./ripv bench slocum} (issue 22; a measurement, not a timed test):
 * <ol>
 *   <li>decoding a 10 MB Slocum binary file on one thread, plain and LZ4-compressed, in MB of
 *       input per second, against reading the same bytes from the same (cached) file — the I/O
 *       floor; wall and the thread's CPU time;</li>
 *   <li>{@code ingest} of a binary file (plain {@code .sbd} and compressed {@code .scd}) through
 *       the DatabaseServer in-process against a direct JDBC batch insert of the same values, in the
 *       same run ({@link IngestBench#measure}).</li>
 * </ol>
 * The files come from {@link SlocumEncoder}, whose output {@code SlocumBadInputTest} checks
 * against the shared real files. Options: {@code --mb N} (default 10), {@code --runs N} (default 5),
 * {@code --ingest-rows N} (default 20,000).
 */
public final class SlocumBench {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private SlocumBench() {}

    /** The sensors of a real .sbd (27, the sizes of rosie_713's flight file). */
    static List<SlocumSensor> sensors() {
        List<SlocumSensor> s = new ArrayList<>();
        s.add(new SlocumSensor("m_present_time", "timestamp", 8));
        s.add(new SlocumSensor("m_gps_lat", "lat", 8));
        s.add(new SlocumSensor("m_gps_lon", "lon", 8));
        s.add(new SlocumSensor("m_lat", "lat", 8));
        s.add(new SlocumSensor("m_lon", "lon", 8));
        s.add(new SlocumSensor("m_depth", "m", 4));
        s.add(new SlocumSensor("m_state", "enum", 1));
        s.add(new SlocumSensor("m_mission_number", "nodim", 2));
        for (int i = s.size(); i < 27; i++) {
            s.add(new SlocumSensor("m_sensor_" + i, "X", 4));
        }
        return s;
    }

    /** A file of about {@code bytes} bytes, or of {@code rows} rows when rows > 0: values that move, some NaN, some repeated. */
    static byte[] generate(long bytes, int rows, long seed) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream((int) Math.min(Integer.MAX_VALUE - 8, bytes + 4096));
        Map<String, String> tags = new LinkedHashMap<>();
        tags.put("full_filename", "bench_1-2024-001-0-" + seed);
        tags.put("the8x3_filename", "00010000");
        tags.put("filename_extension", "sbd");
        List<SlocumSensor> sensors = sensors();
        SlocumEncoder e = SlocumEncoder.start(out, tags, sensors);
        Random r = new Random(seed);
        double[] row = new double[sensors.size()];
        double lat = 4137.99;
        double lon = -7032.18;
        for (int n = 0; rows > 0 ? n < rows : out.size() < bytes; n++) {
            row[0] = 1.7e9 + n * 2.0;
            boolean fix = n % 10 == 0;
            lat += 0.001;
            lon -= 0.001;
            row[1] = fix ? lat : Double.NaN;
            row[2] = fix ? lon : Double.NaN;
            row[3] = lat;
            row[4] = lon;
            row[5] = (float) (50 + 40 * Math.sin(n / 100.0));
            row[6] = n / 500 % 5;
            row[7] = 7;
            for (int i = 8; i < row.length; i++) {
                row[i] = r.nextInt(4) == 0 ? Double.NaN : (float) (r.nextGaussian() * 10);
            }
            e.cycle(row);
        }
        e.end();
        return out.toByteArray();
    }

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int mb = intOption(args, "--mb", 10);
        int runs = intOption(args, "--runs", 5);
        int ingestRows = intOption(args, "--ingest-rows", 20_000);
        BenchTools.inScratchDirectory("ripv-slocumbench", dir -> {
            System.out.printf(Locale.ROOT, "SlocumBench: %s %s (the machine may be shared; its load is on the machine: lines)%n",
                    System.getProperty("java.vm.name"), System.getProperty("java.version"));
            byte[] plain = generate((long) mb << 20, 0, 1);
            byte[] packed = Lz4Blocks.compress(plain, 16_384);
            Path sbd = Files.write(dir.resolve("bench.sbd"), plain);
            Path scd = Files.write(dir.resolve("bench.scd"), packed);
            System.out.printf(Locale.ROOT, "%-26s %9s %11s %11s %10s %10s%n", "file", "MB", "read MB/s", "decode MB/s",
                    "read CPU", "decode CPU");
            decodeSpeed("plain .sbd", sbd, runs);
            decodeSpeed("LZ4 .scd (16 KiB blocks)", scd, runs);
            ingest(dir, ingestRows, runs);
            System.out.println(CpuClock.machineLine());
        });
        return 0;
    }

    private static void decodeSpeed(String what, Path file, int runs) throws Exception {
        double mb = Files.size(file) / 1e6;
        double[] readWall = new double[runs];
        double[] readCpu = new double[runs];
        double[] decodeWall = new double[runs];
        double[] decodeCpu = new double[runs];
        long cycles = 0;
        byte[] buf = new byte[1 << 16];
        for (int i = -1; i < runs; i++) { // run -1 warms the JIT and the page cache
            long t0 = System.nanoTime();
            long c0 = THREADS.getCurrentThreadCpuTime();
            try (InputStream in = Files.newInputStream(file)) {
                while (in.read(buf) >= 0) {
                    // the I/O floor: the bytes, nothing done with them
                }
            }
            long t1 = System.nanoTime();
            long c1 = THREADS.getCurrentThreadCpuTime();
            try (InputStream in = Files.newInputStream(file);
                 SlocumBinaryReader r = SlocumBinaryReader.open(in, file.getFileName().toString(), null)) {
                double[] row = new double[r.sensors().size()];
                while (r.next(row)) {
                    // decoded
                }
                cycles = r.cycles();
            }
            long t2 = System.nanoTime();
            long c2 = THREADS.getCurrentThreadCpuTime();
            if (i >= 0) {
                readWall[i] = (t1 - t0) / 1e9;
                readCpu[i] = (c1 - c0) / 1e9;
                decodeWall[i] = (t2 - t1) / 1e9;
                decodeCpu[i] = (c2 - c1) / 1e9;
            }
        }
        System.out.printf(Locale.ROOT, "%-26s %9.1f %11.0f %11.0f %8.1fms %8.1fms   (%,d cycles; decode on CPU time %.0f MB/s;"
                        + " wall runs %s)%n", what, mb, mb / median(readWall), mb / median(decodeWall), median(readCpu) * 1e3,
                median(decodeCpu) * 1e3, cycles, mb / median(decodeCpu), Arrays.toString(Arrays.stream(decodeWall)
                        .map(w -> Math.round(w * 1e4) / 10.0).toArray()));
        System.out.println("  " + CpuClock.ratioLine("decode per cycle", median(decodeCpu) * 1e6 / cycles,
                median(readCpu) * 1e6 / cycles, median(decodeWall) / median(readWall)) + " (floor: reading the bytes); "
                + CpuClock.machineLine());
    }

    private static void ingest(Path dir, int rows, int runs) throws Exception {
        DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1");
        DatabaseServer local = new DatabaseServer("localhost", List.of(db), new QueryLimits(200_000, 600, 64L * 1024 * 1024));
        local.start();
        BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
        local.replyTo(replies::add);
        byte[] plain = generate(0, rows, 2);
        byte[] dba = SlocumBinaryFiles.dba("bench.sbd", plain, null);
        System.out.printf(Locale.ROOT, "%nbinary ingest against a direct JDBC batch insert of the same values (embedded Derby, %d runs)%n", runs);
        System.out.printf(Locale.ROOT, "%-34s %9s %10s %10s %12s %7s%n", "file", "values", "ingest ms", "direct ms", "ingest v/s", "ratio");
        try (Connection c = DriverManager.getConnection(db.url(), db.user(), db.password())) {
            // creates the schema too; no larger than the measured file (--short measures 300 rows: issue 38)
            IngestBench.ingest(local, replies, "warm-up.sbd", generate(0, Math.min(2000, rows), 3));
            IngestBench.clear(c);
            IngestBench.measure(c, local, replies, String.format(Locale.ROOT, ".sbd, %,d rows", rows), plain, ".sbd", dba, runs);
            IngestBench.measure(c, local, replies, String.format(Locale.ROOT, ".scd, %,d rows", rows), Lz4Blocks.compress(plain, 16_384),
                    ".scd", dba, runs);
        } finally {
            local.stop();
        }
    }
}
