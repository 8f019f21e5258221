package org.ripv.dac;

import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/** The shared rosie_713 files, the sample deployment metadata and QC configuration, and Debian's NetCDF tools. */
final class DacFixtures {
    private DacFixtures() {
    }

    static Path shared() {
        Path dir = Path.of(System.getProperty("user.dir")).toAbsolutePath();
        for (Path p = dir; p != null; p = p.getParent()) {
            Path s = p.resolve("shared/data/slocum-binary");
            if (Files.isDirectory(s)) {
                return s;
            }
        }
        assumeTrue(false, "the shared Slocum data (../shared/data/slocum-binary) is not here");
        return null;
    }

    static Path repo() {
        Path dir = Path.of(System.getProperty("user.dir")).toAbsolutePath();
        return Files.exists(dir.resolve("docs")) ? dir : dir.getParent();
    }

    static Path raw(String name) {
        return shared().resolve("realtime_raw").resolve(name);
    }

    private static Path cacheCopy;

    /**
     * A copy of the shared sensor-list cache, one per test JVM: decoding a file that carries its own
     * list (the recoded .dbd/.ebd, the edited .tbd) keeps that list in the cache, and the shared data
     * must stay as it was (it once gained three stray .cac files on every run).
     */
    static synchronized Path cache() {
        if (cacheCopy == null) {
            try {
                Path copy = Files.createTempDirectory("ripv-dac-cac-");
                try (var files = Files.list(shared().resolve("cac"))) {
                    for (Path f : files.toList()) {
                        Files.copy(f, copy.resolve(f.getFileName()));
                    }
                }
                Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                    try (var files = Files.list(copy)) {
                        for (Path f : files.toList()) {
                            Files.deleteIfExists(f);
                        }
                        Files.deleteIfExists(copy);
                    } catch (IOException ignored) {
                        // a temp folder left behind is harmless
                    }
                }));
                cacheCopy = copy;
            } catch (IOException e) {
                throw new java.io.UncheckedIOException("cannot copy the shared sensor-list cache", e);
            }
        }
        return cacheCopy;
    }

    static Path meta() {
        return repo().resolve("docs/samples/dac-deployment.json");
    }

    static Path qc() {
        return repo().resolve("docs/samples/dac-qc.yml");
    }

    /** Runs a tool, returns its standard output; fails on a non-zero exit. */
    static String run(Path dir, String... cmd) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).start();
        byte[] out = p.getInputStream().readAllBytes();
        assumeTrue(p.waitFor(60, TimeUnit.SECONDS), "timeout");
        String s = new String(out, java.nio.charset.StandardCharsets.UTF_8);
        if (p.exitValue() != 0) {
            throw new AssertionError(String.join(" ", cmd) + " exited " + p.exitValue() + ": " + s);
        }
        return s;
    }

    /** The data rows of a dbd2asc text, each row's values by column. */
    static List<double[]> rows(Path expected, List<String> names) throws IOException {
        List<String> lines = Files.readAllLines(expected);
        int tags = 0;
        for (String l : lines) {
            if (l.startsWith("num_ascii_tags:")) {
                tags = Integer.parseInt(l.substring(l.indexOf(':') + 1).trim());
            }
        }
        names.addAll(List.of(lines.get(tags).trim().split("\\s+")));
        List<double[]> out = new ArrayList<>();
        for (String l : lines.subList(tags + 3, lines.size())) {
            String[] f = l.trim().split("\\s+");
            double[] d = new double[f.length];
            for (int i = 0; i < f.length; i++) {
                d[i] = f[i].equals("NaN") ? Double.NaN : Double.parseDouble(f[i]);
            }
            out.add(d);
        }
        return out;
    }
}
