package org.ripv.bench;

import java.io.FileOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Properties;

/**
 * The named {@code ripv bench NAME --short} runs in one JVM, one after the other (issue 38: fifteen
 * JVMs, each starting Derby, RMI, Jetty and the JIT anew, made {@code EveryBenchmarkRunsTest} the
 * slowest class of the suite; it now starts a few of these side by side, each with its share of the
 * runs, as most of a short run waits rather than computes). Each run's output goes to {@code DIR/NAME.log} and its exit status to
 * {@code DIR/NAME.exit}; a run that throws has its stack trace in its log and status 1.
 *
 * <pre>java -cp ripv-it.jar org.ripv.bench.ShortRuns DIR NAME...</pre>
 */
public final class ShortRuns {
    private ShortRuns() {}

    public static void main(String[] args) throws Exception {
        Path dir = Files.createDirectories(Path.of(args[0]));
        PrintStream out = System.out;
        PrintStream err = System.err;
        for (int i = 1; i < args.length; i++) {
            String name = args[i];
            int status;
            long t0 = System.nanoTime();
            // One run's system properties (Derby's log file in a folder it deletes, known_hosts) are not the next one's.
            Properties before = (Properties) System.getProperties().clone();
            try (PrintStream log = new PrintStream(new FileOutputStream(dir.resolve(name + ".log").toFile()), true,
                    StandardCharsets.UTF_8)) {
                System.setOut(log);
                System.setErr(log);
                try {
                    status = BenchMain.run(new String[] {name, ShortMode.FLAG});
                } catch (Throwable t) {
                    t.printStackTrace(log);
                    status = 1;
                } finally {
                    System.setOut(out);
                    System.setErr(err);
                    System.setProperties(before);
                }
            }
            Files.writeString(dir.resolve(name + ".exit"), Integer.toString(status));
            out.printf("ripv bench %s --short: exit %d in %.1f s%n", name, status, (System.nanoTime() - t0) / 1e9);
        }
        System.exit(0); // the benchmarks' RMI and server threads are not all daemons
    }
}
