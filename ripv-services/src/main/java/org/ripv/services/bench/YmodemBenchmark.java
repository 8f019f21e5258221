package org.ripv.services.bench;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.ymodem.YmodemSender;

/**
 * YMODEM throughput as a fraction of what the line can carry, over a {@link YmodemBaudRelay}:
 * our sender to our receiver, lrzsz's {@code sb} to our receiver, our sender to lrzsz's
 * {@code rb}, and lrzsz to lrzsz as the reference (lrzsz rows only when sb, rb and socat are
 * installed). Not a test: it takes minutes, because the line is slow on purpose.
 *
 * <pre>
 * java -cp ripv-services/target/ripv-services.jar org.ripv.services.bench.YmodemBenchmark [BAUD:BYTES]...
 * (default: 9600:65536 115200:1048576)
 * </pre>
 */
public final class YmodemBenchmark {
    private final ExecutorService pool = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "ymodem-benchmark");
        t.setDaemon(true);
        return t;
    });
    private final Path dir;

    private YmodemBenchmark(Path dir) {
        this.dir = dir;
    }

    /** One measured transfer. */
    record Row(String pair, int baud, long bytes, double seconds, boolean identical) {
        double efficiency() {
            return bytes / seconds / (baud / 10.0);
        }

        String markdown() {
            return String.format(Locale.ROOT, "| %s | %d | %d | %.2f | %.0f | %.1f %% | %s |", pair, baud, bytes, seconds,
                    bytes / seconds, 100 * efficiency(), identical ? "yes" : "NO");
        }
    }

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        List<int[]> runs = new ArrayList<>();
        for (String a : args.length == 0 ? new String[] {"9600:65536", "115200:1048576"} : args) {
            String[] p = a.split(":");
            if (p.length != 2) {
                System.err.println("Error: '" + a + "' is not BAUD:BYTES");
                return 2;
            }
            runs.add(new int[] {Integer.parseInt(p[0]), Integer.parseInt(p[1])});
        }
        Path dir = Files.createTempDirectory("ymodem-bench");
        YmodemBenchmark bench = new YmodemBenchmark(dir);
        boolean lrzsz = Socat.installed("sb") && Socat.installed("rb") && Socat.installed("socat");
        System.out.println("| pair (sender → receiver) | baud | bytes | seconds | bytes/s | of line rate | identical |");
        System.out.println("| --- | --- | --- | --- | --- | --- | --- |");
        for (int[] run : runs) {
            byte[] data = new byte[run[1]];
            new Random(run[0]).nextBytes(data);
            Path file = dir.resolve("bench.bin");
            Files.write(file, data);
            System.out.println(bench.ours(run[0], file).markdown());
            if (lrzsz) {
                System.out.println(bench.sbToOurs(run[0], file).markdown());
                System.out.println(bench.oursToRb(run[0], file).markdown());
                System.out.println(bench.sbToRb(run[0], file).markdown());
            }
        }
        if (!lrzsz) {
            System.out.println("(lrzsz or socat not installed: lrzsz rows skipped)");
        }
        return 0;
    }

    private Row ours(int baud, Path file) throws Exception {
        Path out = Files.createDirectories(dir.resolve("ours-" + baud));
        try (ServerSocket receiverSide = new ServerSocket(0);
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, Socat.local(receiverSide.getLocalPort()))) {
            Future<?> receiving = pool.submit((Callable<Object>) () -> {
                try (Socket s = receiverSide.accept(); TcpLink link = new TcpLink(s)) {
                    return new YmodemReceiver(link, YmodemConfig.lrzsz(), null).receiveBatch(new DirectorySink(out));
                }
            });
            long start = System.nanoTime();
            try (TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                new YmodemSender(link, YmodemConfig.lrzsz(), null).sendBatch(List.of(SendFile.of(file)));
            }
            receiving.get(1, TimeUnit.HOURS);
            return new Row("RIPV → RIPV", baud, Files.size(file), (System.nanoTime() - start) / 1e9,
                    Socat.sameBytes(file, out.resolve(file.getFileName())));
        }
    }

    private Row sbToOurs(int baud, Path file) throws Exception {
        Path out = Files.createDirectories(dir.resolve("sb-" + baud));
        return withLrzsz("lrzsz sb → RIPV", baud, file, out, file.getParent(), "sb --ymodem -k -q " + file.getFileName(),
                link -> new YmodemReceiver(link, YmodemConfig.lrzsz(), null).receiveBatch(new DirectorySink(out)));
    }

    private Row oursToRb(int baud, Path file) throws Exception {
        Path out = Files.createDirectories(dir.resolve("rb-" + baud));
        return withLrzsz("RIPV → lrzsz rb", baud, file, out, out, "rb --ymodem -y -q",
                link -> new YmodemSender(link, YmodemConfig.lrzsz(), null).sendBatch(List.of(SendFile.of(file))));
    }

    /** Our end of a transfer with lrzsz, over the link to it. */
    @FunctionalInterface
    private interface OurEnd {
        void transfer(TcpLink link) throws IOException;
    }

    /**
     * One transfer between our end and lrzsz's {@code command} behind socat (run in {@code lrzszDir}),
     * through the relay: timed from our connecting until our end is done.
     */
    private static Row withLrzsz(String pair, int baud, Path file, Path out, Path lrzszDir, String command, OurEnd ours)
            throws Exception {
        try (Socat.Served socat = Socat.serve(lrzszDir, command);
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, socat.address())) {
            long start = System.nanoTime();
            try (TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                ours.transfer(link);
            }
            double seconds = (System.nanoTime() - start) / 1e9;
            socat.process().waitFor(30, TimeUnit.SECONDS);
            return new Row(pair, baud, Files.size(file), seconds, Socat.sameBytes(file, out.resolve(file.getFileName())));
        }
    }

    private Row sbToRb(int baud, Path file) throws Exception {
        Path out = Files.createDirectories(dir.resolve("sbrb-" + baud));
        try (Socat.Served rb = Socat.serve(out, "rb --ymodem -y -q");
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, rb.address())) {
            long start = System.nanoTime();
            Process sb = Socat.call(file.getParent(), relay.port(), "sb --ymodem -k -q " + file.getFileName());
            rb.process().waitFor(1, TimeUnit.HOURS);
            double seconds = (System.nanoTime() - start) / 1e9;
            sb.waitFor(30, TimeUnit.SECONDS);
            return new Row("lrzsz sb → lrzsz rb", baud, Files.size(file), seconds,
                    Socat.sameBytes(file, out.resolve(file.getFileName())));
        }
    }
}
