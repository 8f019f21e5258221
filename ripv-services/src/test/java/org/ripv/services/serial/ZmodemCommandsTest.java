package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Random;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.Attachment;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileData;
import org.ripv.testing.Tools;

/**
 * zmodem:get, zmodem:put and ?key through the SerialPortServer against a vehicle whose ZMODEM is
 * lrzsz ({@code zmodem-vehicle.sh} behind a socat pseudo-terminal): files both ways and
 * byte-identical, a refused {@code zs} answered clearly and followed by a clean line, Ctrl-C
 * reaching the vehicle and its prompt coming back, keys the link does not allow refused.
 */
class ZmodemCommandsTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path tmp;

    @BeforeAll
    static void tools() {
        Tools.require("socat", "sz", "rz", "bash");
    }

    static Socat vehicle(Path tmp, Path dir, Path pty) throws Exception {
        Path script = tmp.resolve("zmodem-vehicle.sh");
        try (InputStream in = ZmodemCommandsTest.class.getResourceAsStream("zmodem-vehicle.sh")) {
            Files.write(script, in.readAllBytes());
        }
        return Socat.start(dir, "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec bash " + script + " " + dir + "'", pty);
    }

    static LinkSettings gliderLink(String device) {
        LinkSettings d = LinkSettings.defaults(device);
        return new LinkSettings(device, d.baud(), d.dataBits(), d.parity(), d.stopBits(), "\r",
                Pattern.compile("GliderDOS \\S+ # >"), Duration.ofSeconds(1), Duration.ofSeconds(30), d.carrier(),
                d.sendCommand(), d.receiveCommand(), Duration.ofMillis(200), SimulatorOverTcpTest.YMODEM);
    }

    private SerialPortServer serial(Path pty, String keys) throws Exception {
        VehicleLink link = new VehicleLink(gliderLink(pty.toString()), CallSettings.defaults().withName("ru29"),
                new PilotSettings(ControlKey.parseList(keys), "zs", "zr"));
        SerialPortServer serial = SerialPortServer.withCalls("testhost", List.of(link), null, false, tmp.resolve("work"));
        serial.start();
        return serial;
    }

    @Test
    void getAndPutBothWaysByteIdenticalWithACleanLineAfterARefusal() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("vehicle"));
        byte[] log = new byte[70_000];
        new Random(3).nextBytes(log);
        Files.write(dir.resolve("01230000.DBD"), log);
        Path pty = tmp.resolve("ttyZ");
        try (Socat socat = vehicle(tmp, dir, pty)) {
            SerialPortServer serial = serial(pty, ControlKey.DEFAULT_KEYS);
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                Eventually.await("pty open", Duration.ofSeconds(10), () -> probe.status("ru29").available());
                ServiceProbe.Answer got = probe.send("ru29", "zmodem:get 01230000.DBD", T);
                assertTrue(got.ok(), got.text() + "; socat: " + socat.log());
                assertArrayEquals(log, assertInstanceOf(FileData.class, got.last().footer().result()).data());
                assertTrue(got.text().startsWith("received 01230000.DBD (70000 bytes)"), got.text());
                assertFalse(got.progress().isEmpty(), "progress replies while it ran");

                byte[] up = new byte[40_000];
                new Random(4).nextBytes(up);
                ServiceProbe.Answer put = probe.send("ru29", "zmodem:put goto_l10.ma", new Attachment("goto_l10.ma", up), T);
                assertTrue(put.ok(), put.text());
                assertArrayEquals(up, Files.readAllBytes(dir.resolve("goto_l10.ma")));

                ServiceProbe.Answer missing = probe.send("ru29", "zmodem:get NOSUCH.DBD", T);
                assertFalse(missing.ok());
                assertTrue(missing.text().contains("aborted") && missing.text().contains("cannot open"), missing.text());

                // the line is clean after all of it: a plain command gets its own answer
                ServiceProbe.Answer dirAnswer = probe.send("ru29", "dir", T);
                assertTrue(dirAnswer.ok() && dirAnswer.text().contains("goto_l10.ma"), dirAnswer.text());
            } finally {
                serial.stop();
            }
        }
    }

    @Test
    void aVehicleWhoseShellRefusesZsGetsAClearErrorAndACleanLine() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("vehicle"));
        Path pty = tmp.resolve("ttyR");
        try (Socat socat = vehicle(tmp, dir, pty)) {
            VehicleLink link = new VehicleLink(gliderLink(pty.toString()), CallSettings.defaults().withName("ru30"),
                    new PilotSettings(ControlKey.parseList("ctrl-c"), "send-by-z", "zr"));
            SerialPortServer serial = SerialPortServer.withCalls("testhost", List.of(link), null, false, tmp.resolve("work"));
            serial.start();
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                Eventually.await("pty open", Duration.ofSeconds(10), () -> probe.status("ru30").available());
                ServiceProbe.Answer refused = probe.send("ru30", "zmodem:get A.DBD", T);
                assertFalse(refused.ok());
                assertTrue(refused.text().contains("did not start ZMODEM") && refused.text().contains("Bad command"),
                        refused.text());
                ServiceProbe.Answer dirAnswer = probe.send("ru30", "dir", T);
                assertTrue(dirAnswer.ok() && !dirAnswer.text().contains("Bad command"), dirAnswer.text());
            } finally {
                serial.stop();
            }
        }
    }

    @Test
    void ctrlCReachesTheVehicleAndKeysNotInTheLinksListAreRefused() throws Exception {
        Path dir = Files.createDirectories(tmp.resolve("vehicle"));
        Path pty = tmp.resolve("ttyK");
        try (Socat socat = vehicle(tmp, dir, pty)) {
            SerialPortServer serial = serial(pty, "ctrl-c,ctrl-r");
            try {
                ServiceProbe probe = new ServiceProbe(serial);
                Eventually.await("pty open", Duration.ofSeconds(10), () -> probe.status("ru29").available());
                ServiceProbe.Answer c = probe.send("ru29", "?key ctrl-c", T);
                assertTrue(c.ok(), c.text());
                assertTrue(c.text().startsWith("sent ctrl-c") && c.text().contains("Control-C received")
                        && c.text().endsWith("GliderDOS A # >"), c.text());
                ServiceProbe.Answer r = probe.send("ru29", "?key Ctrl-R", T);
                assertTrue(r.ok() && r.text().contains("resuming mission"), r.text());

                ServiceProbe.Answer e = probe.send("ru29", "?key ctrl-e", T);
                assertFalse(e.ok());
                assertEquals(ErrorCode.FORBIDDEN, e.last().footer().errorCode());
                assertTrue(e.text().contains("'ctrl-e' is not allowed on ru29; it allows ctrl-c, ctrl-r"), e.text());
                ServiceProbe.Answer bad = probe.send("ru29", "?key ^C", T);
                assertFalse(bad.ok());
                assertTrue(bad.text().contains("'^C' is not a control key"), bad.text());

                // the transcript says who pressed what; refused keys never reached it
                List<String> commands = probe.console("ru29", ConsoleEntry.Kind.COMMAND).stream()
                        .map(x -> x.user() + ": " + x.text()).toList();
                assertEquals(List.of("alice: ?key ctrl-c", "alice: ?key ctrl-r"), commands);
            } finally {
                serial.stop();
            }
        }
    }
}
