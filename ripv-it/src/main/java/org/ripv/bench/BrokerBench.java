package org.ripv.bench;

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
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.RIPVServer;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.PermitFile;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * The broker benchmark (docs/performance.md): in one run and one JVM, the floor — a bare loopback
 * socket round trip and a bare RMI call — and the full client → server → service → server →
 * client echo, as latency percentiles and as throughput with 1, 8 and 32 concurrent clients.
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

    record Latency(double p50Micros, double p99Micros, long count) {}

    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("ripv-bench");
        String payload = "echo " + "x".repeat(64);
        out.printf("RIPV broker benchmark — %d cores, Java %s, %s s per figure after %s s warm-up%n",
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"), seconds, warmup);

        Latency socket = socketFloor(payload);
        Latency rmi = rmiFloor(payload);
        out.printf("floor: loopback socket round trip  p50 %8.1f us   p99 %8.1f us%n", socket.p50Micros(), socket.p99Micros());
        out.printf("floor: bare RMI call               p50 %8.1f us   p99 %8.1f us%n", rmi.p50Micros(), rmi.p99Micros());
        double floor = socket.p50Micros() + 2 * rmi.p50Micros();
        out.printf("floor: socket + 2 RMI calls (the path's hops)  p50 %8.1f us%n", floor);

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
            out.printf("full:  client→server→service→client  p50 %8.1f us   p99 %8.1f us   (%.2f× the floor; target ≤ 1.5×)%n",
                    full.p50Micros(), full.p99Micros(), full.p50Micros() / floor);
            for (int n : clients) {
                double rate = throughput(pool.subList(0, n), mailbox, payload);
                out.printf("throughput with %2d client(s): %9.0f round trips/s%s%n", n, rate,
                        n == 32 ? "   (target ≥ 20,000/s)" : "");
            }
            pool.forEach(ClientSocketHandler::close);
        } finally {
            connector.close();
            clock.stop();
            server.stop();
        }
        return 0;
    }

    private Latency socketFloor(String payload) throws Exception {
        try (ServerSocket ss = new ServerSocket(0)) {
            Thread echo = new Thread(() -> {
                try (Socket s = ss.accept()) {
                    s.setTcpNoDelay(true);
                    DataInputStream in = new DataInputStream(s.getInputStream());
                    DataOutputStream o = new DataOutputStream(s.getOutputStream());
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
            try (Socket s = new Socket("localhost", ss.getLocalPort())) {
                s.setTcpNoDelay(true);
                DataInputStream in = new DataInputStream(s.getInputStream());
                DataOutputStream o = new DataOutputStream(s.getOutputStream());
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
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < end && n < samples.length) {
            long t0 = System.nanoTime();
            op.run();
            samples[n++] = System.nanoTime() - t0;
        }
        Arrays.sort(samples, 0, n);
        return new Latency(samples[n / 2] / 1000.0, samples[(int) (n * 0.99)] / 1000.0, n);
    }

    private double throughput(List<ClientSocketHandler> cs, String mailbox, String payload) throws Exception {
        AtomicBoolean counting = new AtomicBoolean(false);
        AtomicBoolean stop = new AtomicBoolean(false);
        AtomicLong done = new AtomicLong();
        CountDownLatch finished = new CountDownLatch(cs.size());
        List<Throwable> failures = new java.util.concurrent.CopyOnWriteArrayList<>();
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
        counting.set(true);
        long t0 = System.nanoTime();
        Thread.sleep((long) (seconds * 1000));
        counting.set(false);
        long elapsed = System.nanoTime() - t0;
        stop.set(true);
        finished.await();
        if (!failures.isEmpty()) {
            throw new IllegalStateException("a benchmark client failed", failures.get(0));
        }
        return done.get() / (elapsed / 1e9);
    }
}
