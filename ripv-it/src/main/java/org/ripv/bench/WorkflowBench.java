package org.ripv.bench;

import java.io.PrintStream;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.RIPVServer;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.PermitFile;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import org.ripv.services.bench.YmodemBaudRelay;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;
import org.ripv.services.serial.ymodem.DirectorySink;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.serial.ymodem.YmodemReceiver;
import org.ripv.services.serial.ymodem.YmodemSender;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.simulator.GliderSimulator;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code ./ripv bench workflow}: the glider simulator calls a {@code listen://} link through a
 * baud-paced relay (a serial line of {@code --baud}) with a workflow queued for it — {@code dir},
 * {@code ymodem:get} of 5 files (500 KB in all), {@code ymodem:put} of 100 KB — and the time from
 * the call to WORKFLOW_DONE (seen by a watching client) is set against the sum of the same six
 * transfers' times alone on the same kind of line, measured in the same run (target ≤ 1.15×).
 */
@Command(name = "workflow", mixinStandardHelpOptions = true,
        description = "A queued workflow on a vehicle's call, against its transfers alone at the line rate.")
public final class WorkflowBench implements Callable<Integer> {
    @Option(names = "--baud", defaultValue = "115200", description = "The line's rate (default ${DEFAULT-VALUE}).")
    int baud;

    @Option(names = "--files", defaultValue = "5", description = "Files fetched (default ${DEFAULT-VALUE}).")
    int files;

    @Option(names = "--get-bytes", defaultValue = "512000", description = "Bytes fetched in all (default ${DEFAULT-VALUE}).")
    int getBytes;

    @Option(names = "--put-bytes", defaultValue = "102400", description = "Bytes sent (default ${DEFAULT-VALUE}).")
    int putBytes;

    @Option(names = "--runs", defaultValue = "1", description = "Calls measured, each with a fresh vehicle (default ${DEFAULT-VALUE}).")
    int runs;

    @Option(names = "--report-only", description = "Exit 0 when the ratio misses the target (what --short passes: a shrunk"
            + " transfer is all overhead, so its ratio says nothing).")
    boolean reportOnly;

    private final PrintStream out = System.out;

    /** The files' contents: deterministic, incompressible. */
    private static byte[] content(int size, long seed) {
        byte[] b = new byte[size];
        new Random(seed).nextBytes(b);
        return b;
    }

    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("ripv-bench-workflow");
        out.printf("RIPV workflow benchmark — %d cores, Java %s, %d baud (%d bytes/s), %d runs%n",
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.version"), baud, baud / 10, runs);
        List<byte[]> gets = new ArrayList<>();
        for (int i = 0; i < files; i++) {
            gets.add(content(getBytes / files + (i < getBytes % files ? 1 : 0), i));
        }
        byte[] put = content(putBytes, 99);

        double alone = 0;
        CpuClock aloneCpu = CpuClock.start();
        for (byte[] g : gets) {
            alone += bare(g, dir);
        }
        alone += bare(put, dir);
        double aloneCpuMicros = aloneCpu.cpuMicrosPer(1);
        double arithmetic = (getBytes + putBytes) * 10.0 / baud;
        out.printf(Locale.ROOT, "the six transfers alone over the paced line: %.2f s (the bytes at the line rate: %.2f s)%n",
                alone, arithmetic);

        int worst = 0;
        for (int run = 1; run <= runs; run++) {
            // a fresh server each run: nothing "fetched before", an empty download store
            Path runDir = dir.resolve("run-" + run);
            RIPVServer server = new RIPVServer(ServerConfig.forTests(runDir.resolve("server"))
                    .withServiceCheck(Duration.ofSeconds(5)));
            server.start();
            try {
                PermitFile.setUser(runDir.resolve("server/permit.txt"), "pilot", "bench-password".toCharArray(),
                        List.of("operators"), 1000);
                server.reloadPermits();
                CpuClock callCpu = CpuClock.start();
                double t = oneCall(server, runDir, gets, put);
                double callCpuMicros = callCpu.cpuMicrosPer(1);
                double ratio = t / alone;
                out.printf(Locale.ROOT, "run %d: call → WORKFLOW_DONE %.2f s = %.3f × the transfers alone (target ≤ 1.15)%n",
                        run, t, ratio);
                out.println(CpuClock.ratioLine("call → WORKFLOW_DONE (server, service, simulator and client)", callCpuMicros,
                        aloneCpuMicros, ratio));
                worst = Math.max(worst, (int) Math.ceil(ratio * 1000));
            } finally {
                server.stop();
            }
        }
        return worst <= 1150 || reportOnly ? 0 : 1;
    }

    /** One call with the workflow queued: seconds from the vehicle's connect to WORKFLOW_DONE. */
    private double oneCall(RIPVServer server, Path work, List<byte[]> gets, byte[] put) throws Exception {
        Path vehicleDir = Files.createDirectories(work.resolve("glider"));
        for (int i = 0; i < gets.size(); i++) {
            Files.write(vehicleDir.resolve(String.format(Locale.ROOT, "0123%04d.SBD", i)), gets.get(i));
        }
        Files.writeString(vehicleDir.resolve("GLIDER.CFG"), "vehicle=SIM01\r\n", StandardCharsets.US_ASCII);
        LinkSettings link = LinkSettings.defaults("listen://127.0.0.1:0");
        SerialPortServer serial = SerialPortServer.withCalls("localhost",
                List.of(new VehicleLink(link, CallSettings.defaults().withName("ru29"))), null, false, work.resolve("serial"));
        String secret = Files.readString(server.secretFile(), StandardCharsets.UTF_8).trim();
        ServiceConnector connector = ServiceConnector.connect(serial,
                new ServiceOptions("localhost", server.registryPort(), secret, 0, Duration.ofSeconds(5)));
        connector.awaitRegistered(Duration.ofSeconds(30));
        String mb = "<SerialPortServer>::<localhost>ru29";
        ClientSocketHandler pilot = ClientSocketHandler.connect("localhost", server.port());
        pilot.login("pilot", "bench-password".toCharArray());
        GliderSimulator glider = null;
        try {
            Path local = Files.createDirectories(work.resolve("local"));
            Files.write(local.resolve("goto_l10.ma"), put);
            pilot.upload(local.resolve("goto_l10.ma"), "goto_l10.ma", ClientSocketHandler.IfExists.REPLACE, null);
            Files.writeString(local.resolve("bench.wf"), String.join("\n",
                    "workflow once",
                    "send dir expect=SBD",
                    "ymodem:get *.SBD timeout=10m",
                    "ymodem:put goto_l10.ma timeout=10m", ""));
            pilot.upload(local.resolve("bench.wf"), "bench.wf", ClientSocketHandler.IfExists.REPLACE, null);
            require(pilot.call("", "?queue add " + mb + " bench.wf", Priority.NORMAL, Duration.ofSeconds(30), null));

            CompletableFuture<Long> done = new CompletableFuture<>();
            pilot.addListener(r -> {
                if (Ids.FID_CONSOLE.equals(r.footer().serviceId()) && r.footer().result() instanceof ConsoleBatch b) {
                    for (ConsoleEntry e : b.entries()) {
                        if (e.event() == VehicleEvent.WORKFLOW_DONE) {
                            done.complete(System.nanoTime());
                        } else if (e.event() == VehicleEvent.WORKFLOW_FAILED) {
                            done.completeExceptionally(new IllegalStateException("the workflow failed: " + e.text()));
                        }
                    }
                }
            });
            require(pilot.call("", "?watch " + mb, Priority.NORMAL, Duration.ofSeconds(30), null));

            try (YmodemBaudRelay relay = new YmodemBaudRelay(baud, new InetSocketAddress("127.0.0.1", serial.listenPort("ru29")))) {
                glider = new GliderSimulator(vehicleDir, Duration.ofSeconds(600), YmodemConfig.lrzsz());
                long t0 = System.nanoTime();
                glider.call("127.0.0.1", relay.port(), "ru29", Duration.ofSeconds(600), Duration.ofSeconds(900));
                long t1 = done.get(30, TimeUnit.MINUTES);
                double seconds = (t1 - t0) / 1e9;
                OutgoingServerMessage receipt = pilot.call("", "?receipts " + mb + " --last 1", Priority.NORMAL,
                        Duration.ofSeconds(30), null);
                for (String line : receipt.footer().replyText().split("\n")) {
                    if (line.startsWith("step ") || line.startsWith("result:")) {
                        out.println("  " + line);
                    }
                }
                return seconds;
            }
        } finally {
            if (glider != null) {
                glider.close();
            }
            pilot.close();
            connector.close();
            serial.stop();
        }
    }

    private static void require(OutgoingServerMessage r) {
        if (r.status() != Status.OK) {
            throw new IllegalStateException(r.footer().replyText());
        }
    }

    /** Seconds for one bare YMODEM transfer of {@code data} (RIPV to RIPV) over a fresh paced line. */
    private double bare(byte[] data, Path dir) throws Exception {
        Path file = Files.createTempFile(dir, "bare", ".bin");
        Files.write(file, data);
        Path into = Files.createTempDirectory(dir, "bare-in");
        try (ServerSocket receiverSide = new ServerSocket(0);
             YmodemBaudRelay relay = new YmodemBaudRelay(baud, new InetSocketAddress("127.0.0.1", receiverSide.getLocalPort()))) {
            CompletableFuture<Object> receiving = CompletableFuture.supplyAsync(() -> {
                try (Socket s = receiverSide.accept(); TcpLink link = new TcpLink(s)) {
                    return new YmodemReceiver(link, YmodemConfig.lrzsz(), null).receiveBatch(new DirectorySink(into));
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            });
            long start = System.nanoTime();
            try (TcpLink link = TcpLink.connect("tcp://127.0.0.1:" + relay.port(), 5000)) {
                new YmodemSender(link, YmodemConfig.lrzsz(), null).sendBatch(List.of(SendFile.of(file)));
            }
            receiving.get(1, TimeUnit.HOURS);
            return (System.nanoTime() - start) / 1e9;
        }
    }
}
