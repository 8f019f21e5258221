package org.ripv.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;
import org.ripv.server.RIPVServer;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.PermitFile;

/**
 * What the benchmarks share: their figures' median, their {@code --name N} options, the scratch
 * directory they delete, the in-process server with its {@code bench} user. One place, so that
 * every bench reads its options and reduces its runs the same way.
 */
public final class BenchTools {
    /** The user the in-process benchmarks log in as. */
    public static final String USER = "bench";
    /** Its password. */
    public static final String PASSWORD = "bench-password";

    private BenchTools() {}

    /** The median of the runs' figures (NaN for none). */
    public static double median(double[] values) {
        double[] s = values.clone();
        Arrays.sort(s);
        return s.length == 0 ? Double.NaN : s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }

    /** The whole number after {@code name} in {@code args}, or {@code dflt} when it is not given. */
    public static int intOption(String[] args, String name, int dflt) {
        String v = stringOption(args, name, null);
        return v == null ? dflt : Integer.parseInt(v);
    }

    /** The word after {@code name} in {@code args}, or {@code dflt} when it is not given. */
    public static String stringOption(String[] args, String name, String dflt) {
        for (int i = 0; i + 1 < args.length; i++) {
            if (args[i].equals(name)) {
                return args[i + 1];
            }
        }
        return dflt;
    }

    /** Deletes {@code dir} and everything under it. */
    public static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }

    /** What a benchmark does in its scratch directory. */
    @FunctionalInterface
    public interface InScratch {
        void run(Path dir) throws Exception;
    }

    /** Runs {@code body} in a new temporary directory named after {@code prefix}, deleted afterwards however it ends. */
    public static void inScratchDirectory(String prefix, InScratch body) throws Exception {
        Path dir = Files.createTempDirectory(prefix);
        try {
            body.run(dir);
        } finally {
            deleteTree(dir);
        }
    }

    /** A server started in {@code dir} (its test configuration) with {@link #USER} an operator. */
    public static RIPVServer serverWithOperator(Path dir) throws Exception {
        ServerConfig config = ServerConfig.forTests(dir);
        RIPVServer server = new RIPVServer(config);
        server.start();
        PermitFile.setUser(config.dataDir().resolve("permit.txt"), USER, PASSWORD.toCharArray(), List.of("operators"), 1000);
        server.reloadPermits();
        return server;
    }
}
