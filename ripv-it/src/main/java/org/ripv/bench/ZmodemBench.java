package org.ripv.bench;

import static org.ripv.bench.BenchTools.median;

import java.lang.management.ManagementFactory;
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
import org.ripv.services.bench.Socat;
import org.ripv.services.bench.YmodemBaudRelay;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.zmodem.ResumeStore;
import org.ripv.services.serial.zmodem.ZmodemReceiver;
import org.ripv.services.serial.zmodem.ZmodemSender;

/**
 * {@code ./ripv bench zmodem}: ZMODEM over a baud-paced relay as a share of the line rate,
 * against lrzsz's {@code sz}/{@code rz} on the same relay in the same run; and over an
 * Iridium-like link (2,400 baud, 1 s latency, a drop every 60 s) the calls needed to move
 * 100 KB with ZMODEM's resume against YMODEM, which restarts a cut file from zero ({@link IridiumCalls}). Beside wall
 * time, the CPU time of RIPV's transfer threads for each operation (not the in-process relay's,
 * nor lrzsz's) and the load average (the machine may be shared: read the figures with it).
 *
 * <pre>
 * ripv bench zmodem [--baud N] [--bytes N] [--iridium-baud N] [--latency MS] [--drop-every S]
 *                   [--iridium-bytes N] [--max-calls N] [--ymodem-calls N] [--skip-iridium] [--file PATH]
 * </pre>
 *
 * <p>The bytes sent are random by default: the hardest case, since ZMODEM escapes 7 of the 256
 * byte values and random data has 2.7 % of them. {@code --file} sends a file's bytes instead, such
 * as a glider's own binary files joined together, whose share of escaped bytes is what a link
 * really carries (the shared Slocum files: 0.18 %).
 */
public final class ZmodemBench {
    private final ExecutorService pool = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "zmodem-bench");
        t.setDaemon(true);
        return t;
    });
    private final Path dir;
    /**
     * How long RIPV's sender waits for each answer. The relay's sockets take the whole file at
     * once (loopback buffers run to megabytes) and pace it out at the baud rate, so the answer to
     * ZEOF comes only when the line has drained: 1 MiB at 115200 baud is 91 s behind. Over a real
     * serial line the UART's few bytes of buffer keep the sender in step and 10 s is plenty.
     * These rows stand for a serial line, so RIPV's sender streams as it does on one (no window,
     * as {@code sz} without {@code -w}); the windowed row is RIPV's sender as it runs on a TCP link.
     */
    private static final int SENDER_TIMEOUT_MILLIS = 60_000;
    /**
     * lrzsz's sender, for the same reason without its timeouts ({@code -O}): at 1 MiB it gave up
     * waiting for the answer to ZEOF (CAN CAN CAN…) while the file was still draining from the
     * relay's buffers.
     */
    static final String SZ = "sz -q -O ";

    private ZmodemBench(Path dir) {
        this.dir = dir;
    }

    /** CPU time of the calling thread: the transfer's own work, not the in-process relay's pacing. */
    static long cpuNanos() {
        return ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
    }

    static double load() {
        return ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage();
    }

    record Row(String pair, int baud, long bytes, double seconds, double cpuSeconds, double load, boolean identical) {
        String markdown() {
            return String.format(Locale.ROOT, "| %s | %d | %d | %.2f | %.0f | %.1f %% | %.2f | %.2f | %s |", pair, baud,
                    bytes, seconds, bytes / seconds, 100 * bytes / seconds / (baud / 10.0), cpuSeconds, load,
                    identical ? "yes" : "NO");
        }
    }

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int baud = 115200;
        int bytes = 1 << 20;
        int iBaud = 2400;
        long latency = 1000;
        long dropEvery = 60;
        int iBytes = 100 * 1024;
        int maxCalls = 30;
        int ymodemCalls = 3;
        int rounds = 1;
        boolean iridium = true;
        Path source = null;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--skip-iridium")) {
                iridium = false;
                continue;
            }
            if (a.equals("--file") && i + 1 < args.length) {
                source = Path.of(args[++i]);
                if (!Files.isRegularFile(source) || Files.size(source) == 0) {
                    System.err.println("Error: --file " + source + ": no such file, or it is empty");
                    return 2;
                }
                continue;
            }
            if (i + 1 >= args.length) {
                System.err.println("Error: '" + a + "' needs a value (ripv bench --help)");
                return 2;
            }
            long v;
            try {
                v = Long.parseLong(args[++i]);
            } catch (NumberFormatException e) {
                System.err.println("Error: " + a + " takes a whole number, got '" + args[i] + "'");
                return 2;
            }
            if (v <= 0 && !(a.equals("--latency") && v == 0)) { // a link with no latency is a fair case
                System.err.println("Error: " + a + (a.equals("--latency") ? " must not be negative" : " must be above 0") + ", got " + v);
                return 2;
            }
            switch (a) {
                case "--baud" -> baud = (int) v;
                case "--bytes" -> bytes = (int) v;
                case "--iridium-baud" -> iBaud = (int) v;
                case "--latency" -> latency = v;
                case "--drop-every" -> dropEvery = v;
                case "--iridium-bytes" -> iBytes = (int) v;
                case "--max-calls" -> maxCalls = (int) v;
                case "--ymodem-calls" -> ymodemCalls = (int) v;
                case "--rounds" -> rounds = (int) v;
                default -> {
                    System.err.println("Error: unknown option '" + a + "' (ripv bench --help)");
                    return 2;
                }
            }
        }
        if (!Socat.installed("sz") || !Socat.installed("rz") || !Socat.installed("sb") || !Socat.installed("socat")) {
            System.err.println("Error: the ZMODEM benchmark compares with lrzsz: install lrzsz and socat");
            return 1;
        }
        Path dir = Files.createTempDirectory("zmodem-bench");
        ZmodemBench bench = new ZmodemBench(dir);
        System.out.printf(Locale.ROOT, "%d cores; load average %.2f at start%n%n", Runtime.getRuntime().availableProcessors(), load());
        byte[] data;
        if (source == null) {
            data = new byte[bytes];
            new Random(24).nextBytes(data);
        } else {
            data = Files.readAllBytes(source);
        }
        Path file = dir.resolve("bench.bin");
        Files.write(file, data);
        long escapes = escaped(data);
        System.out.printf(Locale.ROOT, "sending %s: %,d bytes, %.2f %% of them escaped by ZMODEM (the line's ceiling %.2f %%)%n%n",
                source == null ? "random bytes" : source, data.length, 100.0 * escapes / data.length,
                100.0 * data.length / (data.length + escapes + 6.0 * Math.ceil(data.length / 1024.0)));
        System.out.println("| pair (sender → receiver) | baud | bytes | seconds | bytes/s | of line rate | RIPV CPU s | load | identical |");
        System.out.println("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
        List<Row> senders = new ArrayList<>();
        List<Row> receivers = new ArrayList<>();
        List<Row> windowedSenders = new ArrayList<>();
        for (int round = 1; round <= rounds; round++) {
            System.out.println(bench.ours(baud, file).markdown());
            Row szToOurs = bench.szToOurs(baud, file);
            System.out.println(szToOurs.markdown());
            // the two senders into rz take turns at going first, so neither always follows the other's load
            Row oursToRz;
            Row szToRz;
            if (round % 2 == 1) {
                System.out.println((oursToRz = bench.oursToRz(baud, file)).markdown());
                System.out.println((szToRz = bench.szToRz(baud, file)).markdown());
            } else {
                szToRz = bench.szToRz(baud, file);
                System.out.println(szToRz.markdown());
                System.out.println((oursToRz = bench.oursToRz(baud, file)).markdown());
            }
            senders.add(oursToRz);
            senders.add(szToRz);
            Row windowed = bench.oursToRz(baud, file, ZmodemSender.DEEP_LINK_WINDOW, "RIPV → lrzsz rz, windowed as on a TCP link");
            System.out.println(windowed.markdown());
            windowedSenders.add(windowed);
            windowedSenders.add(szToRz);
            receivers.add(szToOurs);
            receivers.add(szToRz);
        }
        System.out.println();
        System.out.println("RIPV → RIPV starts about 1 s later than the others: neither RIPV end speaks first (each waits a second"
                + " of silence, so as not to type into a vehicle's shell), where sz announces itself at once.");
        System.out.println(versus("RIPV's sender", "sz", senders));
        System.out.println(versus("RIPV's receiver", "rz", receivers));
        System.out.println(versus("RIPV's sender with its TCP window (" + ZmodemSender.DEEP_LINK_WINDOW + " bytes, a ZACK asked for every"
                + " quarter)", "sz", windowedSenders));
        if (iridium) {
            byte[] log = new byte[iBytes];
            new Random(25).nextBytes(log);
            Path small = Files.createDirectories(dir.resolve("vehicle")).resolve("01230000.DBD");
            Files.write(small, log);
            System.out.printf(Locale.ROOT, "%nIridium-like link: %d baud, %d ms latency, the call drops every %d s; %d bytes%n%n",
                    iBaud, latency, dropEvery, iBytes);
            System.out.println("| protocol | calls | done | bytes moved per call | wall s | RIPV CPU s | load |");
            System.out.println("| --- | --- | --- | --- | --- | --- | --- |");
            IridiumCalls calls = new IridiumCalls(dir, iBaud, latency, dropEvery);
            System.out.println(calls.zmodem(small, maxCalls));
            System.out.println(calls.ymodem(small, ymodemCalls));
        }
        return 0;
    }

    /** The bytes ZMODEM sends as two: ZDLE, and DLE, XON, XOFF with their high-bit twins. */
    static long escaped(byte[] data) {
        long n = 0;
        for (byte b : data) {
            if (b == 0x18 || (b & 0x7f) == 0x10 || (b & 0x7f) == 0x11 || (b & 0x7f) == 0x13) {
                n++;
            }
        }
        return n;
    }

    private Row ours(int baud, Path file) throws Exception {
        Path out = Files.createDirectories(dir.resolve("ours"));
        try (ServerSocket receiverSide = new ServerSocket(0);
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, Socat.local(receiverSide.getLocalPort()))) {
            double load = load();
            long cpu = cpuNanos();
            Future<Long> receiving = pool.submit((Callable<Long>) () -> {
                long c = cpuNanos();
                try (Socket s = receiverSide.accept(); TcpLink link = new TcpLink(s)) {
                    new ZmodemReceiver(link, 10_000, null).receive(new ResumeStore(dir.resolve("parts-ours")), out);
                }
                return cpuNanos() - c;
            });
            long start = System.nanoTime();
            try (TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                new ZmodemSender(link, SENDER_TIMEOUT_MILLIS, null).window(0).send(SendFile.of(file));
            }
            long receiverCpu = receiving.get(1, TimeUnit.HOURS);
            return new Row("RIPV → RIPV", baud, Files.size(file), (System.nanoTime() - start) / 1e9,
                    (cpuNanos() - cpu + receiverCpu) / 1e9, load, Socat.sameBytes(file, out.resolve(file.getFileName())));
        }
    }

    private Row szToOurs(int baud, Path file) throws Exception {
        Path out = Files.createDirectories(dir.resolve("sz"));
        try (Socat.Served socat = Socat.serve(file.getParent(), SZ + file.getFileName());
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, socat.address())) {
            double load = load();
            long cpu = cpuNanos();
            long start = System.nanoTime();
            try (TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                new ZmodemReceiver(link, 10_000, null).receive(new ResumeStore(dir.resolve("parts-sz")), out);
            }
            double seconds = (System.nanoTime() - start) / 1e9;
            socat.process().waitFor(30, TimeUnit.SECONDS);
            return new Row("lrzsz sz → RIPV", baud, Files.size(file), seconds, (cpuNanos() - cpu) / 1e9, load,
                    Socat.sameBytes(file, out.resolve(file.getFileName())));
        }
    }

    private Row oursToRz(int baud, Path file) throws Exception {
        return oursToRz(baud, file, 0, "RIPV → lrzsz rz");
    }

    private Row oursToRz(int baud, Path file, int window, String pair) throws Exception {
        Path out = Files.createDirectories(dir.resolve("rz"));
        try (Socat.Served socat = Socat.serve(out, "rz -q -y");
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, socat.address())) {
            double load = load();
            long start = System.nanoTime();
            Future<Long> sending = pool.submit((Callable<Long>) () -> {
                long c = cpuNanos();
                try (TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                    new ZmodemSender(link, SENDER_TIMEOUT_MILLIS, null).window(window).send(SendFile.of(file));
                }
                return cpuNanos() - c;
            });
            // timed as lrzsz's pair is: until rz, having the file and the "OO", ends. The sender's
            // own last moments (it listens a while after "OO" for an rz that missed it) are not the line's.
            socat.process().waitFor(1, TimeUnit.HOURS);
            double seconds = (System.nanoTime() - start) / 1e9;
            long senderCpu = sending.get(2, TimeUnit.MINUTES);
            return new Row(pair, baud, Files.size(file), seconds, senderCpu / 1e9, load,
                    Socat.sameBytes(file, out.resolve(file.getFileName())));
        }
    }

    private Row szToRz(int baud, Path file) throws Exception {
        Path out = Files.createDirectories(dir.resolve("szrz"));
        try (Socat.Served rz = Socat.serve(out, "rz -q -y");
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, rz.address())) {
            double load = load();
            long start = System.nanoTime();
            Process sz = Socat.call(file.getParent(), relay.port(), SZ + file.getFileName());
            rz.process().waitFor(1, TimeUnit.HOURS);
            double seconds = (System.nanoTime() - start) / 1e9;
            sz.waitFor(30, TimeUnit.SECONDS);
            return new Row("lrzsz sz → lrzsz rz", baud, Files.size(file), seconds, 0, load,
                    Socat.sameBytes(file, out.resolve(file.getFileName())));
        }
    }

    /**
     * RIPV against lrzsz over the same pairs of rows (RIPV's first in each pair), as medians: "no
     * slower than lrzsz" is judged on these, not on one row, since one transfer's time varies by a
     * tenth of a second with what the machine did just before.
     */
    static String versus(String ours, String theirs, List<Row> pairs) {
        double[] a = new double[pairs.size() / 2];
        double[] b = new double[pairs.size() / 2];
        for (int i = 0; i + 1 < pairs.size(); i += 2) {
            a[i / 2] = pairs.get(i).seconds();
            b[i / 2] = pairs.get(i + 1).seconds();
        }
        double ma = median(a);
        double mb = median(b);
        return String.format(Locale.ROOT, "%s against %s on the same link, median of %d: %.2f s against %.2f s (%s %.2f %%)", ours,
                theirs, a.length, ma, mb, ma <= mb ? "faster by" : "SLOWER by", 100 * Math.abs(ma - mb) / mb);
    }

    static final List<String> USAGE = List.of(
            "  zmodem     ZMODEM over the paced relay against lrzsz sz/rz (share of the line rate, CPU, load), and",
            "             over an Iridium-like link the calls to move 100 KB resuming against YMODEM from zero",
            "             [--baud N] [--bytes N] [--iridium-baud N] [--latency MS] [--drop-every S] [--iridium-bytes N]",
            "             [--max-calls N] [--ymodem-calls N] [--skip-iridium] [--file PATH (the bytes sent; default random)]",
            "             [--rounds N (the four pairs N times; RIPV against lrzsz judged on the medians)]");
}
