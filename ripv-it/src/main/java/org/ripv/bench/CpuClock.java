package org.ripv.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * The CPU time of this whole process (every thread: the benchmark's client, the server and the
 * services it runs in-process, RMI's threads, the collector), for reporting CPU per operation
 * beside wall-clock percentiles (issue 26). On a machine shared with other work the wall time
 * of an operation swings with the neighbours' load, since a ready thread waits for a core; the
 * CPU it burns hardly does, so a ratio of CPU times against a floor measured in the same run is
 * the figure that holds. {@link #loadAverage()} goes beside it so a reader can tell how loaded
 * the machine was.
 */
public final class CpuClock {
    /** The line every benchmark prints once, so a reader and EveryBenchmarkRunsTest can find it. */
    public static final String LOAD_PREFIX = "machine: ";

    private final long wall0 = System.nanoTime();
    private final long cpu0 = processCpuNanos();

    private CpuClock() {}

    /** Starts counting now. */
    public static CpuClock start() {
        return new CpuClock();
    }

    /** CPU nanoseconds the process spent since {@link #start()}. */
    public long cpuNanos() {
        return processCpuNanos() - cpu0;
    }

    /** Wall nanoseconds since {@link #start()}. */
    public long wallNanos() {
        return System.nanoTime() - wall0;
    }

    /** CPU microseconds per operation since {@link #start()}. */
    public double cpuMicrosPer(long operations) {
        return cpuNanos() / 1e3 / Math.max(1, operations);
    }

    /** All threads' CPU time of this JVM, from the operating system (Linux: /proc/self/stat's utime + stime). */
    public static long processCpuNanos() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os) {
            long t = os.getProcessCpuTime();
            if (t >= 0) {
                return t;
            }
        }
        throw new IllegalStateException("this JVM does not report its process CPU time"
                + " (com.sun.management.OperatingSystemMXBean.getProcessCpuTime); run the benchmarks on OpenJDK or HotSpot");
    }

    /** The 1, 5 and 15 minute load averages from /proc/loadavg, e.g. "0.35 0.31 0.13", or the JVM's 1-minute figure elsewhere. */
    public static String loadAverage() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg"), StandardCharsets.US_ASCII).trim().split("\\s+");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (IOException | RuntimeException e) {
            return String.format(Locale.ROOT, "%.2f", ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        }
    }

    /** "machine: 2 cores, load average 0.35 0.31 0.13 (1, 5, 15 min)", to print at the start and end of a run. */
    public static String machineLine() {
        return LOAD_PREFIX + Runtime.getRuntime().availableProcessors() + " cores, load average " + loadAverage()
                + " (1, 5, 15 min)";
    }

    /**
     * "cpu per op: PATH 123.4 us, floor 45.6 us (CPU 2.71×; wall p50 3.02×)": the line that
     * reports a path's CPU against its floor's, measured in the same run.
     */
    public static String ratioLine(String path, double pathCpuMicros, double floorCpuMicros, double wallRatio) {
        return String.format(Locale.ROOT, "cpu per op: %s %.1f us, floor %.1f us (CPU %.2f×; wall %.2f×)",
                path, pathCpuMicros, floorCpuMicros, pathCpuMicros / floorCpuMicros, wallRatio);
    }
}
