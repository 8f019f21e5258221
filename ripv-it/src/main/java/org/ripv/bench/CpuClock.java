package org.ripv.bench;

import com.sun.management.OperatingSystemMXBean;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

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
    private final Map<Long, Long> threads0 = threadCpu();
    private final Map<Long, String> names0 = threadNames();
    private final Map<Long, Long> allocated0 = threadAllocated();

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

    /**
     * Where the CPU went since {@link #start()}, per operation: microseconds per kind of thread
     * (names with their numbers and client ids taken off), largest first, and what no Java thread
     * accounts for (the JIT compilers, the garbage collector) as "JVM: JIT and GC".
     */
    public Map<String, Double> microsPerThreadKind(long operations) {
        Map<Long, Long> now = threadCpu();
        Map<Long, String> names = threadNames();
        names.putAll(names0);
        Map<String, Double> kinds = new TreeMap<>();
        double javaThreads = 0;
        for (Map.Entry<Long, Long> e : now.entrySet()) {
            long spent = e.getValue() - threads0.getOrDefault(e.getKey(), 0L);
            String kind = kind(names.getOrDefault(e.getKey(), "?"));
            double micros = spent / 1e3 / Math.max(1, operations);
            kinds.merge(kind, micros, Double::sum);
            javaThreads += micros;
        }
        kinds.put("JVM: JIT and GC (no Java thread)", Math.max(0, cpuMicrosPer(operations) - javaThreads));
        Map<String, Double> sorted = new LinkedHashMap<>();
        kinds.entrySet().stream().sorted(Map.Entry.<String, Double>comparingByValue().reversed())
                .forEach(e -> sorted.put(e.getKey(), e.getValue()));
        return sorted;
    }

    /**
     * Bytes the process's Java threads allocated per operation since {@link #start()} (the JVM's
     * per-thread allocation counters; a thread that ended meanwhile is not counted), or -1 where
     * the JVM does not count them. What the collector has to clean up after each operation.
     */
    public double bytesAllocatedPer(long operations) {
        Map<Long, Long> now = threadAllocated();
        if (now.isEmpty()) {
            return -1;
        }
        long sum = 0;
        for (Map.Entry<Long, Long> e : now.entrySet()) {
            sum += e.getValue() - allocated0.getOrDefault(e.getKey(), 0L);
        }
        return (double) sum / Math.max(1, operations);
    }

    private static Map<Long, Long> threadAllocated() {
        Map<Long, Long> m = new HashMap<>();
        if (ManagementFactory.getThreadMXBean() instanceof com.sun.management.ThreadMXBean mx && mx.isThreadAllocatedMemorySupported()
                && mx.isThreadAllocatedMemoryEnabled()) {
            long[] ids = mx.getAllThreadIds();
            long[] bytes = mx.getThreadAllocatedBytes(ids);
            for (int i = 0; i < ids.length; i++) {
                if (bytes[i] >= 0) {
                    m.put(ids[i], bytes[i]);
                }
            }
        }
        return m;
    }

    /** "ripv-socket-handler-123456" and "RMI TCP Connection(12)-127.0.0.1" become one kind each. */
    static String kind(String threadName) {
        return threadName.replaceAll("\\(\\d+\\)", "(n)").replaceAll("[-#:]?[0-9][0-9.:]*$", "").replaceAll("-\\d{6,}", "");
    }

    private static Map<Long, Long> threadCpu() {
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        Map<Long, Long> m = new HashMap<>();
        if (!mx.isThreadCpuTimeSupported()) {
            return m;
        }
        for (long id : mx.getAllThreadIds()) {
            long t = mx.getThreadCpuTime(id);
            if (t >= 0) {
                m.put(id, t);
            }
        }
        return m;
    }

    private static Map<Long, String> threadNames() {
        Map<Long, String> m = new HashMap<>();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            m.put(t.getId(), t.getName());
        }
        return m;
    }

    /** All threads' CPU time of this JVM, from the operating system (Linux: /proc/self/stat's utime + stime). */
    public static long processCpuNanos() {
        if (ManagementFactory.getOperatingSystemMXBean() instanceof OperatingSystemMXBean os) {
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
