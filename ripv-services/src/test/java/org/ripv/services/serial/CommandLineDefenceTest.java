package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ErrorCode;
import org.ripv.naming.Handles;

/**
 * Defence in depth: even when a request reaches the SerialPortServer without the server's check,
 * a command with a control character or over the link's length limit is refused before a single
 * byte of it is written to the vehicle.
 */
class CommandLineDefenceTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    Path tmp;
    ServerSocket vehicleSocket;
    Thread vehicle;
    final ByteArrayOutputStream heard = new ByteArrayOutputStream();
    SerialPortServer serial;

    @AfterEach
    void stop() throws Exception {
        if (serial != null) {
            serial.stop();
        }
        if (vehicleSocket != null) {
            vehicleSocket.close();
        }
    }

    /** A vehicle that records every byte it is sent and answers each line with its prompt. */
    private String startRecordingVehicle() throws Exception {
        vehicleSocket = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
        vehicle = new Thread(() -> {
            try (Socket s = vehicleSocket.accept()) {
                InputStream in = s.getInputStream();
                OutputStream out = s.getOutputStream();
                int b;
                while ((b = in.read()) >= 0) {
                    synchronized (heard) {
                        heard.write(b);
                    }
                    if (b == '\n') {
                        out.write("ok\r\nC:\\>".getBytes(StandardCharsets.ISO_8859_1));
                        out.flush();
                    }
                }
            } catch (Exception ignored) {
                // the test ends
            }
        }, "recording-vehicle");
        vehicle.setDaemon(true);
        vehicle.start();
        return "tcp://127.0.0.1:" + vehicleSocket.getLocalPort();
    }

    private String heard() {
        synchronized (heard) {
            return heard.toString(StandardCharsets.ISO_8859_1);
        }
    }

    @Test
    void controlCharactersAndLongCommandsNeverReachTheLink() throws Exception {
        String device = startRecordingVehicle();
        String handle = Handles.forLink(device);
        serial = new SerialPortServer("testhost", List.of(LinkSettings.defaults(device)
                .withIdleTimeout(Duration.ofMillis(500)).withReconnectEvery(Duration.ofMillis(200)).withMaxCommand(100)),
                null, false, tmp.resolve("work"));
        serial.start();
        ServiceProbe probe = new ServiceProbe(serial);
        Eventually.await("link up", Duration.ofSeconds(5), () -> probe.status(handle).available());

        for (String evil : List.of("dir\rGO", "dir\r\ndel GLIDER.CFG", "dir\u0003", "dir\u001b[2J", "dir\u0000GO",
                "dir\u007f", "dir\u009bGO", "ymodem:get A.LOG\rGO", "dir" + "x".repeat(98))) {
            ServiceProbe.Answer a = probe.send(handle, evil, T);
            assertFalse(a.ok(), evil);
            assertEquals(ErrorCode.BAD_REQUEST, a.last().footer().errorCode(), a.text());
        }
        assertEquals("", heard(), "nothing of a refused command was written to the vehicle");

        ServiceProbe.Answer ok = probe.send(handle, "dir\tA" + "x".repeat(94), T);
        assertTrue(ok.ok(), ok.text());
        assertEquals("dir\tA" + "x".repeat(94) + "\r\n", heard(), "a tab and exactly the limit pass");
    }

    @Test
    void maxcommandIsAPerLinkSetting() {
        SerialPortServerCommand c = new SerialPortServerCommand();
        new picocli.CommandLine(c).parseArgs("--server", "h", "--link", "/dev/ttyUSB0,maxcommand=200", "--link", "/tmp/x");
        assertEquals(200, c.settings(c.links.get(0)).maxCommand());
        assertEquals(1024, c.settings(c.links.get(1)).maxCommand());
        assertEquals(1024, LinkSettings.defaults("x").maxCommand());
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> c.settings("/dev/x,maxcommand=100000"));
        assertTrue(e.getMessage().contains("100000"), e.getMessage());
    }
}
