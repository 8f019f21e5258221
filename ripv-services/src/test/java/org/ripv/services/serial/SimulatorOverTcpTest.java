package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.Progress;
import org.ripv.naming.Handles;
import org.ripv.probe.FreePorts;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;

/** The SerialPortServer in-process against the glider simulator over TCP. */
class SimulatorOverTcpTest {
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    Path tmp;

    GliderSimulator glider;
    SerialPortServer serial;
    ServiceProbe probe;
    String handle;

    @BeforeEach
    void start() throws Exception {
        glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(2), YMODEM);
        int port = glider.listen(0);
        String device = "tcp://127.0.0.1:" + port;
        handle = Handles.forLink(device);
        serial = new SerialPortServer("testhost", List.of(settings(device)), null, false, tmp.resolve("work"));
        serial.start();
        probe = new ServiceProbe(serial);
    }

    static LinkSettings settings(String device) {
        return LinkSettings.defaults(device).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(200)).withYmodem(YMODEM);
    }

    @AfterEach
    void stop() {
        serial.stop();
        glider.close();
    }

    @Test
    void mailboxIsNamedAfterTheLinkAndBecomesAvailable() {
        assertEquals("tcp-127.0.0.1-" + glider.port(), handle);
        assertEquals(List.of(handle), serial.handles());
        Eventually.await("link up", Duration.ofSeconds(5), () -> probe.status(handle).available());
        assertEquals("<SerialPortServer>::<testhost>" + handle, probe.status(handle).address());
    }

    @Test
    void dirReturnsTheListingWithoutEchoOrPrompt() throws Exception {
        ServiceProbe.Answer dir = probe.send(handle, "dir", T);
        assertTrue(dir.ok(), dir.text());
        assertTrue(dir.text().contains("MISSION1.LOG"), dir.text());
        assertTrue(dir.text().contains("GLIDER.CFG"), dir.text());
        assertFalse(dir.text().startsWith("dir"), "echo stripped: " + dir.text());
        assertFalse(dir.text().contains("C:\\>"), "prompt stripped: " + dir.text());

        ServiceProbe.Answer type = probe.send(handle, "type GLIDER.CFG", T);
        assertEquals(Files.readString(glider.directory().resolve("GLIDER.CFG")).replace("\r\n", "\n").strip(),
                type.text());
        assertEquals("Bad command or file name", probe.send(handle, "fly away", T).text());
    }

    @Test
    void ymodemGetOfOneMegabyteLog() throws Exception {
        byte[] log = new byte[1024 * 1024];
        new Random(1).nextBytes(log);
        Files.write(glider.directory().resolve("BIG.LOG"), log);
        ServiceProbe.Answer got = probe.send(handle, "ymodem:get BIG.LOG", T);
        assertTrue(got.ok(), got.text());
        FileData file = assertInstanceOf(FileData.class, got.last().footer().result());
        assertEquals("BIG.LOG", file.name());
        assertArrayEquals(log, file.data());
        assertFalse(got.progress().isEmpty(), "PROGRESS replies");
        Progress last = (Progress) got.progress().get(got.progress().size() - 1).footer().result();
        assertEquals(log.length, last.total());
        assertTrue(got.text().startsWith("received BIG.LOG (1048576 bytes)"), got.text());
        // the shell is back at its prompt for the next command
        assertTrue(probe.send(handle, "dir", T).text().contains("BIG.LOG"));
    }

    @Test
    void vehicleLostMidTransferGivesAClearErrorAndNoFile() throws Exception {
        byte[] log = new byte[8 * 1024 * 1024];
        new Random(5).nextBytes(log);
        Files.write(glider.directory().resolve("HUGE.LOG"), log);
        java.util.concurrent.atomic.AtomicBoolean cut = new java.util.concurrent.atomic.AtomicBoolean();
        probe.onProgress = m -> {
            Progress p = (Progress) m.footer().result();
            // The first report comes once block 0 has arrived: the transfer is under way. Waiting for
            // bytes done raced a fast machine, where the first such report is the last.
            if (p.total() > 0 && cut.compareAndSet(false, true)) {
                glider.close(); // the vehicle vanishes with the transfer under way
            }
        };
        ServiceProbe.Answer got = probe.send(handle, "ymodem:get HUGE.LOG", T);
        assertTrue(cut.get(), "the fault was injected mid-transfer");
        assertFalse(got.ok());
        assertEquals(ErrorCode.DEVICE_ERROR, got.last().footer().errorCode(), got.text());
        assertTrue(got.text().contains("reopened when it comes back"), got.text());
        assertFalse(probe.status(handle).available());
        try (var left = Files.walk(tmp.resolve("work"))) {
            assertEquals(List.of(), left.filter(Files::isRegularFile).toList(), "no partial file left");
        }
    }

    @Test
    void echoAndPromptAreFoundWhereverTheyAre() {
        VehicleText h = new VehicleText(settings("tcp://h:1").prompt());
        assertEquals(5, VehicleText.echoEnd("dir\r\nabc", "dir"));
        assertEquals(-1, VehicleText.echoEnd("dirt\r\n", "dir"));
        assertEquals("a\nb", h.clean("\r\nBanner\r\nC:\\>dir\r\na\r\nb\r\nC:\\>", "dir"));
        assertEquals("no echo", h.clean("no echo\r\nC:\\>  ", "dir"));
    }

    @Test
    void ymodemGetOfSeveralFilesIsABundle() throws Exception {
        ServiceProbe.Answer got = probe.send(handle, "ymodem:get MISSION1.LOG GLIDER.CFG SENSOR.DAT", T);
        assertTrue(got.ok(), got.text());
        FileBundle bundle = assertInstanceOf(FileBundle.class, got.last().footer().result());
        assertEquals(List.of("MISSION1.LOG", "GLIDER.CFG", "SENSOR.DAT"),
                bundle.files().stream().map(FileData::name).toList());
        for (FileData f : bundle.files()) {
            assertArrayEquals(Files.readAllBytes(glider.directory().resolve(f.name())), f.data(), f.name());
        }
        assertTrue(Files.list(tmp.resolve("work").resolve(handle)).findAny().isEmpty(), "work dir cleaned");
    }

    @Test
    void ymodemGetOfAMissingFileFailsFast() throws Exception {
        long start = System.nanoTime();
        ServiceProbe.Answer got = probe.send(handle, "ymodem:get NOSUCH.LOG", T);
        assertFalse(got.ok());
        assertEquals(ErrorCode.TRANSFER_FAILED, got.last().footer().errorCode());
        assertTrue(got.text().contains("File not found - NOSUCH.LOG"), got.text());
        // Waiting for the transfer to start would take the 10 s start timeout: anything below tells them apart.
        assertTrue(System.nanoTime() - start < 9_000_000_000L, "did not wait for the YMODEM timeout");
        assertTrue(probe.send(handle, "dir", T).ok());
    }

    @Test
    void ymodemPutSendsTheAttachedUpload() throws Exception {
        byte[] binary = new byte[200_000 + 17];
        new Random(2).nextBytes(binary);
        ServiceProbe.Answer put = probe.send(handle, "ymodem:put GLIDER.BIN",
                new Attachment("GLIDER.BIN", binary), T);
        assertTrue(put.ok(), put.text());
        assertTrue(put.text().startsWith("sent GLIDER.BIN (200017 bytes)"), put.text());
        assertFalse(put.progress().isEmpty());
        assertArrayEquals(binary, Files.readAllBytes(glider.directory().resolve("GLIDER.BIN")));
        assertTrue(probe.send(handle, "dir", T).text().contains("GLIDER.BIN"));
    }

    @Test
    void badTransferRequestsGetClearErrors() throws Exception {
        ServiceProbe.Answer noFile = probe.send(handle, "ymodem:put GLIDER.BIN", T);
        assertEquals(ErrorCode.BAD_REQUEST, noFile.last().footer().errorCode());
        assertTrue(noFile.text().contains("upload it to the server first"), noFile.text());
        ServiceProbe.Answer badName = probe.send(handle, "ymodem:get ../etc/passwd", T);
        assertEquals(ErrorCode.BAD_FILE_NAME, badName.last().footer().errorCode());
        assertEquals(ErrorCode.BAD_REQUEST, probe.send(handle, "ymodem:get", T).last().footer().errorCode());
        assertEquals(ErrorCode.UNKNOWN_COMMAND, probe.send(handle, "ymodem:list", T).last().footer().errorCode());
    }

    @Test
    void vehicleWithoutTheConfiguredCommandsFailsFastWithItsOwnWords() throws Exception {
        serial.stop();
        String device = "tcp://127.0.0.1:" + glider.port();
        serial = new SerialPortServer("testhost", List.of(settings(device).withVehicleCommands("sendfiles", "Creceive")),
                null, false, tmp.resolve("work"));
        serial.start();
        probe = new ServiceProbe(serial);
        long start = System.nanoTime();
        ServiceProbe.Answer put = probe.send(handle, "ymodem:put X.BIN", new Attachment("X.BIN", new byte[100]), T);
        assertEquals(ErrorCode.TRANSFER_FAILED, put.last().footer().errorCode());
        assertTrue(put.text().contains("Bad command or file name"), put.text());
        ServiceProbe.Answer get = probe.send(handle, "ymodem:get GLIDER.CFG", T);
        assertEquals(ErrorCode.TRANSFER_FAILED, get.last().footer().errorCode());
        assertTrue(get.text().contains("Bad command or file name"), get.text());
        assertTrue(System.nanoTime() - start < 9_500_000_000L, "no YMODEM timeouts waited out (one is 10 s)");
        assertFalse(Files.exists(glider.directory().resolve("X.BIN")));
        assertTrue(probe.send(handle, "dir", T).text().contains("GLIDER.CFG"), "shell still usable");
    }

    @Test
    void goSubmergesTheGliderUntilItSurfaces() throws Exception {
        Eventually.await("link up", Duration.ofSeconds(5), () -> probe.status(handle).available());
        ServiceProbe.Answer go = probe.send(handle, "GO", T);
        assertTrue(go.ok(), go.text());
        assertTrue(go.text().contains("submerging"), go.text());
        assertFalse(probe.status(handle).available(), "not available while under water");
        ServiceProbe.Answer under = probe.send(handle, "dir", T);
        assertEquals(ErrorCode.NOT_AVAILABLE, under.last().footer().errorCode(), under.text());
        Eventually.await("surfaced", Duration.ofSeconds(10), () -> probe.status(handle).available());
        assertTrue(probe.send(handle, "dir", T).text().contains("MISSION1.LOG"));
    }

    @Test
    void aLinkToNothingIsNotAvailableAndSaysWhy() throws Exception {
        int closedPort = FreePorts.one();
        String device = "tcp://127.0.0.1:" + closedPort;
        SerialPortServer other = new SerialPortServer("testhost", List.of(settings(device)), null, false,
                tmp.resolve("work2"));
        other.start();
        try {
            ServiceProbe p = new ServiceProbe(other);
            String h = Handles.forLink(device);
            assertFalse(p.status(h).available());
            ServiceProbe.Answer a = p.send(h, "dir", T);
            assertEquals(ErrorCode.NOT_AVAILABLE, a.last().footer().errorCode());
            assertTrue(a.text().contains(device), a.text());
        } finally {
            other.stop();
        }
    }

    @Test
    void unsolicitedOutputDoesNotLeakIntoTheNextReply() throws Exception {
        assertTrue(probe.send(handle, "dir", T).ok());
        // the banner and prompt of a fresh connection are unsolicited; the reply to 'type' must not carry them
        assertEquals(Files.readString(glider.directory().resolve("GLIDER.CFG"), StandardCharsets.US_ASCII)
                .replace("\r\n", "\n").strip(), probe.send(handle, "type glider.cfg", T).text());
    }
}
