package org.ripv.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

/**
 * Another process's CPU time split by what its threads do, from {@code /proc/PID/task}: the JIT
 * compilers, the garbage collector (and the VM thread that runs its pauses), and everything else —
 * the process's own work. {@code bench web} prints it beside each phase's CPU per delivery: a
 * JVM still compiling its path in the measured seconds spends CPU a server that has run for hours
 * no longer does, and the split says how much of a figure that was.
 */
final class ThreadCpu {
    /** CPU nanoseconds of one phase by kind. */
    record Split(long jitNanos, long gcNanos, long restNanos) {
        long totalNanos() {
            return jitNanos + gcNanos + restNanos;
        }
    }

    /** Each live thread's kind and CPU ticks at one moment; threads gone since keep what they had at the first snapshot only. */
    record Snapshot(Map<Long, Long> ticks, Map<Long, Kind> kinds) {}

    enum Kind { JIT, GC, REST }

    private ThreadCpu() {}

    static Snapshot snapshot(long pid) throws IOException {
        Map<Long, Long> ticks = new HashMap<>();
        Map<Long, Kind> kinds = new HashMap<>();
        try (DirectoryStream<Path> tasks = Files.newDirectoryStream(Path.of("/proc", Long.toString(pid), "task"))) {
            for (Path t : tasks) {
                try {
                    String stat = Files.readString(t.resolve("stat"), StandardCharsets.US_ASCII);
                    String name = stat.substring(stat.indexOf('(') + 1, stat.lastIndexOf(')'));
                    String[] f = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
                    long tid = Long.parseLong(t.getFileName().toString());
                    ticks.put(tid, Long.parseLong(f[11]) + Long.parseLong(f[12])); // utime, stime
                    kinds.put(tid, kind(name));
                } catch (IOException | RuntimeException gone) {
                    // the thread ended between listing and reading
                }
            }
        }
        return new Snapshot(ticks, kinds);
    }

    /** HotSpot's thread names as the kernel keeps them (15 characters). */
    static Kind kind(String name) {
        if (name.startsWith("C1 CompilerThre") || name.startsWith("C2 CompilerThre")) {
            return Kind.JIT;
        }
        if (name.startsWith("GC Thread") || name.startsWith("G1 ") || name.equals("VM Thread")) {
            return Kind.GC;
        }
        return Kind.REST;
    }

    /** What each kind spent between the two snapshots (a thread that ended between them is left out). */
    static Split between(Snapshot before, Snapshot after) {
        long[] by = new long[Kind.values().length];
        after.ticks().forEach((tid, t) -> by[after.kinds().get(tid).ordinal()] += t - before.ticks().getOrDefault(tid, 0L));
        long tick = 10_000_000L; // USER_HZ 100
        return new Split(by[Kind.JIT.ordinal()] * tick, by[Kind.GC.ordinal()] * tick, by[Kind.REST.ordinal()] * tick);
    }
}
