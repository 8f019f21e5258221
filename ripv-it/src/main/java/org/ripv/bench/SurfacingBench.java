package org.ripv.bench;

import static org.ripv.bench.BenchTools.intOption;
import static org.ripv.bench.BenchTools.median;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.Writer;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.CharBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;
import org.ripv.surfacing.SurfaceDialogParser;
import org.ripv.surfacing.Surfacing;

/**
 * {@code ./ripv bench surfacing} (issue 38, item 4; a measurement, not a timed test): the surface
 * dialog parser ({@link SurfaceDialogParser}, {@code org.ripv.surfacing}) in dialog lines per
 * second, against its floor — reading the same lines from the same (cached) file and splitting
 * them, with nothing done with them — in the same run, on one thread.
 *
 * <p>Two ways in, as the product feeds it: a line at a time ({@code line}, the server's
 * Surfacings with each console entry) and the raw text in 512-character pieces ({@code feed}, the
 * SerialPortServer's VehicleConsole as bytes arrive). The dialogs are generated in the shapes of
 * three firmware generations (docs/surfacings.md): a routine surfacing, an abort with its whole
 * ABORT HISTORY block and device errors, and a southern one with no fix and a leak; each with its
 * sensor list, CR LF line ends, between them the dive's own lines that are no dialog. The run
 * fails when the parser does not hand back every dialog.
 *
 * <p>Options: {@code --dialogs N} (default 20,000, about 700,000 lines), {@code --runs N} (default 5).
 */
public final class SurfacingBench {
    private static final ThreadMXBean THREADS = ManagementFactory.getThreadMXBean();
    private static final int CHUNK = 512;

    private SurfacingBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark; its exit status is returned, not exited with ({@code ShortRuns} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int dialogs = intOption(args, "--dialogs", 20_000);
        int runs = intOption(args, "--runs", 5);
        if (dialogs < 1 || runs < 1) {
            System.err.println("Usage: ripv bench surfacing [--dialogs N] [--runs N]   (both at least 1)");
            return 2;
        }
        Path file = Files.createTempFile("ripv-surfacingbench", ".txt");
        try {
            long lines = write(file, dialogs, 1);
            System.out.printf(Locale.ROOT, "SurfacingBench: %s %s; %,d dialogs, %,d lines, %.1f MB (the machine may be shared; "
                    + "its load is on the machine: lines)%n", System.getProperty("java.vm.name"), System.getProperty("java.version"),
                    dialogs, lines, Files.size(file) / 1e6);
            System.out.println(CpuClock.machineLine());
            double[][] read = new double[2][runs];
            double[][] byLine = new double[2][runs];
            double[][] byFeed = new double[2][runs];
            CpuClock process = null;
            long processOps = 0;
            for (int i = -1; i < runs; i++) { // run -1 warms the JIT and the page cache
                if (i == 0) {
                    process = CpuClock.start();
                }
                time(read, i, () -> readOnly(file, lines));
                time(byLine, i, () -> parseLines(file, dialogs));
                time(byFeed, i, () -> parseFed(file, dialogs));
                if (i >= 0) {
                    processOps += 3 * lines;
                }
            }
            System.out.printf(Locale.ROOT, "%n%-44s %14s %12s %12s%n", "path (one thread; median of " + runs + " runs)", "lines/s",
                    "wall ms", "CPU us/line");
            row("read and split the lines (the floor)", read, lines);
            row("parser, a line at a time (the server's way)", byLine, lines);
            row("parser, 512-char pieces (the service's way)", byFeed, lines);
            System.out.println(CpuClock.ratioLine("parser per line, a line at a time", perLine(byLine[1], lines), perLine(read[1], lines),
                    median(byLine[0]) / median(read[0])) + " (floor: reading and splitting the same lines)");
            System.out.println(CpuClock.ratioLine("parser per line, 512-char pieces", perLine(byFeed[1], lines), perLine(read[1], lines),
                    median(byFeed[0]) / median(read[0])) + " (floor: reading and splitting the same lines)");
            System.out.printf(Locale.ROOT, "process CPU (every thread: JIT and collector too) per line over all three paths: %.3f us%n",
                    process.cpuMicrosPer(processOps));
            System.out.println(CpuClock.machineLine());
            return 0;
        } finally {
            Files.deleteIfExists(file);
        }
    }

    /** One measured pass: wall seconds and this thread's CPU seconds, kept from run 0 on. */
    private static void time(double[][] into, int run, Pass pass) throws IOException {
        long t0 = System.nanoTime();
        long c0 = THREADS.getCurrentThreadCpuTime();
        pass.run();
        long t1 = System.nanoTime();
        long c1 = THREADS.getCurrentThreadCpuTime();
        if (run >= 0) {
            into[0][run] = (t1 - t0) / 1e9;
            into[1][run] = (c1 - c0) / 1e9;
        }
    }

    private interface Pass {
        void run() throws IOException;
    }

    /** The floor: the file's lines as Strings, counted, nothing else. */
    private static void readOnly(Path file, long expected) throws IOException {
        long n = 0;
        long chars = 0;
        try (BufferedReader r = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
            for (String s; (s = r.readLine()) != null; ) {
                n++;
                chars += s.length();
            }
        }
        if (n != expected || chars == 0) {
            throw new IllegalStateException("read " + n + " lines of " + expected);
        }
    }

    private static void parseLines(Path file, int dialogs) throws IOException {
        Count c = new Count();
        SurfaceDialogParser p = new SurfaceDialogParser(c);
        try (BufferedReader r = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
            for (String s; (s = r.readLine()) != null; ) {
                p.line(s);
            }
        }
        p.end();
        c.check(dialogs);
    }

    private static void parseFed(Path file, int dialogs) throws IOException {
        Count c = new Count();
        SurfaceDialogParser p = new SurfaceDialogParser(c);
        char[] buf = new char[CHUNK];
        try (BufferedReader r = Files.newBufferedReader(file, StandardCharsets.ISO_8859_1)) {
            for (int n; (n = r.read(buf)) > 0; ) {
                p.feed(CharBuffer.wrap(buf, 0, n));
            }
        }
        p.end();
        c.check(dialogs);
    }

    /** What the parser handed back; a dialog lost or misread fails the run. */
    private static final class Count implements SurfaceDialogParser.Listener {
        long surfacings;
        long withFix;
        long sensors;
        long countdowns;

        @Override
        public void surfacing(Surfacing s) {
            surfacings++;
            sensors += s.sensors().size();
            if (s.gps() != null) {
                withFix++;
            }
        }

        @Override
        public void countdown(long seconds) {
            countdowns++;
        }

        void check(int dialogs) {
            if (surfacings != dialogs || sensors < 5L * dialogs || withFix < dialogs / 2 || countdowns < dialogs / 2) {
                throw new IllegalStateException(String.format(Locale.ROOT, "the parser handed back %d dialogs of %d (%d with a fix,"
                        + " %d sensors, %d countdowns)", surfacings, dialogs, withFix, sensors, countdowns));
            }
        }
    }

    private static void row(String what, double[][] t, long lines) {
        System.out.printf(Locale.ROOT, "%-44s %,14.0f %12.1f %12.3f   (wall runs ms %s)%n", what, lines / median(t[0]),
                median(t[0]) * 1e3, perLine(t[1], lines), Arrays.toString(Arrays.stream(t[0]).map(w -> Math.round(w * 1e4) / 10.0).toArray()));
    }

    private static double perLine(double[] cpuSeconds, long lines) {
        return median(cpuSeconds) * 1e6 / lines;
    }

    /**
     * Writes {@code dialogs} surface dialogs with the dive's chatter between them, CR LF, and
     * returns the number of lines. Three shapes in turn (docs/surfacings.md); values move.
     */
    static long write(Path file, int dialogs, long seed) throws IOException {
        Random r = new Random(seed);
        long lines = 0;
        try (Writer w = Files.newBufferedWriter(file, StandardCharsets.ISO_8859_1)) {
            for (int d = 0; d < dialogs; d++) {
                String[] dialog = switch (d % 3) {
                    case 0 -> routine(d, r);
                    case 1 -> abort(d, r);
                    default -> southernNoFix(d, r);
                };
                for (String line : dialog) {
                    w.write(line);
                    w.write("\r\n");
                }
                lines += dialog.length;
            }
        }
        return lines;
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }

    private static String[] sensors(Random r, String... names) {
        String[] out = new String[names.length];
        for (int i = 0; i < names.length; i++) {
            out[i] = f("   sensor:%s=%.3f%28.1f secs ago", names[i], r.nextGaussian() * 10, r.nextDouble() * 900);
        }
        return out;
    }

    private static String[] concat(String[]... parts) {
        return Arrays.stream(parts).flatMap(Arrays::stream).toArray(String[]::new);
    }

    private static String[] routine(int d, Random r) {
        return concat(new String[] {
            f(" behavior surface_2: SUBSTATE 4 ->5 : Picking up surface_2 at %d", d),
            "",
            f("Glider ru%02d at surface.", d % 50),
            "Because:Surface interval [BAW_EVERY_SECS]",
            f("MissionName:box.mi MissionNum:ru%02d-2026-%03d-0-%d (0012.%04d)", d % 50, d % 365, d % 9, d % 10000),
            f("Vehicle Name: ru%02d", d % 50),
            f("Curr Time: Mon Nov 23 12:%02d:%02d 2026 MT:   %d", d % 60, d % 60, 40_000 + d),
            f("DR  Location:  %.4f N -%.4f E measured    %.1f secs ago", 4137.0 + r.nextDouble(), 7032.0 + r.nextDouble(), r.nextDouble() * 200),
            f("GPS Location:  %.4f N -%.4f E measured     %.3f secs ago", 4137.0 + r.nextDouble(), 7032.0 + r.nextDouble(), r.nextDouble() * 60),
        }, sensors(r, "c_wpt_lat(lat)", "c_wpt_lon(lon)", "m_battery(volts)", "m_coulomb_amphr_total(amp-hrs)", "m_vacuum(inHg)",
                "m_leakdetect_voltage(volts)", "m_water_vx(m/s)", "m_water_vy(m/s)", "m_depth(m)"), new String[] {
            "devices:(t/m/s) errs:     0/  0/  0 warn:     1/  0/  0 oddity:     3/  0/  0",
            "ABORT HISTORY: total since reset: 0",
            "   Hit Control-C within 50 seconds to abort the mission",
            f("GliderDos N %d >", d % 9),
        });
    }

    private static String[] abort(int d, Random r) {
        return concat(new String[] {
            f("Glider ru%02d at surface.", d % 50),
            "Because:Abort [MS_ABORT_OVERDEPTH]",
            f("MissionName:deep.mi MissionNum:ru%02d-2026-327-2-4 (0031.0004)", d % 50),
            f("Vehicle Name: ru%02d", d % 50),
            f("Curr Time: Mon Nov 23 14:55:02 2026 MT:   %d", 90_000 + d),
            f("DR  Location:  %.3f N -%.3f E measured    %.1f secs ago", 4137.0 + r.nextDouble(), 7032.0 + r.nextDouble(), r.nextDouble() * 200),
            "GPS TooFar:   69696969.000 N 69696969.000 E measured     1e+308 secs ago",
            f("GPS Invalid :  %.3f N -%.3f E measured     %.3f secs ago", 4137.0 + r.nextDouble(), 7032.0 + r.nextDouble(), r.nextDouble() * 60),
            f("GPS Location:  %.3f N -%.3f E measured     %.3f secs ago", 4137.0 + r.nextDouble(), 7032.0 + r.nextDouble(), r.nextDouble() * 60),
        }, sensors(r, "c_wpt_lat(lat)", "c_wpt_lon(lon)", "m_battery(volts)", "m_coulomb_amphr_total(amp-hrs)", "m_vacuum(inHg)",
                "m_leakdetect_voltage(volts)", "m_leakdetect_voltage_forward(volts)", "m_water_vx(m/s)", "m_water_vy(m/s)", "m_depth(m)"),
                new String[] {
            "devices:(t/m/s) errs:     2/  0/  0 warn:     5/  1/  0 oddity:    11/  2/  0",
            "Waypoint: (-7030.0000,4140.0000) Range: 4178m, Bearing: 36deg, Age: 0:56h:min",
            "ABORT HISTORY: total since reset: 3",
            "ABORT HISTORY: last abort cause: MS_ABORT_OVERDEPTH",
            "ABORT HISTORY: last abort details: dive_to: depth 1012.3 > max depth 1000.0",
            "ABORT HISTORY: last abort time: 2026-11-23T13:02:41",
            "ABORT HISTORY: last abort segment: ru29-2026-327-2-4 (0031.0004)",
            "ABORT HISTORY: last abort mission: deep.mi",
            "GliderDos A 8 >",
        });
    }

    private static String[] southernNoFix(int d, Random r) {
        return concat(new String[] {
            f("Glider unit_%03d at surface.", d % 400),
            "Because:Hardware Error [DEVICE_ERROR]",
            f("MissionName:south.mi MissionNum:unit_%03d-2026-%03d-1-0", d % 400, d % 365),
            f("Vehicle Name: unit_%03d", d % 400),
            f("Curr Time: Tue Nov 24 03:%02d:11 2026 MT:   %d", d % 60, 5_000 + d),
            f("DR  Location: -%.4f N 14733.1050 E measured    %.1f secs ago", 3345.0 + r.nextDouble(), r.nextDouble() * 900),
            "GPS Invalid : 69696969.000 N 69696969.000 E measured     1e+308 secs ago",
        }, sensors(r, "m_battery(volts)", "m_vacuum(inHg)", "m_leakdetect_voltage(volts)", "m_leakdetect_voltage_aft(volts)",
                "m_depth(m)", "m_altitude(m)"), new String[] {
            "   sensor:m_water_vx(m/s)=nan                           1e+308 secs ago",
            "devices:(t/m/s) errs:     1/  1/  1 warn:     0/  0/  0 oddity:     0/  0/  0",
            "ABORT HISTORY: total since reset: 1",
            "Type Control-R to resume the mission, Control-E to extend the surface time,",
            "Control-C to enter GliderDOS, Control-T for the time",
            "   Hit Control-C within 600 seconds to abort the mission",
            f("%d dive lines follow with no dialog in them: m_depth %.1f", d, r.nextDouble() * 100),
        });
    }
}
