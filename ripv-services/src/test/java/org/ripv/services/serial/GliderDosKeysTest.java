package org.ripv.services.serial;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 24: RIPV's {@code ?key} against the simulator's GliderDOS dialog. The simulated Slocum
 * calls a listen:// link and counts down; {@code ?key ctrl-e} extends the wait, {@code ?key
 * ctrl-c} brings its GliderDOS prompt, a command runs there, and GO ends the call.
 */
class GliderDosKeysTest {
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    Path tmp;
    SerialPortServer serial;
    GliderSimulator glider;

    @AfterEach
    void stop() {
        if (glider != null) {
            glider.close();
        }
        if (serial != null) {
            serial.stop();
        }
    }

    @Test
    void keysFromRipvDriveTheSurfaceDialog() throws Exception {
        LinkSettings link = SimulatorOverTcpTest.settings("listen://127.0.0.1:0")
                .withPrompt(Pattern.compile("Glider[Dd][Oo][Ss] [A-Z] -?[0-9]+ >|C:\\\\>")).withIdleTimeout(Duration.ofSeconds(2));
        serial = SerialPortServer.withCalls("testhost", List.of(new VehicleLink(link, CallSettings.defaults().withName("ru29"))),
                null, false, tmp.resolve("work"));
        serial.start();
        ServiceProbe probe = new ServiceProbe(serial);
        glider = new GliderSimulator(tmp.resolve("glider"), Duration.ofSeconds(1), SimulatorOverTcpTest.YMODEM)
                .speakGliderDos(Duration.ofSeconds(40), Duration.ofSeconds(1));
        glider.call("127.0.0.1", serial.listenPort("ru29"), "ru29", Duration.ofSeconds(60), Duration.ofSeconds(40));
        Eventually.await("the countdown", T, () -> probe.lines("ru29").stream().anyMatch(l -> l.contains("to abort the mission")));

        ServiceProbe.Answer extend = probe.send("ru29", "?key ctrl-e", T);
        assertTrue(extend.ok() && extend.text().contains("Surface time extended by 40 s"), extend.text());
        ServiceProbe.Answer c = probe.send("ru29", "?key ctrl-c", T);
        assertTrue(c.ok() && c.text().contains("Mission stopped by the operator: GliderDOS"), c.text());
        ServiceProbe.Answer put = probe.send("ru29", "put c_dive_target_depth 30", T);
        assertTrue(put.ok() && put.text().contains("sensor:c_dive_target_depth=30"), put.text());
        probe.send("ru29", "GO", T);
        Eventually.await("hung up to dive", T, glider::submerged);
    }
}
