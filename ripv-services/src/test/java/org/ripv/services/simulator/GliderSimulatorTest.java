package org.ripv.services.simulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ConnectException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.serial.Eventually;
import org.ripv.services.serial.TcpLink;
import org.ripv.services.serial.ymodem.YmodemConfig;
import picocli.CommandLine;

/** The simulator's shell as a raw TCP client sees it. */
class GliderSimulatorTest {
    @TempDir
    Path tmp;
    GliderSimulator glider;
    TcpLink link;

    @BeforeEach
    void start() throws IOException {
        glider = new GliderSimulator(tmp.resolve("c"), Duration.ofSeconds(1), YmodemConfig.lrzsz());
        link = TcpLink.connect("tcp://127.0.0.1:" + glider.listen(0), 2000);
    }

    @AfterEach
    void stop() {
        link.close();
        glider.close();
    }

    /** Reads until the text ends with the prompt. */
    private String untilPrompt() throws IOException {
        StringBuilder b = new StringBuilder();
        byte[] buf = new byte[4096];
        while (!b.toString().endsWith(GliderSimulator.PROMPT)) {
            int n = link.read(buf, 0, buf.length, 3000);
            if (n == 0) {
                throw new AssertionError("no prompt; got: " + b);
            }
            b.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
        }
        return b.toString();
    }

    private String run(String command) throws IOException {
        link.write((command + "\r\n").getBytes(StandardCharsets.ISO_8859_1));
        return untilPrompt();
    }

    @Test
    void seededFileSystemPromptAndEcho() throws IOException {
        assertTrue(untilPrompt().contains("PicoDOS"));
        String dir = run("dir");
        assertTrue(dir.startsWith("dir\r\n"), "echo: " + dir);
        for (String f : new String[] {"GLIDER.CFG", "MISSION1.LOG", "MISSION2.LOG", "SENSOR.DAT"}) {
            assertTrue(dir.contains(f), f + " in " + dir);
        }
        assertTrue(dir.contains("4 file(s)"), dir);
    }

    @Test
    void typeDelAndErrors() throws IOException {
        untilPrompt();
        assertTrue(run("type glider.cfg").contains("dive_depth_m=200"));
        assertTrue(run("type NOPE.TXT").contains("File not found - NOPE.TXT"));
        assertTrue(run("type ../etc/passwd").contains("File not found"));
        run("del MISSION2.LOG");
        assertFalse(Files.exists(glider.directory().resolve("MISSION2.LOG")));
        assertFalse(run("dir").contains("MISSION2.LOG"));
        assertTrue(run("launch").contains("Bad command or file name"));
        assertTrue(run("del").contains("Required parameter missing"));
    }

    @Test
    @SuppressWarnings("try") // a connection that opens is all the check needs
    void goDropsTheConnectionAndRefusesNewOnesUntilItSurfaces() throws Exception {
        untilPrompt();
        link.write("GO\r\n".getBytes(StandardCharsets.US_ASCII));
        StringBuilder said = new StringBuilder();
        byte[] buf = new byte[1024];
        assertThrows(java.io.EOFException.class, () -> {
            while (true) {
                int n = link.read(buf, 0, buf.length, 3000);
                said.append(new String(buf, 0, n, StandardCharsets.US_ASCII));
            }
        });
        assertTrue(said.toString().contains("submerging for 1 s"), said.toString());
        assertTrue(glider.submerged());
        assertThrows(ConnectException.class, () -> TcpLink.connect("tcp://127.0.0.1:" + glider.port(), 1000));
        Eventually.await("surfaced", Duration.ofSeconds(5), () -> !glider.submerged());
        Eventually.await("listening again", Duration.ofSeconds(5), () -> {
            try (TcpLink again = TcpLink.connect("tcp://127.0.0.1:" + glider.port(), 1000)) {
                return true;
            } catch (IOException e) {
                return false;
            }
        });
    }

    @Test
    void launcherRejectsBothPlaces() {
        int code = new CommandLine(new SimulatorCommand()).setErr(new java.io.PrintWriter(java.io.Writer.nullWriter()))
                .execute("--listen", "1", "--tty", "/dev/null");
        assertEquals(2, code);
    }

    @Test
    void launcherRejectsABadCallTargetAndTimes() {
        for (String[] args : new String[][] {{"--call", "nohost"}, {"--call", "h:99999"}, {"--call", ":2323"},
                {"--call", "h:1", "--surface-seconds", "0"}, {"--call", "h:1", "--dive-seconds", "-1"},
                {"--call", "h:1", "--name", "ru 29"}, {"--call", "h:1", "--listen", "2"}}) {
            int code = new CommandLine(new SimulatorCommand()).setErr(new java.io.PrintWriter(java.io.Writer.nullWriter()))
                    .execute(args);
            assertEquals(2, code, String.join(" ", args));
        }
    }

    @Test
    void launcherRejectsABadDialogAndABadLine() {
        for (String[] args : new String[][] {{"--dialog", "cpm"}, {"--latency", "1 s"}, {"--latency", "2h"},
                {"--latency", "2m"}, {"--drop-after", "60"}, {"--drop-after", "0s"}, {"--drop-after", "0b"},
                {"--baud", "-1"}, {"--minute-seconds", "0"}, {"--tty", "/dev/null", "--baud", "2400"}}) {
            int code = new CommandLine(new SimulatorCommand()).setErr(new java.io.PrintWriter(java.io.Writer.nullWriter()))
                    .execute(args);
            assertEquals(2, code, String.join(" ", args));
        }
    }

    @Test
    void theLineSettingsReadTimesAndBytes() {
        assertEquals(Duration.ofMillis(500), IridiumLine.Settings.duration("--latency", "500ms"));
        IridiumLine.Settings s = IridiumLine.Settings.withDrop(2400, Duration.ofSeconds(1), "60s");
        assertEquals(Duration.ofSeconds(60), s.dropAfterTime());
        assertEquals(40_000, IridiumLine.Settings.withDrop(2400, Duration.ZERO, "40000b").dropAfterBytes());
        assertFalse(IridiumLine.Settings.NONE.any());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> IridiumLine.Settings.withDrop(0, Duration.ZERO, "soon"));
        assertTrue(e.getMessage().contains("'soon'"), e.getMessage());
    }

    @Test
    void overAPacedLineBytesTakeTheirTimeAndTheCallDropsAfterItsBytes() throws Exception {
        link.close();
        glider.close();
        // 2,400 baud: 240 bytes a second; 200 ms each way
        glider = new GliderSimulator(tmp.resolve("paced"), Duration.ofSeconds(1), YmodemConfig.lrzsz())
                .overLine(IridiumLine.Settings.withDrop(2400, Duration.ofMillis(200), "2000b"));
        link = TcpLink.connect("tcp://127.0.0.1:" + glider.listen(0), 2000);
        long t0 = System.nanoTime();
        String banner = untilPrompt();
        double seconds = (System.nanoTime() - t0) / 1e9;
        // the banner's bytes at 240 a second, plus the latency; never faster (slower only under load)
        assertTrue(seconds >= banner.length() / 240.0 * 0.9 + 0.2, banner.length() + " bytes in " + seconds + " s");
        link.write("type MISSION1.LOG\r\n".getBytes(StandardCharsets.US_ASCII));
        StringBuilder got = new StringBuilder();
        byte[] buf = new byte[4096];
        assertThrows(java.io.EOFException.class, () -> {
            while (true) {
                int n = link.read(buf, 0, buf.length, 10_000);
                if (n == 0) {
                    throw new AssertionError("neither bytes nor a drop in 10 s");
                }
                got.append(new String(buf, 0, n, StandardCharsets.ISO_8859_1));
            }
        });
        // dropped after 2000 bytes both ways: a 10 KB file never arrived whole
        assertTrue(banner.length() + got.length() <= 2100, banner.length() + got.length() + " bytes");
    }

    @Test
    void theSurfaceDialogCarriesTheNameAndTheFixAsGlidersPrintIt() {
        String dialog = new SurfaceDialog("ru29").text(1, java.time.Instant.parse("2026-11-23T14:55:02Z"));
        assertTrue(dialog.contains("\r\nGlider ru29 at surface.\r\n"), dialog);
        assertTrue(dialog.contains("Vehicle Name: ru29\r\n"), dialog);
        assertTrue(dialog.contains("Curr Time: Mon Nov 23 14:55:02 2026"), dialog);
        assertTrue(dialog.contains("GPS Location:  4137.994 N -7032.188 E measured     26.0 secs ago\r\n"), dialog);
        assertTrue(dialog.contains("sensor:m_battery(volts)=15.15"), dialog);
        assertTrue(dialog.contains("MissionName:SIM.MI"), dialog);
        assertFalse(dialog.matches("(?s).*(abort|ABORT|leak|LEAK|Error|ERROR).*"), "no alert in a normal call");
    }
}
