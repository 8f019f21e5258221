package org.ripv.bench;

import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.ReplySink;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ./ripv bench calls}: N vehicles call N {@code listen://} links of one SerialPortServer,
 * their calls starting spread over a time, each printing a surface dialog with a GPS fix and then
 * time-stamped lines for the length of its call, then hanging up. Measured where the service
 * hands its console entries on (its {@code ReplySink}, in place of the server): calls accepted
 * (SURFACED with the position, then DIVED), lines seen and in order, and the delay from the
 * vehicle's write to the entry's delivery, against one vehicle alone in the same run.
 */
@Command(name = "calls", mixinStandardHelpOptions = true,
        description = "N vehicles calling N listen:// links: every call accepted and streamed, and the delay.")
public final class CallsBench implements Callable<Integer> {
    @Option(names = "--vehicles", defaultValue = "100", description = "Vehicles and links (default ${DEFAULT-VALUE}).")
    int vehicles;

    @Option(names = "--spread", defaultValue = "60", paramLabel = "SECONDS",
            description = "The calls start within this time (default ${DEFAULT-VALUE} s).")
    int spread;

    @Option(names = "--surface", defaultValue = "30", paramLabel = "SECONDS",
            description = "How long each call lasts (default ${DEFAULT-VALUE} s).")
    int surface;

    @Option(names = "--lines-per-second", defaultValue = "10", description = "Lines each vehicle prints a second (default ${DEFAULT-VALUE}).")
    int rate;

    /** What one run saw. */
    public record Result(int vehicles, int surfaced, int surfacedWithPosition, int dived, long linesSent, long linesSeen,
                         long skipped, int outOfOrder, double p50Millis, double p99Millis, double maxMillis) {
        public boolean allAccepted() {
            return surfaced == vehicles && surfacedWithPosition == vehicles && dived == vehicles;
        }

        @Override
        public String toString() {
            return String.format(Locale.ROOT, "%d vehicles: %d SURFACED (%d with position), %d DIVED; lines %d sent,"
                    + " %d seen, %d skipped, %d out of order; delay p50 %.1f ms, p99 %.1f ms, max %.1f ms",
                    vehicles, surfaced, surfacedWithPosition, dived, linesSent, linesSeen, skipped, outOfOrder,
                    p50Millis, p99Millis, maxMillis);
        }
    }

    /**
     * Where the links listen and the vehicles call. Not 127.0.0.1: the links take ports the kernel
     * picks, and in a JVM or on a machine that ran other tests a stray client still redialling
     * some 127.0.0.1 port of an earlier test (an outbound link reconnecting every 300 ms) can land on
     * one, hold it for a second and leave the vehicle that calls then refused (CI saw "v074: call
     * failed: Broken pipe" and a SURFACED with no position). Loopback answers on all of 127/8.
     */
    static final String ADDRESS = "127.0.0.2";

    /** Collects what the service publishes. */
    private static final class Sink implements ReplySink {
        final Map<String, AtomicLong> lastSeq = new ConcurrentHashMap<>();
        final Map<String, List<ConsoleEntry>> events = new ConcurrentHashMap<>();
        final AtomicLong seen = new AtomicLong();
        final AtomicLong skipped = new AtomicLong();
        final AtomicLong outOfOrder = new AtomicLong();
        final long[] delays = new long[4_000_000];
        final AtomicLong delayCount = new AtomicLong();

        @Override
        public void reply(OutgoingServiceMessage reply) {
        }

        @Override
        public void console(List<ConsoleEntry> entries) {
            long now = System.nanoTime();
            for (ConsoleEntry e : entries) {
                if (e.kind() == ConsoleEntry.Kind.EVENT) {
                    events.computeIfAbsent(e.mailbox(), m -> new CopyOnWriteArrayList<>()).add(e);
                } else if (e.text().startsWith("t=")) {
                    String[] f = e.text().split(" ");
                    long sent = Long.parseLong(f[0].substring(2));
                    long seq = Long.parseLong(f[1].substring(2));
                    long i = delayCount.getAndIncrement();
                    if (i < delays.length) {
                        delays[(int) i] = now - sent;
                    }
                    seen.incrementAndGet();
                    AtomicLong last = lastSeq.computeIfAbsent(e.mailbox(), m -> new AtomicLong(-1));
                    if (seq <= last.getAndSet(seq)) {
                        outOfOrder.incrementAndGet();
                    }
                } else if (e.text().contains("lines skipped")) {
                    skipped.addAndGet(Long.parseLong(e.text().substring(1, e.text().indexOf(' '))));
                }
            }
        }
    }

    /** Runs one round: {@code n} vehicles, calls starting within {@code spread}, each {@code surface} long. */
    public static Result run(int n, Duration spread, Duration surface, int linesPerSecond, Path work) throws Exception {
        List<VehicleLink> links = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            links.add(new VehicleLink(LinkSettings.defaults("listen://" + ADDRESS + ":0"),
                    CallSettings.defaults().withName(String.format(Locale.ROOT, "v%03d", i))));
        }
        SerialPortServer serial = SerialPortServer.withCalls("bench", links, null, false, work);
        Sink sink = new Sink();
        serial.replyTo(sink);
        serial.start();
        AtomicLong sent = new AtomicLong();
        List<Thread> callers = new ArrayList<>();
        long t0 = System.nanoTime();
        try {
            for (int i = 0; i < n; i++) {
                String name = String.format(Locale.ROOT, "v%03d", i);
                int port = serial.listenPort(name);
                long startAt = t0 + spread.toNanos() * i / Math.max(1, n);
                Thread t = new Thread(() -> vehicle(name, port, startAt, surface, linesPerSecond, sent), "vehicle-" + name);
                t.setDaemon(true);
                t.start();
                callers.add(t);
            }
            for (Thread t : callers) {
                t.join();
            }
            // the last DIVED and lines travel on the publisher's thread
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
            while (System.nanoTime() < deadline && (sink.seen.get() + sink.skipped.get() < sent.get()
                    || count(sink, VehicleEvent.DIVED, false) < n)) {
                LockSupport.parkNanos(TimeUnit.MILLISECONDS.toNanos(50)); // nothing announces "all delivered"
            }
        } finally {
            serial.stop();
        }
        int m = (int) Math.min(sink.delayCount.get(), sink.delays.length);
        long[] d = Arrays.copyOf(sink.delays, m);
        Arrays.sort(d);
        return new Result(n, count(sink, VehicleEvent.SURFACED, false), count(sink, VehicleEvent.SURFACED, true),
                count(sink, VehicleEvent.DIVED, false), sent.get(), sink.seen.get(), sink.skipped.get(),
                (int) sink.outOfOrder.get(), percentile(d, 0.50), percentile(d, 0.99), m == 0 ? 0 : d[m - 1] / 1e6);
    }

    private static int count(Sink sink, VehicleEvent event, boolean withPosition) {
        int c = 0;
        for (List<ConsoleEntry> l : sink.events.values()) {
            c += l.stream().anyMatch(e -> e.event() == event && (!withPosition || e.lat() != null)) ? 1 : 0;
        }
        return c;
    }

    private static double percentile(long[] sorted, double p) {
        return sorted.length == 0 ? 0 : sorted[(int) Math.min(sorted.length - 1, Math.floor(p * sorted.length))] / 1e6;
    }

    private static void vehicle(String name, int port, long startAt, Duration surface, int linesPerSecond, AtomicLong sent) {
        LockSupport.parkNanos(Math.max(0, startAt - System.nanoTime())); // the bench paces the calls
        try (Socket s = new Socket(ADDRESS, port)) {
            s.setTcpNoDelay(true);
            OutputStream out = s.getOutputStream();
            out.write(("\r\nGlider " + name + " at surface.\r\nVehicle Name: " + name
                    + "\r\nGPS Location:  4137.994 N -7032.188 E measured 26.0 secs ago"
                    // the dialog's end, as a glider's: a caller that hangs up inside its dialog dropped the call (LINK_LOST)
                    + "\r\nHit Control-C within 30 seconds to abort the mission\r\n").getBytes(StandardCharsets.US_ASCII));
            long end = System.nanoTime() + surface.toNanos();
            long period = 1_000_000_000L / linesPerSecond;
            long next = System.nanoTime();
            for (long seq = 0; System.nanoTime() < end; seq++) {
                out.write(("t=" + System.nanoTime() + " n=" + seq + "\r\n").getBytes(StandardCharsets.US_ASCII));
                out.flush();
                sent.incrementAndGet();
                next += period;
                LockSupport.parkNanos(Math.max(0, next - System.nanoTime())); // the vehicle's pace
            }
        } catch (Exception e) {
            System.err.println(name + ": call failed: " + e);
        }
    }

    @Override
    public Integer call() throws Exception {
        Path work = Files.createTempDirectory("ripv-bench-calls");
        Duration s = Duration.ofSeconds(surface);
        System.out.println("baseline: one vehicle alone, " + surface + " s, " + rate + " lines/s");
        Result one = run(1, Duration.ZERO, s, rate, work.resolve("one"));
        System.out.println("  " + one);
        System.out.println(vehicles + " vehicles, calls starting within " + spread + " s, each " + surface + " s, "
                + rate + " lines/s");
        Result many = run(vehicles, Duration.ofSeconds(spread), s, rate, work.resolve("many"));
        System.out.println("  " + many);
        System.out.printf(Locale.ROOT, "every call accepted and streamed: %s; p99 delay %.1f ms = %.2f x one vehicle's%n",
                many.allAccepted() && many.linesSeen() == many.linesSent() && many.outOfOrder() == 0 ? "yes" : "NO",
                many.p99Millis(), many.p99Millis() / Math.max(0.001, one.p99Millis()));
        return many.allAccepted() ? 0 : 1;
    }
}
