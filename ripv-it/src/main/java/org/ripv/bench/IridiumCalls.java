package org.ripv.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.probe.FreePorts;
import org.ripv.services.bench.Socat;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.TransferListener;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.zmodem.ResumeStore;
import org.ripv.services.serial.zmodem.ZmodemReceiver;

/**
 * The ZMODEM bench's second half: over an Iridium-like link ({@link IridiumRelay}: a slow line,
 * latency, a drop every so often) the calls needed to move one file with ZMODEM, which resumes a
 * cut file on the next call, against YMODEM, which starts it again from zero. One markdown row each.
 *
 * @param latency   ms each byte takes each way
 * @param dropEvery s after which each call drops
 */
record IridiumCalls(Path dir, int baud, long latency, long dropEvery) {
    /** What one side does over one call; an IOException is the call dropping. */
    @FunctionalInterface
    private interface OverTheCall {
        void receive(TcpLink link) throws IOException;
    }

    /** The calls so far: how many, whether the file is whole, bytes each call moved, and the clocks from the first. */
    private static final class Tally {
        private final StringBuilder perCall = new StringBuilder();
        private final double load = ZmodemBench.load();
        private final long cpu = ZmodemBench.cpuNanos();
        private final long start = System.nanoTime();
        private int calls;
        private boolean done;

        boolean another(int maxCalls) {
            return !done && calls < maxCalls;
        }

        void called(boolean whole, long moved) {
            calls++;
            done = whole;
            perCall.append(perCall.isEmpty() ? "" : ", ").append(moved);
        }

        /** calls, done, bytes per call, wall s, CPU s and load: the columns both rows end with. */
        Object[] columns(String callsNote) {
            return new Object[] {calls + callsNote, done ? "yes" : "no", perCall, (System.nanoTime() - start) / 1e9,
                    (ZmodemBench.cpuNanos() - cpu) / 1e9, load};
        }
    }

    /** Calls until the file is whole: each call a fresh sz, our receiver continuing from the part. */
    String zmodem(Path file, int maxCalls) throws Exception {
        Path out = Files.createDirectories(dir.resolve("iridium-z"));
        ResumeStore store = new ResumeStore(dir.resolve("parts-iridium"));
        String name = file.getFileName().toString();
        Tally tally = new Tally();
        while (tally.another(maxCalls)) {
            long before = Math.max(0, store.partLength(name));
            // a dropped call leaves its part for the next one
            boolean done = call(file, ZmodemBench.SZ + name, out,
                    link -> new ZmodemReceiver(link, 10_000, null).startTimeout(30_000).receive(store, out));
            long after = done ? Files.size(file) : Math.max(0, store.partLength(name));
            tally.called(done, after - before);
        }
        return String.format(Locale.ROOT, "| ZMODEM, resuming | %s | %s | %s | %.0f | %.2f | %.2f |", tally.columns(""));
    }

    /** YMODEM over the same calls: a cut file starts again from zero on the next. */
    String ymodem(Path file, int maxCalls) throws Exception {
        Path out = Files.createDirectories(dir.resolve("iridium-y"));
        YmodemConfig config = YmodemConfig.lrzsz();
        Tally tally = new Tally();
        while (tally.another(maxCalls)) {
            AtomicLong moved = new AtomicLong(); // a dropped call leaves nothing to resume from
            boolean done = call(file, "sb --ymodem -k -q " + file.getFileName(), out,
                    link -> new YmodemReceiver(link, config, new TransferListener() {
                        @Override
                        public void progress(FileHeader f, long d) {
                            moved.set(d);
                        }
                    }).receiveBatch(new DirectorySink(out)));
            tally.called(done, done ? Files.size(file) : moved.get());
        }
        boolean stopped = !tally.done;
        return String.format(Locale.ROOT, "| YMODEM, from zero each call | %s | %s | %s (kept: 0) | %.0f | %.2f | %.2f |",
                tally.columns(stopped ? " (stopped)" : ""));
    }

    /**
     * One call: {@code sender} behind socat, the relay between, our receiver over it. True when the
     * file arrived whole; false when the call dropped first.
     */
    private boolean call(Path file, String sender, Path out, OverTheCall receiver) throws Exception {
        int port = FreePorts.one();
        Process p = Socat.listen(file.getParent(), port, sender);
        try (IridiumRelay relay = new IridiumRelay(baud, latency, dropEvery * 1000, Socat.local(port));
             TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
            receiver.receive(link);
            return Socat.sameBytes(file, out.resolve(file.getFileName()));
        } catch (IOException e) {
            return false;
        } finally {
            p.destroy();
            p.waitFor(10, TimeUnit.SECONDS);
        }
    }
}
