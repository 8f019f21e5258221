package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import org.assertj.swing.edt.GuiActionRunner;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.services.serial.CallSettings;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.VehicleLink;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.testing.Tools;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The console's key bar clicked under Xvfb ({@code -Dripv.gui.tests=true}): a real server, a
 * SerialPortServer on a socat pseudo-terminal, and behind it a vehicle that answers Ctrl-C with
 * its GliderDOS prompt ({@code zmodem-vehicle.sh}). alice's Ctrl-C brings the prompt into the
 * COM panel; bob, without the right to {@code ?key ctrl-c}, clicks the same button and is refused.
 */
@ResourceLock(Shared.DISPLAY)
class KeyBarGuiTest {
    static final Path ROOT = LaunchedJars.ROOT;
    static final String SERIAL = "<SerialPortServer>::<localhost>";

    @TempDir
    Path dir;
    TestSystem sys;
    SerialPortServer serial;
    LaunchedJars processes;

    @AfterEach
    void stop() throws Exception {
        if (serial != null) {
            serial.stop();
        }
        if (processes != null) {
            processes.close();
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
        processes = new LaunchedJars(dir);
        processes.add(new ProcessBuilder("socat", "pty,raw,echo=0,link=" + pty, "SYSTEM:'exec bash " + script + " "
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
        try (ClientWindow w = ClientWindow.open()) {
            try {
                w.gm().logIn("localhost", sys.server().port(), user, TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
                ClientGuiTest.waitFor("the serial tab", () -> w.client().panel(SERIAL) != null);
                ClientGuiTest.showTab(w.client(), SERIAL);
                ServiceLayoutPanel tab = GuiActionRunner.execute(() -> w.client().panel(SERIAL));
                ClientGuiTest.waitFor("ru29 as the target", () -> w.gm().model().service(SERIAL).target().equals(SERIAL + "ru29"));
                // on a loaded machine the console's layout may come after the fixture's own lookup gives up
                ClientGuiTest.waitFor("the key bar showing", () -> showing(w.client().frame(), "key-ctrl-c"));
                // a robot click under Xvfb now and then lands beside a button just laid out: press() sees
                // whether ?key went out (the COM panel's Last Action) and falls back to doClick
                ClientGuiTest.press(() -> w.fixture().button("key-ctrl-c"),
                        () -> w.gm().model().service(SERIAL).lastAction().startsWith("?key "));
                ClientGuiTest.waitFor("the reply to Ctrl-C in COM", () -> done.test(tab.com().replyText()));
                return GuiActionRunner.execute(() -> tab.com().replyText());
            } catch (Throwable t) {
                ClientGuiTest.screenshot("KeyBarGuiTest-" + user + "-failure.png");
                throw t;
            }
        }
    }

    private static boolean showing(java.awt.Container in, String name) {
        for (java.awt.Component c : in.getComponents()) {
            if (name.equals(c.getName()) && c.isShowing()
                    || c instanceof java.awt.Container inner && showing(inner, name)) {
                return true;
            }
        }
        return false;
    }
}
