package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileData;
import org.ripv.naming.Handles;
import org.ripv.services.simulator.GliderSimulator;

/**
 * The SerialPortServer against the simulator's Iridium-like line (issue 24): a YMODEM get is no
 * faster than the line's baud rate, as its rate and ETA then say, and a cancel crosses the line's
 * latency and still leaves the vehicle at its prompt.
 */
class IridiumLikeTransferTest {
    static final Duration T = Duration.ofSeconds(120);
    static final Pattern RATE = Pattern.compile("\\((\\d+) bytes/s\\)");

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

    private ServiceProbe start(int baud) throws Exception {
        glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(2), SimulatorOverTcpTest.YMODEM)
                .overLine(baud, Duration.ofMillis(100), null);
        String device = "tcp://127.0.0.1:" + glider.listen(0);
        serial = new SerialPortServer("testhost", List.of(SimulatorOverTcpTest.settings(device)
                .withIdleTimeout(Duration.ofSeconds(3))), null, false, tmp.resolve("work"));
        serial.start();
        ServiceProbe probe = new ServiceProbe(serial);
        Eventually.await("link up", Duration.ofSeconds(10), () -> probe.status(Handles.forLink(device)).available());
        return probe;
    }

    @Test
    void aGetIsPacedToTheLineAndACancelLeavesTheVehicleAtItsPrompt() throws Exception {
        ServiceProbe probe = start(19_200); // 1,920 bytes a second
        String h = serial.handles().get(0);
        byte[] log = new byte[6000];
        new Random(24).nextBytes(log);
        Files.write(glider.directory().resolve("PACED.LOG"), log);
        long t0 = System.nanoTime();
        ServiceProbe.Answer got = probe.send(h, "ymodem:get PACED.LOG", T);
        double seconds = (System.nanoTime() - t0) / 1e9;
        assertTrue(got.ok(), got.text());
        assertArrayEquals(log, assertInstanceOf(FileData.class, got.last().footer().result()).data());
        assertTrue(seconds >= 6000 / 1920.0, "6000 bytes at 1,920 a second took " + seconds + " s");
        Matcher m = RATE.matcher(got.text());
        assertTrue(m.find(), got.text());
        assertTrue(Long.parseLong(m.group(1)) <= 1920 * 1.05, "the reported rate is the line's: " + got.text());

        // a cancel mid-transfer crosses the line and the vehicle is back at its prompt afterwards
        byte[] big = new byte[60_000];
        new Random(25).nextBytes(big);
        Files.write(glider.directory().resolve("BIG.LOG"), big);
        java.util.concurrent.CountDownLatch going = new java.util.concurrent.CountDownLatch(1);
        probe.onProgress = p -> going.countDown();
        CompletableFuture<ServiceProbe.Answer> cut = CompletableFuture.supplyAsync(() -> {
            try {
                return probe.send(h, "ymodem:get BIG.LOG", T);
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
        assertTrue(going.await(60, TimeUnit.SECONDS), "the transfer got going");
        assertTrue(probe.cancel(h, probe.lastId()), "the handler takes the cancel");
        ServiceProbe.Answer cancelled = cut.get(120, TimeUnit.SECONDS);
        assertEquals(ErrorCode.CANCELLED, cancelled.last().footer().errorCode(), cancelled.text());
        probe.onProgress = p -> { };
        ServiceProbe.Answer dir = probe.send(h, "dir", T);
        assertTrue(dir.ok() && dir.text().contains("BIG.LOG"), dir.text());
    }
}
