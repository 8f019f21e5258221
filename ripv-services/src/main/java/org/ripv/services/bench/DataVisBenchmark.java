package org.ripv.services.bench;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.ripv.messages.Attachment;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.ImageResult;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.naming.Handles;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.datavis.WorkerMode;

/**
 * Benchmark (not a test): {@code vis:} request to JPEG reply through a DataVisServer, for 10,000
 * and 1,000,000 points, with the built-in worker and, when {@code octave-cli} is on the PATH,
 * with Octave running ripvOut.m. The request enters the service the way the server's RMI call
 * does ({@code accept}) and the clock stops at the final reply; each size runs a few times and
 * the median is reported (the first built-in run includes JIT warm-up and is reported apart).
 *
 * <pre>java -cp ripv-services/target/ripv-services.jar org.ripv.services.bench.DataVisBenchmark [--no-octave] [--keep DIR]
 *     [--points 10000,1000000] [--runs N]</pre>
 */
public final class DataVisBenchmark {
    private DataVisBenchmark() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark, its exit status returned rather than exited with ({@code BenchMain} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        System.setProperty("java.awt.headless", "true");
        Locale.setDefault(Locale.ROOT);
        boolean octave = !List.of(args).contains("--no-octave") && onPath("octave-cli");
        Path keep = null;
        for (int i = 0; i < args.length - 1; i++) {
            if (args[i].equals("--keep")) {
                keep = Path.of(args[i + 1]);
                Files.createDirectories(keep);
            }
        }
        int[] sizes = {10_000, 1_000_000};
        int fixedRuns = 0; // 0: 7 runs of the small sizes and 3 of a million points
        for (int i = 0; i < args.length - 1; i++) {
            if (args[i].equals("--points")) {
                sizes = Arrays.stream(args[i + 1].split(",")).mapToInt(Integer::parseInt).toArray();
            } else if (args[i].equals("--runs")) {
                fixedRuns = Integer.parseInt(args[i + 1]);
            }
        }
        System.out.printf("DataVisServer benchmark: vis: request -> JPEG reply (in-process, %d cores, max heap %d MB)%n",
                Runtime.getRuntime().availableProcessors(), Runtime.getRuntime().maxMemory() >> 20);
        System.out.printf("%-8s %10s %9s %10s %10s %10s %9s%n", "worker", "points", "file MB", "first ms", "median ms",
                "runs", "JPEG KB");
        List<WorkerMode> modes = new ArrayList<>(List.of(WorkerMode.BUILTIN));
        if (octave) {
            modes.add(WorkerMode.OCTAVE);
        } else {
            System.out.println("(octave-cli not on the PATH or --no-octave: Octave rows skipped)");
        }
        for (WorkerMode mode : modes) {
            Path dir = Files.createTempDirectory("ripv-vis-bench");
            DataVisServer vis = new DataVisServer("bench", DataVisServer.Config.of(dir).withWorker(mode)
                    .withTimeout(Duration.ofMinutes(10)));
            BlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
            vis.replyTo(replies::add);
            vis.start();
            try {
                for (int n : sizes) {
                    byte[] data = dataFile(n);
                    int runs = fixedRuns > 0 ? Math.max(2, fixedRuns) : n >= 1_000_000 ? 3 : 7;
                    long[] ms = new long[runs];
                    int jpegBytes = 0;
                    for (int r = 0; r < runs; r++) {
                        long t0 = System.nanoTime();
                        ImageResult img = plot(vis, replies, "bench" + n + ".dat", data);
                        ms[r] = (System.nanoTime() - t0) / 1_000_000;
                        jpegBytes = img.jpeg().length;
                        if (keep != null && r == 0) {
                            Files.write(keep.resolve(mode + "-" + n + ".jpg"), img.jpeg());
                        }
                    }
                    long first = ms[0];
                    long[] rest = Arrays.copyOfRange(ms, 1, runs);
                    Arrays.sort(rest);
                    System.out.printf("%-8s %,10d %9.1f %10d %10d %10d %9d%n", mode, n, data.length / 1e6, first,
                            rest[rest.length / 2], runs, jpegBytes / 1024);
                }
            } finally {
                vis.stop();
            }
        }
        return 0;
    }

    private static ImageResult plot(DataVisServer vis, BlockingQueue<OutgoingServiceMessage> replies, String name, byte[] data)
            throws InterruptedException {
        String mailbox = vis.name().mailbox(Handles.platformDefault()).toString();
        vis.accept(new IncomingServiceMessage(new Header(System.nanoTime(), new IdBadge("123456", "bench"), List.of(),
                vis.name().toString(), mailbox, "vis:" + name, Priority.NORMAL, new Attachment(name, data))));
        while (true) {
            OutgoingServiceMessage m = replies.poll(15, TimeUnit.MINUTES);
            if (m == null) {
                throw new IllegalStateException("no reply within 15 minutes");
            }
            if (m.footer().status() == Status.PROGRESS) {
                continue;
            }
            if (m.footer().status() != Status.OK) {
                throw new IllegalStateException("plot failed: " + m.footer().replyText());
            }
            return (ImageResult) m.footer().result();
        }
    }

    /** n rows: time, a noisy sine and a cosine, with a short NaN gap every 100,000 rows. */
    static byte[] dataFile(int n) {
        StringBuilder sb = new StringBuilder(n * 28);
        sb.append("% title: benchmark, ").append(n).append(" rows\n% xlabel: t (s)\n% ylabel: value\n% legend: sine | cosine\n");
        Random random = new Random(42);
        for (int i = 0; i < n; i++) {
            double t = i * 0.01;
            sb.append(String.format(Locale.ROOT, "%.2f", t)).append(' ');
            if (i % 100_000 >= 50_000 && i % 100_000 < 50_050) {
                sb.append("NaN NaN\n");
            } else {
                sb.append(String.format(Locale.ROOT, "%.4f %.4f%n", Math.sin(t / 50) + 0.05 * random.nextGaussian(),
                        Math.cos(t / 80)));
            }
        }
        return sb.toString().getBytes(StandardCharsets.US_ASCII);
    }

    private static boolean onPath(String program) {
        String path = System.getenv("PATH");
        return path != null && Arrays.stream(path.split(File.pathSeparator)).anyMatch(d -> Files.isExecutable(Path.of(d, program)));
    }
}
