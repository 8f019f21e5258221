package org.ripv.bench;

import com.sun.management.OperatingSystemMXBean;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.SqlScript;

/**
 * {@code ./ripv bench firststart [--runs N]}: the DatabaseServer's first start — embedded Derby
 * created, its users set up and the sample data loaded — each in a fresh JVM, as a real first
 * start is, against the same run's baseline: a fresh JVM that only creates the database and runs
 * {@code vehicleDB.sql} and {@code sample-data.sql} statement by statement (the way first start
 * used to load it, without even the users). Reports wall time from JVM launch and CPU time
 * (user + system, all threads, the first start's own seeding JVM included), median of the runs;
 * CPU time is what a loaded machine does not distort.
 */
public final class FirstStartBench {
    private FirstStartBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        if (args.length >= 1 && args[0].equals("child")) {
            child(args[1], Path.of(args[2]));
            return 0;
        }
        int runs = args.length >= 2 && args[0].equals("--runs") ? Integer.parseInt(args[1]) : 3;
        List<long[]> ripv = new ArrayList<>();
        List<long[]> script = new ArrayList<>();
        for (int i = 0; i < runs; i++) {
            script.add(run("script"));
            ripv.add(run("ripv"));
        }
        long[] s = median(script);
        long[] r = median(ripv);
        System.out.printf("first start, baseline (statement by statement, no users): wall %5d ms, cpu %5d ms%n", s[0], s[1]);
        System.out.printf("first start, RIPV (batched seed, users, grants):          wall %5d ms, cpu %5d ms%n", r[0], r[1]);
        System.out.printf("RIPV / baseline: wall %.2f, cpu %.2f (median of %d runs; %d cores, load average %.1f)%n",
                (double) r[0] / s[0], (double) r[1] / s[1], runs, Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        return 0;
    }

    private static long[] median(List<long[]> v) {
        long[] wall = v.stream().mapToLong(x -> x[0]).sorted().toArray();
        long[] cpu = v.stream().mapToLong(x -> x[1]).sorted().toArray();
        return new long[] {wall[wall.length / 2], cpu[cpu.length / 2]};
    }

    /** One first start in a fresh JVM: {wall ms from launch, cpu ms}. */
    private static long[] run(String mode) throws Exception {
        Path dir = Files.createTempDirectory("ripv-firststart");
        try {
            String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
            long t0 = System.nanoTime();
            Process p = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), FirstStartBench.class.getName(),
                    "child", mode, dir.toString()).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes());
            if (!p.waitFor(600, TimeUnit.SECONDS) || p.exitValue() != 0) {
                throw new IllegalStateException(mode + " failed: " + out);
            }
            long wall = (System.nanoTime() - t0) / 1_000_000;
            String cpu = Arrays.stream(out.split("\n")).filter(l -> l.startsWith("CPU ")).findFirst()
                    .orElseThrow(() -> new IllegalStateException("no CPU line: " + out));
            return new long[] {wall, Long.parseLong(cpu.substring(4).trim())};
        } finally {
            try (var walk = Files.walk(dir)) {
                walk.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
            }
        }
    }

    private static void child(String mode, Path dir) throws Exception {
        if (mode.equals("ripv")) {
            EmbeddedDatabase.prepare(dir, "TTY1");
        } else {
            try (Connection c = DriverManager.getConnection("jdbc:derby:" + dir.resolve("db") + ";create=true")) {
                c.setAutoCommit(false);
                SqlScript.run(c, SqlScript.resource("vehicleDB.sql"), "vehicleDB.sql");
                SqlScript.run(c, SqlScript.resource("sample-data.sql"), "sample-data.sql");
                c.commit();
            }
        }
        long cpu = ((OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean()).getProcessCpuTime();
        System.out.println("CPU " + (cpu / 1_000_000 + childrenCpuMillis()));
        System.exit(0);
    }

    /**
     * CPU time of the child processes this JVM waited for (the first start's own seeding JVM,
     * {@code SeedInChild}): fields 16 and 17 of /proc/self/stat, in clock ticks (100 a second).
     */
    private static long childrenCpuMillis() {
        try {
            String stat = Files.readString(Path.of("/proc/self/stat"));
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
            return (Long.parseLong(f[13]) + Long.parseLong(f[14])) * 10; // fields 16, 17 counted from after the name
        } catch (Exception e) {
            return 0;
        }
    }
}
