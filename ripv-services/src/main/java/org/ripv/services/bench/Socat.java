package org.ripv.services.bench;

import java.io.File;
import java.io.IOException;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.ripv.probe.FreePorts;

/**
 * lrzsz's programs ({@code sb}, {@code rb}, {@code sz}, {@code rz}) on a loopback TCP port through
 * socat, as the transfer benchmarks ({@link YmodemBenchmark}, the ZMODEM bench of ripv-it) put
 * them at the far end of a paced relay; and the checks around them (is the tool installed, did
 * the file arrive whole).
 */
public final class Socat {
    private Socat() {}

    /** 127.0.0.1:port, where a relay finds the program socat serves. */
    public static InetSocketAddress local(int port) {
        return new InetSocketAddress("127.0.0.1", port);
    }

    /** {@code program} (e.g. {@code rb --ymodem -y -q}) run in {@code cwd} for the one connection socat accepts on {@code port}. */
    public static Process listen(Path cwd, int port, String program) throws IOException {
        return start(cwd, "TCP-LISTEN:" + port + ",bind=127.0.0.1,reuseaddr", "SYSTEM:'exec " + program + "'");
    }

    /** A program socat serves on a loopback port; closing it ends the program. */
    public record Served(Process process, int port) implements AutoCloseable {
        /** Where a relay finds it. */
        public InetSocketAddress address() {
            return local(port);
        }

        @Override
        public void close() {
            process.destroy();
        }
    }

    /**
     * {@code program} run in {@code cwd} for the one connection socat accepts on a free loopback
     * port, listening by the time this returns ({@link #awaitListening}).
     */
    public static Served serve(Path cwd, String program) throws IOException, InterruptedException {
        int port = FreePorts.one();
        Served served = new Served(listen(cwd, port, program), port);
        try {
            awaitListening(port);
            return served;
        } catch (IOException | InterruptedException | RuntimeException e) {
            served.close();
            throw e;
        }
    }

    /** {@code program} run in {@code cwd}, connected to 127.0.0.1:port. */
    public static Process call(Path cwd, int port, String program) throws IOException {
        return start(cwd, "TCP:127.0.0.1:" + port, "SYSTEM:'exec " + program + "'");
    }

    private static Process start(Path cwd, String a, String b) throws IOException {
        return new ProcessBuilder("socat", a, b).directory(cwd.toFile()).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
    }

    /**
     * Until socat listens on {@code port}: otherwise a relay's first connect may come before it,
     * and its retry a moment later falls inside the timed transfer (one row 0.1 s slower than its
     * pair for no fault of either end). Read from the kernel's table, since a test connection would
     * take the one connection socat accepts. Where there is no such table (not Linux) it returns
     * at once, and the relay's own retries wait for socat.
     */
    public static void awaitListening(int port) throws IOException, InterruptedException {
        List<Path> tables = List.of(Path.of("/proc/net/tcp"), Path.of("/proc/net/tcp6"));
        if (tables.stream().noneMatch(Files::isReadable)) {
            return;
        }
        String local = String.format(Locale.ROOT, ":%04X ", port);
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (System.nanoTime() < deadline) {
            for (Path t : tables) {
                if (Files.isReadable(t)) {
                    for (String line : Files.readAllLines(t)) {
                        String[] f = line.trim().split("\\s+");
                        if (f.length > 3 && (f[1] + " ").endsWith(local) && f[3].equals("0A")) {
                            return;
                        }
                    }
                }
            }
            Thread.sleep(5);
        }
        throw new IOException("socat did not listen on port " + port + " within 10 s");
    }

    /** True when {@code received} exists and holds exactly {@code sent}'s bytes. */
    public static boolean sameBytes(Path sent, Path received) throws IOException {
        return Files.exists(received) && Arrays.equals(Files.readAllBytes(sent), Files.readAllBytes(received));
    }

    /** True when an executable {@code tool} is on the PATH. */
    public static boolean installed(String tool) {
        for (String d : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(d, tool))) {
                return true;
            }
        }
        return false;
    }
}
