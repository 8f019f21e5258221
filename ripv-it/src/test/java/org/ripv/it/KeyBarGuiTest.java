package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import com.formdev.flatlaf.FlatLightLaf;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.prefs.Preferences;
import java.util.regex.Pattern;
import org.assertj.swing.core.BasicRobot;
import org.assertj.swing.core.Robot;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.gui.RIPVClient;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.testing.Tools;

/**
 * The console's key bar clicked under Xvfb ({@code -Dripv.gui.tests=true}): a real server, a
 * SerialPortServer on a socat pseudo-terminal, and behind it a vehicle that answers Ctrl-C with
 * its GliderDOS prompt ({@code zmodem-vehicle.sh}). alice's Ctrl-C brings the prompt into the
 * COM panel; bob, without the right to {@code ?key ctrl-c}, clicks the same button and is refused.
 */
class KeyBarGuiTest {
    static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
    static final String SERIAL = "<SerialPortServer>::<localhost>";

    @TempDir
    Path dir;
    TestSystem sys;
    SerialPortServer serial;
    final List<Process> started = new ArrayList<>();

    @AfterEach
    void stop() throws Exception {
        if (serial != null) {
            serial.stop();
        }
        for (Process p : started) {
            p.descendants().forEach(ProcessHandle::destroy);
            p.destroy();
            p.waitFor(10, TimeUnit.SECONDS);
        }
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void ctrlCFromTheKeyBarBringsThePromptAndIsRefusedWithoutTheRight() throws Exception {
        ClientGuiTest.requireDisplay();
        Tools.require("socat", "bash");
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators").user("bob", "observers");
        sys.rules("allow @operators * * *", "allow @observers * * ?read", "allow bob SerialPortServer * ?key ctrl-r");

        Path vehicle = Files.createDirectories(dir.resolve("vehicle"));
        Path pty = dir.resolve("ttyG");
        Path script = ROOT.resolve("ripv-services/src/test/resources/org/ripv/services/serial/zmodem-vehicle.sh");
        started.add(new ProcessBuilder("socat", "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec bash " + script + " "
                + vehicle + "'").directory(vehicle.toFile()).redirectErrorStream(true)
                .redirectOutput(dir.resolve("socat.log").toFile()).start());
        ClientGuiTest.waitFor("socat made " + pty, () -> Files.exists(pty));
        LinkSettings d = LinkSettings.defaults(pty.toString());
        LinkSettings link = new LinkSettings(pty.toString(), d.baud(), d.dataBits(), d.parity(), d.stopBits(), "\r",
                Pattern.compile("GliderDOS \\S+ # >"), Duration.ofSeconds(1), Duration.ofSeconds(30), d.carrier(),
                d.sendCommand(), d.receiveCommand(), Duration.ofMillis(200), YmodemConfig.lrzsz());
        serial = SerialPortServer.withCalls("localhost", List.of(new VehicleLink(link, CallSettings.defaults().withName("ru29"))), null, false, dir.resolve("work"));
        serial.start();
        sys.register(serial);

        String alice = clickCtrlC("alice", r -> r.contains("GliderDOS A # >"));
        assertThat(alice).contains("sent ctrl-c").contains("Control-C received").contains("GliderDOS A # >");
        String bob = clickCtrlC("bob", r -> r.contains("may not send"));
        assertThat(bob).contains("may not send '?key ctrl-c'").doesNotContain("Control-C received");
    }

    /** Logs {@code user} in in a window of its own, clicks the console's Ctrl-C, and returns the COM panel's reply text. */
    private String clickCtrlC(String user, java.util.function.Predicate<String> done) throws Exception {
        Preferences prefs = Preferences.userRoot().node("org/ripv/test/" + UUID.randomUUID());
        Robot robot = BasicRobot.robotWithNewAwtHierarchy();
        GuiManager gm = GuiActionRunner.execute(() -> new GuiManager(new ClientModel()));
        RIPVClient client = GuiActionRunner.execute(() -> {
            FlatLightLaf.setup();
            return new RIPVClient(gm, prefs);
        });
        FrameFixture window = new FrameFixture(robot, client.frame());
        try {
            window.show();
            gm.logIn("localhost", sys.server().port(), user, TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
            ClientGuiTest.waitFor("the serial tab", () -> client.panel(SERIAL) != null);
            ClientGuiTest.showTab(client, SERIAL);
            ServiceLayoutPanel tab = GuiActionRunner.execute(() -> client.panel(SERIAL));
            ClientGuiTest.waitFor("ru29 as the target", () -> gm.model().service(SERIAL).target().equals(SERIAL + "ru29"));
            window.button("key-ctrl-c").click();
            ClientGuiTest.waitFor("the reply to Ctrl-C in COM", () -> done.test(tab.com().replyText()));
            return GuiActionRunner.execute(() -> tab.com().replyText());
        } catch (Throwable t) {
            ClientGuiTest.screenshot("KeyBarGuiTest-" + user + "-failure.png");
            throw t;
        } finally {
            window.cleanUp();
            gm.close();
            prefs.removeNode();
        }
    }
}
