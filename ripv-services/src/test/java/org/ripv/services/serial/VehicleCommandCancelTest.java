package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Progress;
import org.ripv.services.bench.YmodemBaudRelay;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 12 on the service side, against the glider simulator over TCP: a running plain command
 * is cancelled with the link's interrupt and the vehicle is back at its prompt for the next one;
 * a link without an interrupt says it cannot; during a transfer the MailBox's status says what
 * runs, with percent, ETA and rate.
 */
class VehicleCommandCancelTest {
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path tmp;
    GliderSimulator glider;
    SerialPortServer serial;

    @AfterEach
    void stop() {
        if (serial != null) {
            serial.stop();
        }
        if (glider != null) {
            glider.close();
        }
    }

    private ServiceProbe start(LinkSettings link) throws Exception {
        serial = new SerialPortServer("testhost", List.of(link), null, false, tmp.resolve("work"));
        serial.start();
        ServiceProbe probe = new ServiceProbe(serial);
        String h = serial.handles().get(0);
        Eventually.await("link open", Duration.ofSeconds(10), () -> probe.status(h).available());
        return probe;
    }

    private int simulator() throws Exception {
        glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1), SimulatorOverTcpTest.YMODEM);
        return glider.listen(0);
    }

    @Test
    void aRunningCommandIsInterruptedAndTheVehicleIsBackAtItsPromptForTheNext() throws Exception {
        int port = simulator();
        ServiceProbe probe = start(SimulatorOverTcpTest.settings("tcp://127.0.0.1:" + port));
        String h = serial.handles().get(0);
        CompletableFuture<ServiceProbe.Answer> monitor = CompletableFuture.supplyAsync(() -> {
            try {
                return probe.send(h, "monitor 60", Duration.ofSeconds(90));
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
        Eventually.await("monitor running", Duration.ofSeconds(10),
                () -> probe.status(h).running().startsWith("running 'monitor 60' for alice"));
        Eventually.await("vehicle printing", Duration.ofSeconds(10),
                () -> probe.lines(h).stream().anyMatch(l -> l.startsWith("m_depth")));
        long t0 = System.nanoTime();
        assertTrue(probe.cancel(h, probe.lastId()), "the handler takes the cancel");
        ServiceProbe.Answer a = monitor.get(20, TimeUnit.SECONDS);
        assertFalse(a.ok());
        assertEquals(ErrorCode.CANCELLED, a.last().footer().errorCode(), a.text());
        assertTrue(a.text().startsWith("interrupted 'monitor 60' with ^C; the vehicle is back at its prompt"), a.text());
        assertTrue(a.text().contains("m_depth"), "what it printed comes with the reply: " + a.text());
        assertTrue(System.nanoTime() - t0 < TimeUnit.SECONDS.toNanos(30), "stopped long before the command (60 s) would have");
        assertEquals("", probe.status(h).running(), "nothing runs now");

        ServiceProbe.Answer dir = probe.send(h, "dir", T);
        assertTrue(dir.ok(), dir.text());
        assertTrue(dir.text().contains("MISSION1.LOG"), dir.text());
        assertFalse(dir.text().contains("m_depth"), "nothing of the cancelled command leaks into the next: " + dir.text());
        assertFalse(probe.cancel(h, probe.lastId()), "nothing left to cancel");
    }

    @Test
    void aLinkWithoutAnInterruptCannotCancelAPlainCommand() throws Exception {
        int port = simulator();
        ServiceProbe probe = start(SimulatorOverTcpTest.settings("tcp://127.0.0.1:" + port).withInterrupt(""));
        String h = serial.handles().get(0);
        CompletableFuture<ServiceProbe.Answer> monitor = CompletableFuture.supplyAsync(() -> {
            try {
                return probe.send(h, "monitor 2", T);
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
        Eventually.await("monitor running", Duration.ofSeconds(10), () -> !probe.status(h).running().isEmpty());
        assertFalse(probe.cancel(h, probe.lastId()));
        ServiceProbe.Answer a = monitor.get(20, TimeUnit.SECONDS);
        assertTrue(a.ok(), a.text());
    }

    @Test
    void duringATransferTheStatusSaysWhatRunsWithPercentEtaAndRate() throws Exception {
        int port = simulator();
        byte[] log = new byte[40_000];
        new Random(5).nextBytes(log);
        Files.write(glider.directory().resolve("BIG.LOG"), log);
        try (YmodemBaudRelay relay = new YmodemBaudRelay(57600, new InetSocketAddress("127.0.0.1", port))) {
            ServiceProbe probe = start(SimulatorOverTcpTest.settings("tcp://127.0.0.1:" + relay.port()));
            String h = serial.handles().get(0);
            CompletableFuture<ServiceProbe.Answer> get = CompletableFuture.supplyAsync(() -> {
                try {
                    return probe.send(h, "ymodem:get BIG.LOG", T);
                } catch (InterruptedException e) {
                    throw new IllegalStateException(e);
                }
            });
            Pattern shown = Pattern.compile("ymodem:get BIG\\.LOG \\d+ % ETA \\d+:\\d\\d, \\d+\\.\\d kB/s for alice");
            Eventually.await("status shows the transfer", T, () -> shown.matcher(probe.status(h).running()).matches());
            ServiceProbe.Answer a = get.get(30, TimeUnit.SECONDS);
            assertTrue(a.ok(), a.text());
            assertEquals("", probe.status(h).running());
            // the PROGRESS replies carry what the CLI shows as rate and ETA
            assertTrue(a.progress().stream().map(m -> (Progress) m.footer().result())
                    .anyMatch(p -> p.ratePerSecond() > 0 && !p.etaText().isEmpty()), "a progress with rate and ETA");
        }
    }

    @Test
    void interruptSpecs() {
        assertEquals("\u0003", Interrupt.parse("^C"));
        assertEquals("\u0003", Interrupt.parse("^c"));
        assertEquals("\u0018\u0003", Interrupt.parse("^X\\x03"));
        assertEquals("", Interrupt.parse("none"));
        assertEquals("q", Interrupt.parse("q"));
        assertEquals("^C", Interrupt.describe("\u0003"));
        assertEquals("none", Interrupt.describe(""));
        assertThrows(IllegalArgumentException.class, () -> Interrupt.parse("^1"));
        assertThrows(IllegalArgumentException.class, () -> Interrupt.parse("\\xZZ"));
        assertThrows(IllegalArgumentException.class, () -> Interrupt.parse(""));
    }
}
