package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.simulator.GliderSimulator;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * A YMODEM get from the simulated glider behind a slow link (a relay at 256 KB/s), seen and stopped from the GUI's model: its COM
 * progress bar shows bytes, rate and time left from the service's PROGRESS replies, Cancel
 * sends {@code ?cancel}, the transfer ends CANCELLED, nothing of the file is stored, and the
 * vehicle answers the next command.
 */
@ResourceLock(Shared.DISPLAY)
class TransferCancelGuiTest {
    static final Duration T = Duration.ofSeconds(60);
    static final String SERIAL = "<SerialPortServer>::<localhost>";

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
    SlowLinkRelay relay;
    ClientGuiTest.UiThread ui;
    GuiManager manager;
    ClientModel model;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators");
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), ClientGuiTest.YMODEM);
        // 2 MB through a 256 KB/s link: about 8 s, so there is a middle to see and cancel in.
        byte[] big = new byte[2 * 1024 * 1024];
        new java.util.Random(7).nextBytes(big);
        Files.write(glider.directory().resolve("BIG.DAT"), big);
        relay = new SlowLinkRelay(glider.listen(0), 256 * 1024);
        LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + relay.port()).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(ClientGuiTest.YMODEM);
        sys.register(new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("serial-work")));
    }

    @AfterEach
    void stop() {
        if (manager != null) {
            manager.close();
        }
        if (ui != null) {
            ui.close();
        }
        sys.close();
        if (relay != null) {
            relay.close();
        }
        if (glider != null) {
            glider.close();
        }
    }

    private <V> V until(String what, java.util.concurrent.Callable<V> value, java.util.function.Predicate<V> ok) throws Exception {
        return ui.until(what, T, value, ok);
    }

    @Test
    void aGetShowsRateAndTimeLeftAndIsCancelledFromTheGui() throws Exception {
        ui = new ClientGuiTest.UiThread();
        model = new ClientModel();
        manager = new GuiManager(model, ui, ClientSocketHandler::connect,
                new GuiManager.Timings(Duration.ofSeconds(15), Duration.ofMillis(200), Duration.ofSeconds(1)));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
        until("the glider's mailbox as the target", () -> model.service(SERIAL) == null ? "" : model.service(SERIAL).target(),
                t -> !t.isEmpty());
        ui.run(() -> manager.sendCommand(SERIAL, "ymodem:get BIG.DAT"));
        // A progress report in the middle: bytes of the total, a rate, and the time left.
        ServiceModel.Running r = until("progress with a rate", () -> model.service(SERIAL).running(), l -> l.size() == 1
                && l.get(0).progress() != null && l.get(0).progress().done() > 0
                && l.get(0).progress().done() < l.get(0).progress().total()).get(0);
        String text = r.text(System.currentTimeMillis());
        assertThat(text).as(text).matches("ymodem:get BIG\\.DAT  [0-9.]+ [KM]B / 2\\.0 MB  [0-9.]+ [KM]?B/s  [0-9:]+ left");
        assertThat(ui.get(() -> model.service(SERIAL).serviceStatus())).matches("busy: ymodem:get BIG\\.DAT \\(\\d+%, ETA [0-9:]+\\)");
        boolean cancelling = ui.get(() -> {
            manager.cancel(SERIAL, r.messageId());
            return model.service(SERIAL).running().get(0).cancelling();
        });
        assertThat(cancelling).isTrue();
        until("the transfer gone from COM", () -> model.service(SERIAL).running(), List::isEmpty);
        String transcript = until("the cancelled line", () -> model.service(SERIAL).transcriptText(),
                s -> s.contains("-- cancelled 'ymodem:get BIG.DAT'"));
        assertThat(transcript).contains("alice");
        try (var stored = Files.walk(sys.downloadDir())) {
            assertThat(stored.map(p -> p.getFileName().toString())).as("nothing of the file is stored")
                    .noneMatch(n -> n.startsWith("BIG.DAT"));
        }
        // The line is back at the prompt: the vehicle answers the next command.
        ui.run(() -> manager.sendCommand(SERIAL, "dir"));
        until("dir answered after the cancel", () -> model.service(SERIAL).transcriptText(), s -> s.contains("SENSOR.DAT"));
    }

    @Test
    void windowShowsTheTransfersRateAndTimeLeftAndCancelsIt() throws Exception {
        ClientGuiTest.requireDisplay();
        java.util.prefs.Preferences prefs = java.util.prefs.Preferences.userRoot().node("org/ripv/test/" + java.util.UUID.randomUUID());
        org.assertj.swing.core.Robot robot = org.assertj.swing.core.BasicRobot.robotWithNewAwtHierarchy();
        GuiManager gm = org.assertj.swing.edt.GuiActionRunner.execute(() -> new GuiManager(new ClientModel()));
        org.ripv.client.gui.RIPVClient client = org.assertj.swing.edt.GuiActionRunner.execute(() -> {
            com.formdev.flatlaf.FlatLightLaf.setup();
            return new org.ripv.client.gui.RIPVClient(gm, prefs);
        });
        org.assertj.swing.fixture.FrameFixture window = new org.assertj.swing.fixture.FrameFixture(robot, client.frame());
        try {
            window.show();
            gm.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
            ClientGuiTest.waitFor("the serial tab", () -> client.panel(SERIAL) != null);
            ClientGuiTest.showTab(client, SERIAL);
            org.ripv.client.panels.ServiceLayoutPanel tab = org.assertj.swing.edt.GuiActionRunner.execute(() -> client.panel(SERIAL));
            ClientGuiTest.waitFor("the glider as the target", () -> !gm.model().service(SERIAL).target().isEmpty());
            ClientGuiTest.command(window, "ymodem:get BIG.DAT");
            ClientGuiTest.waitFor("rate and time left on the bar", () -> tab.com().runningTexts().stream()
                    .anyMatch(t -> t.matches("ymodem:get BIG\\.DAT  [0-9.]+ [KM]B / 2\\.0 MB  [0-9.]+ KB/s  0:0[2-9] left")));
            ClientGuiTest.screenshotOf(client, "client-transfer.png");
            long id = org.assertj.swing.edt.GuiActionRunner.execute(() -> gm.model().service(SERIAL).running().get(0).messageId());
            javax.swing.JButton cancel = window.button("cancel-" + id).target();
            ClientGuiTest.press(() -> window.button("cancel-" + id), () -> tab.com().runningTexts().isEmpty()
                    || cancel.getText().startsWith("Cancelling"));
            ClientGuiTest.waitFor("the get cancelled", () -> tab.com().runningTexts().isEmpty()
                    && tab.com().replyText().contains("-- cancelled 'ymodem:get BIG.DAT'"));
        } catch (Throwable t) {
            ClientGuiTest.screenshot("TransferCancelGuiTest-failure.png");
            throw t;
        } finally {
            window.cleanUp();
            gm.close();
            prefs.removeNode();
        }
    }
}
