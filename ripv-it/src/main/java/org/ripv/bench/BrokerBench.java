package org.ripv.bench;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.rmi.Remote;
import java.rmi.RemoteException;
import java.rmi.server.UnicastRemoteObject;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import javax.net.SocketFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.SSLSocket;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.Tls;
import org.ripv.examples.ClockService;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.RIPVServer;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.security.SelfSignedTls;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The broker benchmark (docs/performance.md): in one run and one JVM, the floors — a bare loopback
 * socket round trip, the same over TLS with the server's own certificate and the client's own
 * socket factory (so the same cipher suite), and a bare RMI call — and the full client → server →
 * service → server → client echo, as latency percentiles and as throughput with 1, 8 and 32
 * concurrent clients. Every figure comes with the CPU time per round trip of the whole process
 * ({@link CpuClock}): wall ratios swing with a shared machine's load, CPU ratios hardly do.
 */
@Command(name = "broker", mixinStandardHelpOptions = true, description = "Measures the broker's round trip against its floor.")
public final class BrokerBench implements Callable<Integer> {
    @Option(names = "--seconds", defaultValue = "3", description = "Measuring time per figure (default ${DEFAULT-VALUE}).")
    double seconds;
    @Option(names = "--warmup", defaultValue = "2", description = "Warm-up time per figure (default ${DEFAULT-VALUE}).")
    double warmup;
    @Option(names = "--clients", split = ",", defaultValue = "1,8,32", description = "Concurrent clients (default ${DEFAULT-VALUE}).")
    int[] clients;

    private final PrintStream out;

    public BrokerBench() {
        this(System.out);
    }

    BrokerBench(PrintStream out) {
        this.out = out;
    }

    /** A bare remote object for the RMI floor. */
    public interface Echo extends Remote {
        String echo(String s) throws RemoteException;
    }

    /** Wall percentiles and the whole process's CPU per operation, over the same operations. */
    record Latency(double p50Micros, double p99Micros, long count, double cpuMicros, Map<String, Double> byThread,
                   double allocatedBytes) {}

    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("ripv-bench");
        String payload = "echo " + "x".repeat(64);
        out.printf("RIPV broker benchmark — %d cores, Java %s, %s s per figure after %s s warm-up%n",
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"), seconds, warmup);

        out.println(CpuClock.machineLine());
        Latency socket = socketFloor(payload, null);
        Latency rmi = rmiFloor(payload);
        out.printf("floor: loopback socket round trip  p50 %8.1f us   p99 %8.1f us   cpu %6.1f us/op%n",
                socket.p50Micros(), socket.p99Micros(), socket.cpuMicros());
        out.printf("floor: bare RMI call               p50 %8.1f us   p99 %8.1f us   cpu %6.1f us/op%n",
                rmi.p50Micros(), rmi.p99Micros(), rmi.cpuMicros());
        double floor = socket.p50Micros() + 2 * rmi.p50Micros();
        double floorCpu = socket.cpuMicros() + 2 * rmi.cpuMicros();
        out.printf("floor: socket + 2 RMI calls (plain)               p50 %8.1f us   cpu %6.1f us/op%n", floor, floorCpu);

        RIPVServer server = new RIPVServer(ServerConfig.forTests(dir.resolve("server"))
                .withRequestTimeout(Duration.ofSeconds(30)).withServiceCheck(Duration.ofSeconds(5)));
        server.start();
        PermitFile.setUser(dir.resolve("server/permit.txt"), "bench", "bench-password".toCharArray(), List.of("operators"), 1000);
        server.reloadPermits();
        ClockService clock = new ClockService("localhost");
        String secret = Files.readString(server.secretFile(), StandardCharsets.UTF_8).trim();
        ServiceConnector connector = ServiceConnector.connect(clock,
                new ServiceOptions("localhost", server.registryPort(), secret, 0, Duration.ofSeconds(5)));
        connector.awaitRegistered(Duration.ofSeconds(30));
        String mailbox = "<ClockService>::<localhost>TTY1";
        try {
            // The TLS floor: the server's own certificate, the client's own trust-on-first-use socket factory.
            SSLContext serverTls = SelfSignedTls.loadOrCreate(dir.resolve("server/tls")).context();
            Latency tls = socketFloor(payload, serverTls);
            double tlsFloor = tls.p50Micros() + 2 * rmi.p50Micros();
            double tlsFloorCpu = tls.cpuMicros() + 2 * rmi.cpuMicros();
            out.printf("floor: TLS socket round trip (%s)  p50 %8.1f us   p99 %8.1f us   cpu %6.1f us/op%n",
                    tlsSuite, tls.p50Micros(), tls.p99Micros(), tls.cpuMicros());
            out.printf("floor: TLS socket + 2 RMI calls (the path's hops)  p50 %8.1f us   cpu %6.1f us/op%n", tlsFloor, tlsFloorCpu);

            List<ClientSocketHandler> pool = new ArrayList<>();
            int max = Arrays.stream(clients).max().orElse(1);
            for (int i = 0; i < max; i++) {
                ClientSocketHandler c = ClientSocketHandler.connect("localhost", server.port());
                c.login("bench", "bench-password".toCharArray());
                pool.add(c);
            }
            Latency full = measure(() -> {
                if (pool.get(0).call(mailbox, payload, Priority.NORMAL, Duration.ofSeconds(30), null).status() != Status.OK) {
                    throw new IllegalStateException("echo failed");
                }
            });
            out.printf("full:  client→server→service→client  p50 %8.1f us   p99 %8.1f us   cpu %6.1f us/op%n",
                    full.p50Micros(), full.p99Micros(), full.cpuMicros());
            out.printf("  against the TLS floor: wall p50 %.2f× (target ≤ 2×), CPU %.2f× (target ≤ 2×);"
                    + " against the plain floor: wall %.2f×, CPU %.2f×%n",
                    full.p50Micros() / tlsFloor, full.cpuMicros() / tlsFloorCpu, full.p50Micros() / floor, full.cpuMicros() / floorCpu);
            out.println(CpuClock.ratioLine("full path", full.cpuMicros(), tlsFloorCpu, full.p50Micros() / tlsFloor));
            out.printf("allocated per round trip (all Java threads): full path %.1f KB; floors: TLS socket %.1f KB, RMI call %.1f KB%n",
                    full.allocatedBytes() / 1e3, tls.allocatedBytes() / 1e3, rmi.allocatedBytes() / 1e3);
            out.print("  the full path's CPU per round trip by thread:");
            full.byThread().entrySet().stream().filter(e -> e.getValue() >= 0.5)
                    .forEach(e -> out.printf(" %s %.1f us;", e.getKey(), e.getValue()));
            out.println();
            for (int n : clients) {
                long[] done = new long[2];
                double rate = throughput(pool.subList(0, n), mailbox, payload, done);
                out.printf("throughput with %2d client(s): %9.0f round trips/s   cpu %6.1f us per round trip%s%n", n, rate,
                        done[1] / 1e3 / Math.max(1, done[0]), n == 32 ? "   (target ≥ 25,000/s on 2 cores)" : "");
            }
            out.println(CpuClock.machineLine());
            pool.forEach(ClientSocketHandler::close);
        } finally {
            connector.close();
            clock.stop();
            server.stop();
        }
        return 0;
    }

    /** The cipher suite the TLS floor negotiated, for the report. */
    private String tlsSuite = "none";

    /** A length-prefixed echo over loopback; over TLS when {@code tls} is given (the client side as ClientSocketHandler makes it). */
    private Latency socketFloor(String payload, SSLContext tls) throws Exception {
        try (ServerSocket ss = tls == null ? new ServerSocket(0) : tls.getServerSocketFactory().createServerSocket(0)) {
            Thread echo = new Thread(() -> {
                try (Socket s = ss.accept()) {
                    s.setTcpNoDelay(true);
                    DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
                    DataOutputStream o = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                    byte[] buf = new byte[1 << 16];
                    while (true) {
                        int n = in.readInt();
                        in.readFully(buf, 0, n);
                        o.writeInt(n);
                        o.write(buf, 0, n);
                        o.flush();
                    }
                } catch (IOException e) {
                    // the benchmark closed the connection
                }
            }, "bench-socket-echo");
            echo.setDaemon(true);
            echo.start();
            SocketFactory factory = tls == null ? SocketFactory.getDefault()
                    : Tls.trustOnFirstUse("localhost", ss.getLocalPort(), Tls.defaultKnownHosts(), notice -> { });
            try (Socket s = factory.createSocket("localhost", ss.getLocalPort())) {
                s.setTcpNoDelay(true);
                if (s instanceof SSLSocket ssl) {
                    ssl.startHandshake();
                    tlsSuite = ssl.getSession().getProtocol() + " " + ssl.getSession().getCipherSuite();
                }
                DataInputStream in = new DataInputStream(new BufferedInputStream(s.getInputStream()));
                DataOutputStream o = new DataOutputStream(new BufferedOutputStream(s.getOutputStream()));
                byte[] body = payload.getBytes(StandardCharsets.UTF_8);
                byte[] back = new byte[body.length];
                return measure(() -> {
                    o.writeInt(body.length);
                    o.write(body);
                    o.flush();
                    in.readInt();
                    in.readFully(back);
                });
            }
        }
    }

    private Latency rmiFloor(String payload) throws Exception {
        Echo impl = s -> s;
        Echo stub = (Echo) UnicastRemoteObject.exportObject(impl, 0);
        try {
            return measure(() -> stub.echo(payload));
        } finally {
            UnicastRemoteObject.unexportObject(impl, true);
        }
    }

    interface Op {
        void run() throws Exception;
    }

    private Latency measure(Op op) throws Exception {
        long warmEnd = System.nanoTime() + (long) (warmup * 1e9);
        while (System.nanoTime() < warmEnd) {
            op.run();
        }
        long[] samples = new long[1 << 20];
        int n = 0;
        CpuClock cpu = CpuClock.start();
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < end && n < samples.length) {
            long t0 = System.nanoTime();
            op.run();
            samples[n++] = System.nanoTime() - t0;
        }
        double cpuMicros = cpu.cpuMicrosPer(n);
        Map<String, Double> byThread = cpu.microsPerThreadKind(n);
        double allocated = cpu.bytesAllocatedPer(n);
        Arrays.sort(samples, 0, n);
        return new Latency(samples[n / 2] / 1000.0, samples[(int) (n * 0.99)] / 1000.0, n, cpuMicros, byThread, allocated);
    }

    /** Round trips a second of {@code cs} calling at once; {@code counted} gets how many were counted and the CPU nanoseconds they took. */
    private double throughput(List<ClientSocketHandler> cs, String mailbox, String payload, long[] counted) throws Exception {
        AtomicBoolean counting = new AtomicBoolean(false);
        AtomicBoolean stop = new AtomicBoolean(false);
        AtomicLong done = new AtomicLong();
        CountDownLatch finished = new CountDownLatch(cs.size());
        List<Throwable> failures = new CopyOnWriteArrayList<>();
        for (ClientSocketHandler c : cs) {
            Thread t = new Thread(() -> {
                try {
                    while (!stop.get()) {
                        if (c.call(mailbox, payload, Priority.NORMAL, Duration.ofSeconds(30), null).status() != Status.OK) {
                            throw new IllegalStateException("echo failed");
                        }
                        if (counting.get()) {
                            done.incrementAndGet();
                        }
                    }
                } catch (Throwable e) {
                    failures.add(e);
                } finally {
                    finished.countDown();
                }
            }, "bench-client");
            t.setDaemon(true);
            t.start();
        }
        Thread.sleep((long) (warmup * 1000));
        CpuClock cpu = CpuClock.start();
        counting.set(true);
        long t0 = System.nanoTime();
        Thread.sleep((long) (seconds * 1000));
        counting.set(false);
        counted[1] = cpu.cpuNanos();
        long elapsed = System.nanoTime() - t0;
        stop.set(true);
        finished.await();
        if (!failures.isEmpty()) {
            throw new IllegalStateException("a benchmark client failed", failures.get(0));
        }
        counted[0] = done.get();
        return done.get() / (elapsed / 1e9);
    }
}
