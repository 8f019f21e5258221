package org.ripv.services.database;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The embedded database's first start in a short-lived JVM of its own, run with the client
 * compiler only ({@code -XX:TieredStopAtLevel=1}). Creating and seeding Derby is code that runs
 * once: in the service's own JVM most of its CPU went to the optimizing compiler compiling Derby
 * (4–5 s of CPU on 2 cores; 1.9 s with the client compiler only), and the service's JVM must keep
 * that compiler for the queries it will serve for months. Falls back to seeding in-process when
 * the child cannot run. Off with {@code -Dripv.database.seedInChild=false}.
 */
final class SeedInChild {
    private static final Logger log = LoggerFactory.getLogger(SeedInChild.class);
    static final String PROPERTY = "ripv.database.seedInChild";

    private SeedInChild() {}

    static boolean wanted() {
        return !"false".equals(System.getProperty(PROPERTY));
    }

    /** Creates and seeds the database in {@code dataDir} in a child JVM; false when that did not work. */
    static boolean run(Path dataDir, String handle) {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        String classPath = System.getProperty("java.class.path");
        if (!Files.isExecutable(java) || classPath == null || classPath.isBlank()) {
            return false;
        }
        List<String> cmd = new ArrayList<>(List.of(java.toString(), "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC",
                "-Xshare:auto", "-D" + PROPERTY + "=false"));
        for (String p : List.of("derby.storage.useDefaultFilePermissions", "derby.stream.error.file")) {
            String v = System.getProperty(p);
            if (v != null) {
                cmd.add("-D" + p + "=" + v);
            }
        }
        cmd.addAll(List.of("-cp", classPath, SeedInChild.class.getName(), dataDir.toAbsolutePath().toString(), handle));
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.INHERIT).start();
            if (!p.waitFor(10, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                log.warn("the first start's child JVM did not finish in 10 minutes; seeding here instead");
                return false;
            }
            if (p.exitValue() != 0) {
                log.warn("the first start's child JVM failed (exit {}); seeding here instead", p.exitValue());
                return false;
            }
            return Files.isRegularFile(dataDir.resolve(EmbeddedDatabase.CREDENTIALS));
        } catch (IOException e) {
            log.warn("cannot start a JVM for the first start ({}); seeding here instead", e.getMessage());
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /** The child: create and seed, shut Derby down cleanly, exit 0. */
    public static void main(String[] args) throws Exception {
        DatabaseTarget t = EmbeddedDatabase.prepare(Path.of(args[0]), args[1]);
        EmbeddedDatabase.shutdown(t.url(), t.password());
        System.exit(0);
    }
}
