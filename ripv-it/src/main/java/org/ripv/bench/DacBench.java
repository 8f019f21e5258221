package org.ripv.bench;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import org.ripv.dac.Metadata;
import org.ripv.dac.Profile;
import org.ripv.dac.ProfileChecker;
import org.ripv.dac.ProfileSplitter;
import org.ripv.dac.ProfileWriter;
import org.ripv.dac.Profiles;
import org.ripv.dac.QcConfig;
import org.ripv.dac.Segment;
import ucar.ma2.Array;
import ucar.nc2.Dimension;
import ucar.nc2.NetcdfFileWriter;
import ucar.nc2.Variable;

/**
 * {@code ./ripv bench dac} (issue 37; a measurement, not a timed test): DAC profile files per
 * second from decoded data — a segment of {@code --yos} dives and climbs, 1 sample / 10 s, split,
 * derived (GSW), QC'd (four tests on temperature, gross range on four more variables), written
 * from the template as NAME.tmp and renamed into place — against NetCDF-Java alone writing the
 * same files again, the floor, in the same run: the path's first files read back, every dimension,
 * variable (QC flags included), attribute and value, written anew and checked equal to the path's
 * byte for byte. Both write new files into an empty folder per run, as a deployment does, after
 * a warm-up that lasts until the JIT has next to nothing left to compile. Wall and process CPU per
 * profile, the writing thread's own CPU, bytes allocated, the ratios (target ≤ 1.5×), the load
 * average. Options: {@code --yos N} (default 200), {@code --runs N} (default 5).
 */
public final class DacBench {
    private DacBench() {}

    static final String QC = """
            temperature: {qartod: {gross_range_test: {suspect_span: [0, 30], fail_span: [-2.5, 40]}, spike_test: {suspect_threshold: 0.5, fail_threshold: 2.0}, rate_of_change_test: {threshold: 0.1}, flat_line_test: {tolerance: 0.001, suspect_threshold: 600, fail_threshold: 1800}}}
            conductivity: {qartod: {gross_range_test: {fail_span: [0, 10]}}}
            salinity: {qartod: {gross_range_test: {fail_span: [0, 42]}}}
            density: {qartod: {gross_range_test: {fail_span: [1000, 1040]}}}
            pressure: {qartod: {gross_range_test: {fail_span: [-1, 1000]}}}
            """;

    /** A decoded segment: {@code yos} dives to 100 m and climbs, one sample every 10 s, GPS fixes at both ends. */
    static Segment segment(int yos) {
        int perLeg = 60;
        int n = yos * 2 * perLeg;
        double[] t = new double[n], p = new double[n], temp = new double[n], cond = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = 1.7e9 + i * 10.0;
            int k = i % (2 * perLeg);
            double depthFraction = k < perLeg ? k / (double) perLeg : (2 * perLeg - k) / (double) perLeg;
            p[i] = 0.1 + 10 * depthFraction; // bar
            temp[i] = 14 - 8 * depthFraction + 0.01 * Math.sin(i);
            cond[i] = 4.2 - 0.6 * depthFraction;
        }
        Segment.Track gps = new Segment.Track(new double[] {t[0] - 60, t[n - 1] + 60}, new double[] {41.5, 41.6}, new double[] {-70.5, -70.4});
        return new Segment("bench_1-2024-001-0-1", "bench_1", false, "bench_1-2024-001-0-1.tbd", t, p, temp, cond,
                gps, new Segment.Track(new double[0], new double[0], new double[0]), t[n - 1], 0.05, -0.02);
    }

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        List<String> a = new ArrayList<>(Arrays.asList(args));
        boolean shortRun = a.remove("--not-a-measurement");
        int yos = option(a, "--yos", 200);
        int runs = option(a, "--runs", 5);
        if (!a.isEmpty()) {
            System.err.println("Error: unknown options " + a + "; ripv bench dac [--yos N] [--runs N]");
            return 2;
        }
        Metadata meta;
        try (InputStream in = DacBench.class.getResourceAsStream("dac-deployment.json")) {
            meta = Metadata.parse(new ObjectMapper().readTree(in), "dac-deployment.json");
        }
        QcConfig qc = QcConfig.parse(new ObjectMapper(new YAMLFactory()).readTree(QC), "bench QC");
        ProfileWriter writer = new ProfileWriter(meta, qc);
        ProfileChecker checker = new ProfileChecker();
        Segment seg = segment(yos);
        List<Profile> decoded = Profiles.of(seg, ProfileSplitter.defaults());
        Path dir = Files.createTempDirectory("ripv-bench-dac");
        try {
            System.out.printf(Locale.ROOT, "dac: %d yos, %d profiles of about %d samples per run, %d runs%s%n", yos, decoded.size(),
                    decoded.get(0).size(), runs, shortRun ? " (--short: the figures below are not measurements)" : "");
            // warm-up: both paths once; the floor's files are the path's, read back
            Path first = Files.createDirectory(dir.resolve("first"));
            path(seg, writer, first);
            List<FileContent> contents = new ArrayList<>();
            try (var files = Files.list(first)) {
                for (Path f : files.sorted().toList()) {
                    contents.add(FileContent.read(f));
                }
            }
            // The comparison is honest only if the floor writes what the path writes: the same
            // files, byte for byte (the same variables, attributes, dimensions and values).
            Path firstFloor = Files.createDirectory(dir.resolve("first-floor"));
            floor(contents, firstFloor);
            List<Path> pathFiles, floorFiles;
            try (var a1 = Files.list(first); var b1 = Files.list(firstFloor)) {
                pathFiles = a1.sorted().toList();
                floorFiles = b1.sorted(Comparator.comparingInt(DacBench::floorIndex)).toList();
            }
            long bytes = 0;
            for (int i = 0; i < pathFiles.size(); i++) {
                if (Files.mismatch(pathFiles.get(i), floorFiles.get(i)) != -1) {
                    System.err.println("Error: the floor's " + floorFiles.get(i).getFileName() + " differs from the path's "
                            + pathFiles.get(i).getFileName() + ": the comparison would not be of the same work");
                    return 1;
                }
                bytes += Files.size(pathFiles.get(i));
            }
            System.out.printf(Locale.ROOT, "the floor's %d files are the path's byte for byte (%d bytes a file on average)%n",
                    pathFiles.size(), bytes / Math.max(1, pathFiles.size()));
            BenchTools.deleteTree(first);
            BenchTools.deleteTree(firstFloor);
            // The JIT's warm-up, for both: rounds of the path and the floor until a round leaves the
            // compilers next to nothing new to compile (code run once per profile reaches C2 only
            // after thousands of profiles; compiled during the timed runs, it was counted against
            // the path, whose code is the larger). At least 5 rounds, at most 60; --short: one.
            var jit = ManagementFactory.getCompilationMXBean();
            int warm = 0;
            long compiledBefore = jit.getTotalCompilationTime();
            while (warm < (shortRun ? 1 : 60)) {
                Path wp = Files.createDirectory(dir.resolve("warm-path"));
                path(seg, writer, wp);
                BenchTools.deleteTree(wp);
                Path wf = Files.createDirectory(dir.resolve("warm-floor"));
                floor(contents, wf);
                BenchTools.deleteTree(wf);
                Path wc = Files.createDirectory(dir.resolve("warm-checked"));
                checked(seg, writer, checker, wc);
                BenchTools.deleteTree(wc);
                warm++;
                long compiled = jit.getTotalCompilationTime();
                if (shortRun || (warm >= 5 && compiled - compiledBefore <= 5)) {
                    break;
                }
                compiledBefore = compiled;
            }
            System.out.printf(Locale.ROOT, "warm-up: %d round%s of both%s%n", warm, warm == 1 ? "" : "s",
                    shortRun ? " (--short: one)" : " (until a round left the JIT under 5 ms of compiling)");
            // Per run, the path, the floor, then the path with its check, each into an empty folder of its own: files are new,
            // as a deployment's profiles are. (Writing over the last run's files measured the file
            // system instead: the floor rewrote blocks in place while the path's rename replaced an
            // existing file, which ext4 makes flush the new file's blocks first, auto_da_alloc.)
            // CPU summed over all runs (the process clock ticks in 10 ms, too coarse for one run),
            // wall as the median of the runs' ratios.
            long cpuPath = 0, cpuFloor = 0, threadPath = 0, threadFloor = 0, nPath = 0, nFloor = 0;
            double bytesPath = 0, bytesFloor = 0;
            long cpuChecked = 0, nChecked = 0, userPath = 0, userFloor = 0;
            double[] ratios = new double[runs];
            double bestPath = 0, bestFloor = 0;
            ThreadMXBean mx = ManagementFactory.getThreadMXBean();
            for (int r = 0; r < runs; r++) {
                Path pd = Files.createDirectory(dir.resolve("path-" + r));
                Path fd = Files.createDirectory(dir.resolve("floor-" + r));
                long t0 = mx.getCurrentThreadCpuTime();
                long u0 = mx.getCurrentThreadUserTime();
                CpuClock c = CpuClock.start();
                int profiles = path(seg, writer, pd);
                double wall = c.wallNanos() / 1e9 / profiles;
                cpuPath += c.cpuNanos();
                threadPath += mx.getCurrentThreadCpuTime() - t0;
                userPath += mx.getCurrentThreadUserTime() - u0;
                bytesPath += c.bytesAllocatedPer(1);
                nPath += profiles;
                long t1 = mx.getCurrentThreadCpuTime();
                long u1 = mx.getCurrentThreadUserTime();
                CpuClock f = CpuClock.start();
                int n = floor(contents, fd);
                double fwall = f.wallNanos() / 1e9 / n;
                cpuFloor += f.cpuNanos();
                threadFloor += mx.getCurrentThreadCpuTime() - t1;
                userFloor += mx.getCurrentThreadUserTime() - u1;
                bytesFloor += f.bytesAllocatedPer(1);
                nFloor += n;
                Path cd = Files.createDirectory(dir.resolve("checked-" + r));
                CpuClock k = CpuClock.start();
                int nc = checked(seg, writer, checker, cd);
                cpuChecked += k.cpuNanos();
                nChecked += nc;
                BenchTools.deleteTree(pd);
                BenchTools.deleteTree(fd);
                BenchTools.deleteTree(cd);
                ratios[r] = wall / fwall;
                bestPath = Math.max(bestPath, 1 / wall);
                bestFloor = Math.max(bestFloor, 1 / fwall);
                System.out.printf(Locale.ROOT, "run %d: DAC files %.0f profiles/s, NetCDF alone %.0f profiles/s (wall %.2f×)%n",
                        r + 1, 1 / wall, 1 / fwall, ratios[r]);
            }
            Arrays.sort(ratios);
            double median = ratios[runs / 2];
            if (cpuFloor == 0 || cpuPath == 0) {
                // the process clock ticks in 10 ms: a run this short has no CPU figure to give
                System.out.printf(Locale.ROOT, "DAC files against NetCDF-Java writing the same files alone: wall median %.2f×;"
                        + " CPU not measured (the run is shorter than the process clock's 10 ms tick)%n", ratios[runs / 2]);
                System.out.println(CpuClock.machineLine());
                return 0;
            }
            double cpuRatio = (cpuPath / (double) nPath) / (cpuFloor / (double) nFloor);
            System.out.printf(Locale.ROOT, "DAC files (split, GSW, QC, template, write and rename) against NetCDF-Java writing the same"
                    + " files alone: best %.0f against %.0f profiles/s; wall median %.2f×, CPU %.2f× (target <= 1.5×), load average %s%n",
                    bestPath, bestFloor, median, cpuRatio, CpuClock.loadAverage());
            System.out.printf(Locale.ROOT, "the writing thread's own CPU: %.1f us against %.1f us a profile (%.2f×); the rest of the"
                    + " process CPU (the collector, the JIT): %.1f us against %.1f us; allocated %.0f KiB against %.0f KiB a profile%n",
                    threadPath / 1e3 / nPath, threadFloor / 1e3 / nFloor, (threadPath / (double) nPath) / (threadFloor / (double) nFloor),
                    (cpuPath - threadPath) / 1e3 / nPath, (cpuFloor - threadFloor) / 1e3 / nFloor, bytesPath / 1024 / nPath, bytesFloor / 1024 / nFloor);
            // Creating a file costs the kernel more than either's Java work on ext4: its user time alone is the Java side's ratio.
            System.out.printf(Locale.ROOT, "the writing thread's user time (the Java side, without the kernel's file creation and writing): %.1f us"
                    + " against %.1f us (%.2f×)%n", userPath / 1e3 / nPath, userFloor / 1e3 / nFloor,
                    (userPath / (double) nPath) / (userFloor / (double) nFloor));
            System.out.printf(Locale.ROOT, "as a deployment makes them, each file also read back and checked against the template"
                    + " before it takes its name (the floor does not check): %.1f us CPU a profile, %.2f× the floor's (reported, not the target)%n",
                    cpuChecked / 1e3 / nChecked, (cpuChecked / (double) nChecked) / (cpuFloor / (double) nFloor));
            System.out.println(CpuClock.ratioLine("DAC profile file", cpuPath / 1e3 / nPath, cpuFloor / 1e3 / nFloor, median));
            System.out.println(CpuClock.machineLine());
        } finally {
            BenchTools.deleteTree(dir);
        }
        return 0;
    }

    /** The floor's file profile-N.nc: N. */
    private static int floorIndex(Path f) {
        String n = f.getFileName().toString();
        return Integer.parseInt(n.substring("profile-".length(), n.length() - ".nc".length()));
    }

    /** The product's path from decoded data: split, derive, QC, write each profile's file. */
    static int path(Segment seg, ProfileWriter writer, Path dir) throws Exception {
        List<Profile> ps = Profiles.of(seg, ProfileSplitter.defaults());
        for (Profile p : ps) {
            writer.write(p, dir);
        }
        return ps.size();
    }

    /**
     * The same as a deployment makes them: each file also read back and checked against the
     * template (ProfileChecker) before it takes its name, which the floor does not do.
     */
    static int checked(Segment seg, ProfileWriter writer, ProfileChecker checker, Path dir) throws Exception {
        List<Profile> ps = Profiles.of(seg, ProfileSplitter.defaults());
        ProfileChecker.Report[] report = new ProfileChecker.Report[1];
        for (Profile p : ps) {
            writer.write(p, dir, checker, report);
            if (!report[0].passed()) {
                throw new IllegalStateException(report[0].file() + " fails the check: " + report[0].failures());
            }
        }
        return ps.size();
    }

    /**
     * A file's dimensions, variables (type, dimensions, attributes, values) and global attributes,
     * everything the floor hands NetCDF-Java taken out of the read-back file beforehand, so that the
     * floor's time is NetCDF-Java's writing alone.
     */
    record FileContent(List<Dimension> dims, List<Var> vars, List<ucar.nc2.Attribute> globals) {
        record Var(String name, ucar.ma2.DataType type, String dims, List<ucar.nc2.Attribute> attributes, boolean unlimited, Array values) {}

        static FileContent read(Path f) throws Exception {
            try (ucar.nc2.NetcdfFile nc = ucar.nc2.NetcdfFile.open(f.toString())) {
                List<Var> vars = new ArrayList<>();
                for (Variable v : nc.getVariables()) {
                    vars.add(new Var(v.getShortName(), v.getDataType(), v.getDimensionsString(), List.copyOf(v.getAttributes()),
                            v.isUnlimited(), v.read()));
                }
                return new FileContent(List.copyOf(nc.getDimensions()), List.copyOf(vars), List.copyOf(nc.getGlobalAttributes()));
            }
        }
    }

    /** The floor: NetCDF-Java alone writing each file again — the same dimensions, variables, attributes and arrays. */
    static int floor(List<FileContent> files, Path dir) throws Exception {
        int i = 0;
        int[] origin = {0};
        List<Variable> vars = new ArrayList<>();
        for (FileContent c : files) {
            Path f = dir.resolve("profile-" + (i++) + ".nc");
            NetcdfFileWriter w = NetcdfFileWriter.createNew(NetcdfFileWriter.Version.netcdf3, f.toString());
            try {
                for (Dimension d : c.dims()) {
                    if (d.isUnlimited()) {
                        w.addUnlimitedDimension(d.getShortName());
                    } else {
                        w.addDimension(null, d.getShortName(), d.getLength());
                    }
                }
                vars.clear();
                for (FileContent.Var v : c.vars()) {
                    Variable nv = w.addVariable(null, v.name(), v.type(), v.dims());
                    for (ucar.nc2.Attribute a : v.attributes()) {
                        w.addVariableAttribute(nv, a);
                    }
                    vars.add(nv);
                }
                for (ucar.nc2.Attribute a : c.globals()) {
                    w.addGroupAttribute(null, a);
                }
                w.create();
                for (int k = 0; k < vars.size(); k++) {
                    FileContent.Var v = c.vars().get(k);
                    if (v.unlimited()) {
                        w.write(vars.get(k), origin, v.values());
                    } else {
                        w.write(vars.get(k), v.values());
                    }
                }
            } finally {
                w.close();
            }
        }
        return files.size();
    }

    private static int option(List<String> a, String name, int dflt) {
        int i = a.indexOf(name);
        if (i < 0) {
            return dflt;
        }
        if (i + 1 >= a.size()) {
            System.err.println("Error: " + name + " needs a number");
            System.exit(2);
        }
        int v = Integer.parseInt(a.get(i + 1));
        a.remove(i + 1);
        a.remove(i);
        return v;
    }
}
