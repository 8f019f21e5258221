package org.ripv.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
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
    /** Calls until the file is whole: each call a fresh sz, our receiver continuing from the part. */
    String zmodem(Path file, int maxCalls) throws Exception {
        Path out = Files.createDirectories(dir.resolve("iridium-z"));
        ResumeStore store = new ResumeStore(dir.resolve("parts-iridium"));
        StringBuilder perCall = new StringBuilder();
        double load = ZmodemBench.load();
        long cpu = ZmodemBench.cpuNanos();
        long start = System.nanoTime();
        int calls = 0;
        boolean done = false;
        while (!done && calls < maxCalls) {
            calls++;
            long before = Math.max(0, store.partLength(file.getFileName().toString()));
            int port = Socat.freePort();
            Process sz = Socat.listen(file.getParent(), port, ZmodemBench.SZ + file.getFileName());
            try (IridiumRelay relay = new IridiumRelay(baud, latency, dropEvery * 1000, Socat.local(port));
                 TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                new ZmodemReceiver(link, 10_000, null).startTimeout(30_000).receive(store, out);
                done = Socat.sameBytes(file, out.resolve(file.getFileName()));
            } catch (IOException e) {
                // the call dropped: the part waits for the next one
            } finally {
                sz.destroy();
                sz.waitFor(10, TimeUnit.SECONDS);
            }
            long after = done ? Files.size(file) : Math.max(0, store.partLength(file.getFileName().toString()));
            perCall.append(perCall.isEmpty() ? "" : ", ").append(after - before);
        }
        return String.format(Locale.ROOT, "| ZMODEM, resuming | %d | %s | %s | %.0f | %.2f | %.2f |", calls,
                done ? "yes" : "no", perCall, (System.nanoTime() - start) / 1e9, (ZmodemBench.cpuNanos() - cpu) / 1e9, load);
    }

    /** YMODEM over the same calls: a cut file starts again from zero on the next. */
    String ymodem(Path file, int maxCalls) throws Exception {
        Path out = Files.createDirectories(dir.resolve("iridium-y"));
        StringBuilder perCall = new StringBuilder();
        double load = ZmodemBench.load();
        long cpu = ZmodemBench.cpuNanos();
        long start = System.nanoTime();
        int calls = 0;
        boolean done = false;
        YmodemConfig config = YmodemConfig.lrzsz();
        while (!done && calls < maxCalls) {
            calls++;
            AtomicLong moved = new AtomicLong();
            int port = Socat.freePort();
            Process sb = Socat.listen(file.getParent(), port, "sb --ymodem -k -q " + file.getFileName());
            try (IridiumRelay relay = new IridiumRelay(baud, latency, dropEvery * 1000, Socat.local(port));
                 TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                new YmodemReceiver(link, config, new TransferListener() {
                    @Override
                    public void progress(FileHeader f, long d) {
                        moved.set(d);
                    }
                }).receiveBatch(new DirectorySink(out));
                done = Socat.sameBytes(file, out.resolve(file.getFileName()));
            } catch (IOException e) {
                // dropped: YMODEM has nothing to resume from
            } finally {
                sb.destroy();
                sb.waitFor(10, TimeUnit.SECONDS);
            }
            perCall.append(perCall.isEmpty() ? "" : ", ").append(done ? Files.size(file) : moved.get());
        }
        return String.format(Locale.ROOT, "| YMODEM, from zero each call | %d%s | %s | %s (kept: 0) | %.0f | %.2f | %.2f |",
                calls, done ? "" : " (stopped)", done ? "yes" : "no", perCall, (System.nanoTime() - start) / 1e9,
                (ZmodemBench.cpuNanos() - cpu) / 1e9, load);
    }
}
