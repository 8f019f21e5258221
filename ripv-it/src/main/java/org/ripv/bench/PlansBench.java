package org.ripv.bench;

import static org.ripv.bench.BenchTools.intOption;
import static org.ripv.bench.BenchTools.median;

import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.ripv.plans.BehaviorFileReader;
import org.ripv.plans.PlanCheck;
import org.ripv.plans.PlanLimits;

/**
 * {@code ./ripv bench plans} (issue 38, item 4; a measurement, not a timed test): checking Slocum
 * behaviour files ({@link BehaviorFileReader}, {@code org.ripv.plans}, as {@code ripv plan check}
 * and the server's {@code ?plan check} do) in files per second, against its floor — reading the
 * same (cached) files' bytes with nothing done with them — in the same run, on one thread.
 *
 * <p>The files are generated in the shapes of docs/plans.md: {@code goto_list} files with two to
 * eight waypoints, comments after values and on their own lines, tabs and CR LF; {@code yo} and
 * {@code surface} files; and one in ten with a mistake the checker must find (a waypoint off the
 * globe, a b_arg with no value, a control byte). The run fails when a good file is refused or a
 * bad one passes.
 *
 * <p>Options: {@code --files N} (default 2,000), {@code --runs N} (default 5).
 */
public final class PlansBench {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();

    private PlansBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark; its exit status is returned, not exited with ({@code ShortRuns} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int files = intOption(args, "--files", 2_000);
        int runs = intOption(args, "--runs", 5);
        if (files < 10 || runs < 1) {
            System.err.println("Usage: ripv bench plans [--files N] [--runs N]   (at least 10 files and 1 run)");
            return 2;
        }
        Path dir = Files.createTempDirectory("ripv-plansbench");
        try {
            List<Path> paths = new ArrayList<>();
            long bytes = 0;
            int bad = 0;
            Random r = new Random(1);
            for (int i = 0; i < files; i++) {
                boolean broken = i % 10 == 9;
                String text = switch (i % 5) {
                    case 0, 1, 2 -> gotoList(i, r, broken);
                    case 3 -> yo(i, broken);
                    default -> surface(i, broken);
                };
                Path p = dir.resolve(String.format(Locale.ROOT, "%s%05d.ma", broken ? "bad" : "ok", i));
                Files.writeString(p, text, StandardCharsets.ISO_8859_1);
                paths.add(p);
                bytes += text.length();
                bad += broken ? 1 : 0;
            }
            System.out.printf(Locale.ROOT, "PlansBench: %s %s; %,d behaviour files (%,d with a mistake), %.1f KB (the machine may be"
                    + " shared; its load is on the machine: lines)%n", System.getProperty("java.vm.name"),
                    System.getProperty("java.version"), files, bad, bytes / 1e3);
            System.out.println(CpuClock.machineLine());
            double[][] read = new double[2][runs];
            double[][] check = new double[2][runs];
            CpuClock process = null;
            for (int i = -1; i < runs; i++) { // run -1 warms the JIT and the page cache
                if (i == 0) {
                    process = CpuClock.start();
                }
                long t0 = System.nanoTime();
                long c0 = THREADS.getCurrentThreadCpuTime();
                long seen = 0;
                for (Path p : paths) {
                    seen += Files.readAllBytes(p).length;
                }
                long t1 = System.nanoTime();
                long c1 = THREADS.getCurrentThreadCpuTime();
                int refused = 0;
                for (Path p : paths) {
                    PlanCheck c;
                    try (InputStream in = Files.newInputStream(p)) {
                        c = BehaviorFileReader.check(p.getFileName().toString(), in, PlanLimits.DEFAULT);
                    }
                    boolean shouldFail = p.getFileName().toString().startsWith("bad");
                    if (c.ok() == shouldFail) {
                        throw new IllegalStateException(p.getFileName() + (shouldFail ? " passed the check" : " was refused: "
                                + c.problemText()));
                    }
                    refused += c.ok() ? 0 : 1;
                }
                long t2 = System.nanoTime();
                long c2 = THREADS.getCurrentThreadCpuTime();
                if (seen != bytes || refused != bad) {
                    throw new IllegalStateException("read " + seen + " of " + bytes + " bytes; " + refused + " of " + bad + " refused");
                }
                if (i >= 0) {
                    read[0][i] = (t1 - t0) / 1e9;
                    read[1][i] = (c1 - c0) / 1e9;
                    check[0][i] = (t2 - t1) / 1e9;
                    check[1][i] = (c2 - c1) / 1e9;
                }
            }
            System.out.printf(Locale.ROOT, "%n%-40s %12s %10s %13s%n", "path (one thread; median of " + runs + " runs)", "files/s",
                    "wall ms", "CPU us/file");
            row("read the files' bytes (the floor)", read, files);
            row("check them (BehaviorFileReader)", check, files);
            System.out.println(CpuClock.ratioLine("plan check per file", median(check[1]) * 1e6 / files, median(read[1]) * 1e6 / files,
                    median(check[0]) / median(read[0])) + " (floor: reading the same files' bytes)");
            System.out.printf(Locale.ROOT, "process CPU (every thread: JIT and collector too) per file, both paths: %.1f us%n",
                    process.cpuMicrosPer(2L * files * runs));
            System.out.println(CpuClock.machineLine());
            return 0;
        } finally {
            try (var s = Files.walk(dir)) {
                for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(p);
                }
            }
        }
    }

    private static void row(String what, double[][] t, int files) {
        System.out.printf(Locale.ROOT, "%-40s %,12.0f %10.1f %13.1f   (wall runs ms %s)%n", what, files / median(t[0]),
                median(t[0]) * 1e3, median(t[1]) * 1e6 / files,
                Arrays.toString(Arrays.stream(t[0]).map(w -> Math.round(w * 1e4) / 10.0).toArray()));
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }

    /** A goto_list as people and tools write them: 2 to 8 waypoints, comments, tabs, CR LF every other file. */
    static String gotoList(int i, Random r, boolean broken) {
        int n = 2 + i % 7;
        StringBuilder b = new StringBuilder();
        b.append("behavior_name=goto_list\n");
        b.append(f("# goto_l%02d.ma, box %d off Martha's Vineyard\n", 10 + i % 90, i));
        b.append("#  2026-11-21 alice: moved wpt 2 north of the shoal\n");
        b.append("<start:b_arg>\n");
        b.append("b_arg: start_when(enum)       0     # BAW_IMMEDIATELY\n");
        b.append("b_arg: list_stop_when(enum)   7 # BAW_WHEN_WPT_DIST\n");
        b.append("b_arg:  list_when_wpt_dist(m)\t50  # used if list_stop_when == 7\n");
        b.append("b_arg: initial_wpt(enum)     -2# closest\n");
        b.append("                                 # >=0: start with this waypoint\n");
        b.append(f("\tb_arg: num_waypoints(nodim)\t%d\n", n));
        b.append(broken && i % 30 == 9 ? "b_arg: num_legs_to_run(nodim)\n" : "b_arg: num_legs_to_run(nodim) -1 # loop\n");
        b.append("<end:b_arg>\n");
        b.append("<start:waypoints>\n");
        b.append("# LON        LAT\n");
        for (int w = 0; w < n; w++) {
            double lon = -7040 + r.nextDouble() * 8;
            double lat = 4115 + r.nextDouble() * 8;
            if (broken && i % 30 == 19 && w == 1) {
                lat = 9130.5; // past the pole
            }
            b.append(f(w % 2 == 0 ? "%.3f\t%.3f  # wpt %d\n" : "  %.4f   %.4f #wpt %d\n", lon, lat, w));
        }
        b.append("<end:waypoints>\n\n# trailing notes are comments too\n");
        if (broken && i % 30 == 29) {
            b.insert(b.indexOf("<end:b_arg>"), "b_arg: d_target_depth(m) 30\u0007\n");
        }
        String text = b.toString();
        return i % 2 == 0 ? text.replace("\n", "\r\n") : text;
    }

    static String yo(int i, boolean broken) {
        return "behavior_name=yo\n"
                + f("# yo%d.ma: 3 to %d m\n", 10 + i % 50, 30 + i % 70)
                + "<start:b_arg>\n"
                + "    b_arg: start_when(enum)             2   # pitch idle\n"
                + "    b_arg: num_half_cycles_to_do(nodim) -1  # forever\n"
                + f("    b_arg: d_target_depth(m)            %d\n", 30 + i % 70)
                + "    b_arg: d_target_altitude(m)         5\n"
                + "    b_arg: c_dive_bpump_value(X)        -260.0\n"
                + "    b_arg: c_climb_bpump_value(X)       1000.0\n"
                + "    b_arg: d_use_pitch(enum)            3\n"
                + "    b_arg: d_pitch_value(X)             -0.4538 # -26 deg\n"
                + (broken ? "    b_arg: c_climb_target_depth(m)\n" : "    b_arg: c_climb_target_depth(m)      3\n")
                + "    b_arg: end_action(enum)             2   # resume\n"
                + "<end:b_arg>\n";
    }

    static String surface(int i, boolean broken) {
        return "behavior_name=surface\n"
                + "# climb to surface, pitch servoed\n"
                + "<start:b_arg>\n"
                + "b_arg: start_when(enum) 9 # 9-every when_secs\n"
                + "b_arg: end_action(enum) 1 # 0-quit, 1 wait for ^C quit/resume, 2 resume\n"
                + f("b_arg: when_secs(s) %d # How long between surfacing\n", 3600 + 60 * (i % 120))
                + "b_arg: gps_wait_time(s) 300 # how long to wait for gps\n"
                + (broken ? "b_arg: keystroke_wait_time(sec)\n" : "b_arg: keystroke_wait_time(sec) 300 # how long to wait for control-C\n")
                + "b_arg: c_use_pitch(enum) 3 # 3:servo\n"
                + "b_arg: c_pitch_value(X) 0.4528 # 26 deg\n"
                + "b_arg: printout_cycle_time(sec) 60.0 # How often to print dialog\n"
                + "<end:b_arg>\n";
    }
}
