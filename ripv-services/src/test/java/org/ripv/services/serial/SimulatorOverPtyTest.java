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
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.testing.Tools;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileData;
import org.ripv.services.simulator.GliderSimulator;

/**
 * The SerialPortServer and the glider simulator on the two ends of a socat pseudo-terminal
 * pair, both through jSerialComm, opened by symlink: commands, YMODEM both ways, carrier
 * handling, and a link that vanishes and comes back.
 */
class SimulatorOverPtyTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path tmp;

    @BeforeAll
    static void tools() {
        Tools.require("socat");
    }

    private Socat ptyPair(Path a, Path b) throws Exception {
        return Socat.start(tmp, "pty,raw,echo=0,link=" + a, "pty,raw,echo=0,link=" + b, a, b);
    }

    @Test
    @SuppressWarnings("try") // socat only has to live as long as the block
    void commandsAndYmodemOverAPseudoTerminal() throws Exception {
        Path server = tmp.resolve("ttyV0");
        Path vehicle = tmp.resolve("ttyV1");
        try (Socat socat = ptyPair(server, vehicle);
             GliderSimulator glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1),
                     SimulatorOverTcpTest.YMODEM)) {
            glider.attach(vehicle.toString());
            byte[] log = new byte[300_000];
            new Random(3).nextBytes(log);
            Files.write(glider.directory().resolve("LOG1.BIN"), log);
            SerialPortServer serial = new SerialPortServer("testhost",
                    List.of(SimulatorOverTcpTest.settings(server.toString())), null, false, tmp.resolve("work"));
            serial.start();
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                assertEquals(List.of("ttyV0"), serial.handles(), "handle is the symlink's name, not /dev/pts/N");
                Eventually.await("pty open", Duration.ofSeconds(5), () -> probe.status("ttyV0").available());
                assertTrue(probe.status("ttyV0").detail().contains("/dev/pts/"), probe.status("ttyV0").detail());

                ServiceProbe.Answer dir = probe.send("ttyV0", "dir", T);
                assertTrue(dir.text().contains("MISSION1.LOG"), dir.text());

                ServiceProbe.Answer got = probe.send("ttyV0", "ymodem:get LOG1.BIN", T);
                assertTrue(got.ok(), got.text());
                assertArrayEquals(log, assertInstanceOf(FileData.class, got.last().footer().result()).data());

                byte[] binary = new byte[70_000];
                new Random(4).nextBytes(binary);
                ServiceProbe.Answer put = probe.send("ttyV0", "ymodem:put NEW.BIN", new Attachment("NEW.BIN", binary), T);
                assertTrue(put.ok(), put.text());
                assertArrayEquals(binary, Files.readAllBytes(glider.directory().resolve("NEW.BIN")));
            } finally {
                serial.stop();
            }
        }
    }

    @Test
    @SuppressWarnings("try")
    void carrierRequiredOnAPtyMeansNothingIsSent() throws Exception {
        Path server = tmp.resolve("ttyC0");
        Path far = tmp.resolve("ttyC1");
        try (Socat socat = ptyPair(server, far);
             SerialLink farEnd = SerialLink.open(LinkSettings.defaults(far.toString()))) {
            SerialPortServer serial = new SerialPortServer("testhost",
                    List.of(SimulatorOverTcpTest.settings(server.toString()).withCarrier(CarrierMode.REQUIRE)), null,
                    false, tmp.resolve("work"));
            serial.start();
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                // a pty reports DCD low
                Eventually.await("carrier reported", Duration.ofSeconds(5),
                        () -> probe.status("ttyC0").detail().contains("DCD low"));
                assertFalse(probe.status("ttyC0").available());
                ServiceProbe.Answer a = probe.send("ttyC0", "dir", T);
                assertEquals(ErrorCode.NOT_AVAILABLE, a.last().footer().errorCode());
                assertTrue(a.text().contains("nothing was sent"), a.text());
                assertEquals(0, farEnd.read(new byte[16], 0, 16, 300), "no byte reached the far end");
            } finally {
                serial.stop();
            }
        }
    }

    @Test
    void vanishedPtyPeerIsReportedAndTheLinkReopensWhenItComesBack() throws Exception {
        Path server = tmp.resolve("ttyR0");
        Path vehicle = tmp.resolve("ttyR1");
        Socat socat = ptyPair(server, vehicle);
        GliderSimulator glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1),
                SimulatorOverTcpTest.YMODEM);
        glider.attach(vehicle.toString());
        SerialPortServer serial = new SerialPortServer("testhost",
                List.of(SimulatorOverTcpTest.settings(server.toString())), null, false, tmp.resolve("work"));
        serial.start();
        try {
            ServiceProbe probe = new ServiceProbe(serial);
            assertTrue(probe.send("ttyR0", "dir", T).ok());
            socat.close(); // the pty pair disappears under both programs
            glider.close();
            Eventually.await("link reported down", Duration.ofSeconds(10), () -> !probe.status("ttyR0").available());
            ServiceProbe.Answer down = probe.send("ttyR0", "dir", T);
            assertFalse(down.ok());
            assertTrue(down.text().contains("ttyR0"), down.text());

            socat = ptyPair(server, vehicle);
            glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1), SimulatorOverTcpTest.YMODEM);
            glider.attach(vehicle.toString());
            Eventually.await("link reopened", Duration.ofSeconds(10), () -> probe.status("ttyR0").available());
            assertTrue(probe.send("ttyR0", "dir", T).text().contains("MISSION1.LOG"));
        } finally {
            serial.stop();
            glider.close();
            socat.close();
        }
    }

    /** Issue 24: the GliderDOS dialog on a pty, raw bytes through jSerialComm on the other end. */
    @Test
    @SuppressWarnings("try") // socat only has to live as long as the block
    void theGliderDosDialogOverAPseudoTerminal() throws Exception {
        Path shore = tmp.resolve("ttyG0");
        Path vehicle = tmp.resolve("ttyG1");
        try (Socat socat = ptyPair(shore, vehicle);
             GliderSimulator glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1),
                     SimulatorOverTcpTest.YMODEM).named("ru29").speakGliderDos(Duration.ofSeconds(30), Duration.ofSeconds(1));
             SerialLink link = SerialLink.open(LinkSettings.defaults(shore.toString()))) {
            glider.attach(vehicle.toString());
            StringBuilder said = new StringBuilder();
            until(link, said, "seconds to abort the mission...");
            assertTrue(said.toString().contains("Glider ru29 at surface."), said.toString());
            link.write(new byte[] {0x03}, 0, 1);
            link.flush();
            until(link, said, "GliderDOS I -3 >");
            link.write("put c_dive_target_depth 30\r".getBytes(StandardCharsets.US_ASCII), 0, 27);
            link.flush();
            assertTrue(until(link, said, "GliderDOS I -3 >").contains("sensor:c_dive_target_depth=30"), said.toString());
            link.write("go\r".getBytes(StandardCharsets.US_ASCII), 0, 3);
            link.flush();
            // resumed: on a tty the glider dives (1 s) and surfaces with its dialog again
            until(link, said, "MissionNum:ru29-2");
        }
    }

    private static String until(SerialLink link, StringBuilder said, String text) throws java.io.IOException {
        int from = said.length();
        long end = System.nanoTime() + T.toNanos();
        byte[] buf = new byte[1024];
        while (said.indexOf(text, from) < 0) {
            assertTrue(System.nanoTime() < end, "never said '" + text + "': " + said.substring(from));
            int n = link.read(buf, 0, buf.length, 500);
            said.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
        }
        return said.substring(from);
    }
}
