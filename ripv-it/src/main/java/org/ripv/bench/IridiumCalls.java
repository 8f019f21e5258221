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
        String name = file.getFileName().toString();
        Calls c = call(file, maxCalls, ZmodemBench.SZ + name, new Receiver() {
            long before;

            @Override
            public void begin() throws IOException {
                before = Math.max(0, store.partLength(name));
            }

            @Override
            public void receive(TcpLink link) throws IOException {
                new ZmodemReceiver(link, 10_000, null).startTimeout(30_000).receive(store, out);
            }

            @Override
            public long moved(boolean whole) throws IOException {
                return (whole ? Files.size(file) : Math.max(0, store.partLength(name))) - before;
            }
        }, out);
        return String.format(Locale.ROOT, "| ZMODEM, resuming | %d | %s | %s | %.0f | %.2f | %.2f |", c.calls(),
                c.done() ? "yes" : "no", c.perCall(), c.seconds(), c.cpuSeconds(), c.load());
    }

    /** YMODEM over the same calls: a cut file starts again from zero on the next. */
    String ymodem(Path file, int maxCalls) throws Exception {
        Path out = Files.createDirectories(dir.resolve("iridium-y"));
        YmodemConfig config = YmodemConfig.lrzsz();
        AtomicLong moved = new AtomicLong();
        Calls c = call(file, maxCalls, "sb --ymodem -k -q " + file.getFileName(), new Receiver() {
            @Override
            public void begin() {
                moved.set(0);
            }

            @Override
            public void receive(TcpLink link) throws IOException {
                new YmodemReceiver(link, config, new TransferListener() {
                    @Override
                    public void progress(FileHeader f, long d) {
                        moved.set(d);
                    }
                }).receiveBatch(new DirectorySink(out));
            }

            @Override
            public long moved(boolean whole) throws IOException {
                return whole ? Files.size(file) : moved.get(); // dropped: YMODEM has nothing to resume from
            }
        }, out);
        return String.format(Locale.ROOT, "| YMODEM, from zero each call | %d%s | %s | %s (kept: 0) | %.0f | %.2f | %.2f |",
                c.calls(), c.done() ? "" : " (stopped)", c.done() ? "yes" : "no", c.perCall(), c.seconds(),
                c.cpuSeconds(), c.load());
    }

    /** Our side of one call: receives what the sender sends until the file is whole or the call drops. */
    private interface Receiver {
        /** Before each call is dialled. */
        void begin() throws IOException;

        void receive(TcpLink link) throws IOException;

        /** Bytes this call added to what we hold of the file. */
        long moved(boolean whole) throws IOException;
    }

    /** How the calls went: how many, whether the file arrived, the bytes of each call, and their cost. */
    private record Calls(int calls, boolean done, String perCall, double seconds, double cpuSeconds, double load) {}

    /** Calls until the file is whole or {@code maxCalls} are made, each a fresh {@code sender} behind the relay. */
    private Calls call(Path file, int maxCalls, String sender, Receiver receiver, Path out) throws Exception {
        StringBuilder perCall = new StringBuilder();
        double load = ZmodemBench.load();
        long cpu = ZmodemBench.cpuNanos();
        long start = System.nanoTime();
        int calls = 0;
        boolean done = false;
        while (!done && calls < maxCalls) {
            calls++;
            receiver.begin();
            int port = Socat.freePort();
            Process p = Socat.listen(file.getParent(), port, sender);
            try (IridiumRelay relay = new IridiumRelay(baud, latency, dropEvery * 1000, Socat.local(port));
                 TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                receiver.receive(link);
                done = Socat.sameBytes(file, out.resolve(file.getFileName()));
            } catch (IOException e) {
                // the call dropped: the next one goes on (ZMODEM) or starts again (YMODEM)
            } finally {
                p.destroy();
                p.waitFor(10, TimeUnit.SECONDS);
            }
            perCall.append(perCall.isEmpty() ? "" : ", ").append(receiver.moved(done));
        }
        return new Calls(calls, done, perCall.toString(), (System.nanoTime() - start) / 1e9,
                (ZmodemBench.cpuNanos() - cpu) / 1e9, load);
    }
}
