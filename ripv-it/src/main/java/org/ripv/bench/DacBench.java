package org.ripv.bench;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.ripv.dac.Metadata;
import org.ripv.dac.Profile;
import org.ripv.dac.ProfileSplitter;
import org.ripv.dac.ProfileWriter;
import org.ripv.dac.Profiles;
import org.ripv.dac.QcConfig;
import org.ripv.dac.Segment;
import ucar.ma2.Array;
import ucar.ma2.DataType;
import ucar.nc2.Dimension;
import ucar.nc2.NetcdfFileWriter;
import ucar.nc2.Variable;

/**
 * {@code ./ripv bench dac} (issue 37; a measurement, not a timed test): DAC profile files per
 * second from decoded data — a segment of {@code --yos} dives and climbs, 1 sample / 10 s, split,
 * derived (GSW), QC'd (four tests on temperature, gross range on four more variables), written
 * from the template and renamed into place — against writing the same nine arrays per profile
 * with NetCDF-Java alone (no attributes, no QC), the floor, in the same run. Wall and process CPU
 * per profile, the ratio (target ≤ 1.5×), the load average. Options: {@code --yos N} (default
 * 50), {@code --runs N} (default 5).
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
        List<String> a = new ArrayList<>(Arrays.asList(args));
        boolean shortRun = a.remove("--not-a-measurement");
        int yos = option(a, "--yos", 50);
        int runs = option(a, "--runs", 5);
        if (!a.isEmpty()) {
            System.err.println("Error: unknown options " + a + "; ripv bench dac [--yos N] [--runs N]");
            System.exit(2);
        }
        Metadata meta;
        try (InputStream in = DacBench.class.getResourceAsStream("dac-deployment.json")) {
            meta = Metadata.parse(new ObjectMapper().readTree(in), "dac-deployment.json");
        }
        QcConfig qc = QcConfig.parse(new ObjectMapper(new YAMLFactory()).readTree(QC), "bench QC");
        ProfileWriter writer = new ProfileWriter(meta, qc);
        Segment seg = segment(yos);
        List<Profile> decoded = Profiles.of(seg, ProfileSplitter.defaults());
        Path dir = Files.createTempDirectory("ripv-bench-dac");
        try {
            System.out.printf(Locale.ROOT, "dac: %d yos, %d profiles of about %d samples per run, %d runs%s%n", yos, decoded.size(),
                    decoded.get(0).size(), runs, shortRun ? " (--short: the figures below are not measurements)" : "");
            // warm-up: both paths once
            path(seg, writer, dir);
            floor(decoded, dir);
            double bestPath = Double.MAX_VALUE, bestFloor = Double.MAX_VALUE, cpuPath = 0, cpuFloor = 0;
            int profiles = 0;
            for (int r = 0; r < runs; r++) {
                CpuClock c = CpuClock.start();
                profiles = path(seg, writer, dir);
                double wall = c.wallNanos() / 1e9 / profiles;
                double cpu = c.cpuMicrosPer(profiles);
                CpuClock f = CpuClock.start();
                int n = floor(Profiles.of(seg, ProfileSplitter.defaults()), dir);
                double fwall = f.wallNanos() / 1e9 / n;
                double fcpu = f.cpuMicrosPer(n);
                if (wall < bestPath) {
                    bestPath = wall;
                    cpuPath = cpu;
                }
                if (fwall < bestFloor) {
                    bestFloor = fwall;
                    cpuFloor = fcpu;
                }
                System.out.printf(Locale.ROOT, "run %d: DAC files %.0f profiles/s, NetCDF alone %.0f profiles/s (wall %.2f×)%n",
                        r + 1, 1 / wall, 1 / fwall, wall / fwall);
            }
            System.out.printf(Locale.ROOT, "best: DAC files %.0f profiles/s (split, GSW, QC, template, check-free write and rename)"
                    + " against NetCDF-Java writing the same arrays %.0f profiles/s: %.2f× (target <= 1.5×)%n",
                    1 / bestPath, 1 / bestFloor, bestPath / bestFloor);
            System.out.println(CpuClock.ratioLine("DAC profile file", cpuPath, cpuFloor, bestPath / bestFloor));
            System.out.println(CpuClock.machineLine());
        } finally {
            try (var s = Files.list(dir)) {
                for (Path p : s.toList()) {
                    Files.deleteIfExists(p);
                }
            }
            Files.deleteIfExists(dir);
        }
    }

    /** The product's path from decoded data: split, derive, QC, write each profile's file. */
    static int path(Segment seg, ProfileWriter writer, Path dir) throws Exception {
        List<Profile> ps = Profiles.of(seg, ProfileSplitter.defaults());
        for (Profile p : ps) {
            writer.write(p, dir);
        }
        return ps.size();
    }

    /** The floor: the same nine arrays of each profile written by NetCDF-Java, nothing else. */
    static int floor(List<Profile> ps, Path dir) throws Exception {
        String[] names = {"time", "lat", "lon", "pressure", "depth", "temperature", "conductivity", "salinity", "density"};
        int i = 0;
        for (Profile p : ps) {
            Path f = dir.resolve("floor-" + (i++) + ".nc");
            NetcdfFileWriter w = NetcdfFileWriter.createNew(NetcdfFileWriter.Version.netcdf3, f.toString());
            try {
                Dimension time = w.addUnlimitedDimension("time");
                List<Variable> vars = new ArrayList<>();
                for (String n : names) {
                    vars.add(w.addVariable(null, n, DataType.DOUBLE, time.getShortName()));
                }
                w.create();
                for (int k = 0; k < names.length; k++) {
                    w.write(vars.get(k), new int[] {0}, Array.factory(p.values(names[k])));
                }
            } finally {
                w.close();
            }
        }
        return ps.size();
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
