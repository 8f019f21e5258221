package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import com.formdev.flatlaf.FlatLightLaf;
import java.nio.file.Path;
import java.time.Duration;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.prefs.Preferences;
import org.assertj.swing.core.BasicRobot;
import org.assertj.swing.core.Robot;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.gui.RIPVClient;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.ConsolePanel;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The client's live console against a real server and a vehicle service publishing over RMI:
 * the model headless (always), and the window under Xvfb ({@code -Dripv.gui.tests=true}) with a
 * screenshot for docs/images ({@code -Dripv.screenshot.dir=docs/images}).
 */
@ResourceLock(Shared.DISPLAY)
class ConsoleGuiTest {
    static final Duration T = Duration.ofSeconds(20);
    static final String SERVICE = "<VehicleConsole>::<localhost>";

    @TempDir
    Path dir;
    TestSystem sys;
    VehicleConsoleService vehicle;
    ClientGuiTest.UiThread ui;
    GuiManager manager;
    ClientModel model;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators");
        vehicle = new VehicleConsoleService("localhost", "ru29");
        sys.register(vehicle);
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
    }

    private <V> V until(String what, java.util.concurrent.Callable<V> value, java.util.function.Predicate<V> ok) throws Exception {
        return ui.until(what, T, value, ok);
    }

    @Test
    void theModelWatchesThePickedMailboxAndNotifiesOnSurfacing() throws Exception {
        for (int i = 0; i < 30; i++) {
            vehicle.line("old " + i);
        }
        vehicle.line("printed before the client came");
        ui = new ClientGuiTest.UiThread();
        model = new ClientModel();
        manager = new GuiManager(model, ui, ClientSocketHandler::connect,
                new GuiManager.Timings(Duration.ofSeconds(15), Duration.ofMillis(200), Duration.ofSeconds(1)));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
        String box = vehicle.mailbox();
        until("the vehicle's mailbox as the target", () -> model.service(SERVICE) == null ? "" : model.service(SERVICE).target(),
                box::equals);
        until("the replay", () -> model.console().entries(box), l -> !l.isEmpty());
        assertThat(ui.get(() -> model.console().entries(box))).hasSize(20).last()
                .extracting(ConsoleEntry::text).isEqualTo("printed before the client came");
        // Scrolling back: the transcript fills in what came before the replay, once and in order.
        manager.loadHistory(box);
        until("the older lines", () -> model.console().entries(box).size(), n -> n == 31);
        manager.loadHistory(box);
        assertThat(ui.get(() -> model.console().entries(box).stream().map(ConsoleEntry::text).toList()))
                .startsWith("old 0", "old 1").hasSize(31).doesNotHaveDuplicates();
        vehicle.event(VehicleEvent.SURFACED, "Glider ru29 at surface", 41.63323, -70.53647);
        vehicle.line("unsolicited: battery 14.2 V");
        until("the live lines", () -> model.console().entries(box).stream().map(ConsoleEntry::text).toList(),
                l -> l.contains("unsolicited: battery 14.2 V"));
        // Without a system tray (headless), the notification shows in the window's status bar.
        until("the desktop notice", () -> model.notice(), n -> n.contains("ru29 SURFACED"));
        assertThat(sys.server().console().watcherCount()).isEqualTo(1);
        manager.close();
        manager = null;
        long end = System.nanoTime() + T.toNanos();
        while (sys.server().console().watcherCount() > 0 && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertThat(sys.server().console().watcherCount()).isZero();
    }

    @Test
    void theModelWatchesAgainAfterReconnecting() throws Exception {
        ui = new ClientGuiTest.UiThread();
        model = new ClientModel();
        manager = new GuiManager(model, ui, ClientSocketHandler::connect,
                new GuiManager.Timings(Duration.ofMillis(500), Duration.ofMillis(200), Duration.ofSeconds(1)));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
        String box = vehicle.mailbox();
        until("the vehicle's mailbox as the target", () -> model.service(SERVICE) == null ? "" : model.service(SERVICE).target(),
                box::equals);
        until("the watch", () -> sys.server().console().watcherCount(), n -> n == 1);
        int port = sys.server().port();
        int registry = sys.server().registryPort();
        sys.server().stop();
        try (org.ripv.server.RIPVServer again = new org.ripv.server.RIPVServer(
                org.ripv.server.ServerConfig.forTests(sys.dataDir()).withPorts(port, registry, -1))) {
            again.start();
            until("watching again on the new server", () -> again.console().watcherCount(), n -> n == 1);
            until("the vehicle registered again", () -> again.serviceCount(), n -> n == 1);
            vehicle.line("after the restart");
            until("the line after the restart", () -> model.console().entries(box).stream().map(ConsoleEntry::text).toList(),
                    l -> l.contains("after the restart"));
            manager.close();
            manager = null;
        }
    }

    @Test
    void windowShowsTheLiveConsoleAndTheStateBadge() throws Exception {
        ClientGuiTest.requireDisplay();
        vehicle.event(VehicleEvent.SURFACED, "Glider ru29 at surface", 41.63323, -70.53647);
        vehicle.line("GPS Location: 4137.994 N -7032.188 E measured 26.0 secs ago");
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
            gm.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
            ClientGuiTest.waitFor("the vehicle's tab", () -> client.panel(SERVICE) != null);
            ClientGuiTest.showTab(client, SERVICE);
            ServiceLayoutPanel tab = GuiActionRunner.execute(() -> client.panel(SERVICE));
            ConsolePanel console = tab.console();
            assertThat(console).isNotNull();
            ClientGuiTest.waitFor("the replay in the console", () -> console.consoleText().contains("GPS Location"));
            for (int i = 1; i <= 8; i++) {
                vehicle.line("sensor: m_battery(volts) = 14." + i + "   (unsolicited)");
            }
            vehicle.publishEntry(ConsoleEntry.command(vehicle.mailbox(), "bob", "report ++ m_battery"));
            vehicle.event(VehicleEvent.ALERT, "LEAK detected in aft hull", null, null);
            ClientGuiTest.waitFor("unsolicited lines in the console", () -> console.consoleText().contains("LEAK detected"));
            ClientGuiTest.waitFor("the state badge", () -> console.badgeText().contains("on call"));
            assertThat(console.consoleText()).contains("[bob] > report ++ m_battery", "* SURFACED Glider ru29 at surface (41.63323, -70.53647)");
            window.textBox("consoleSearch").setText("battery");
            ClientGuiTest.waitFor("only the lines with 'battery'", () -> !console.consoleText().contains("LEAK"));
            assertThat(console.consoleText().lines()).hasSize(9).allMatch(l -> l.contains("battery"));
            window.textBox("consoleSearch").setText("");
            ClientGuiTest.waitFor("the badge in the MAM tree", () -> {
                javax.swing.tree.TreeModel tm = tab.mam().tree().getModel();
                Object root = tm.getRoot();
                return tm.getChildCount(root) == 1
                        && tm.getChild(root, 0).toString().matches("ru29 +● on call · last contact (just now|1 min ago)");
            });
            ClientGuiTest.screenshotOf(client, "client-console.png");
        } catch (Throwable t) {
            ClientGuiTest.screenshot("ConsoleGuiTest-failure.png");
            throw t;
        } finally {
            window.cleanUp();
            gm.close();
            prefs.removeNode();
        }
    }

    /**
     * Issue 25: the window opens on the vehicle, not on the service listed first (here a
     * ClockService, which sorts before it), and its SS line and its badge say the same state as
     * the vehicle dives and calls again.
     */
    @Test
    void windowOpensOnTheFirstVehicleAndItsStatusLineAgreesWithTheBadge() throws Exception {
        ClientGuiTest.requireDisplay();
        sys.register(new org.ripv.examples.ClockService("localhost"));
        vehicle.event(VehicleEvent.SURFACED, "Glider ru29 at surface", 41.63323, -70.53647);
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
            gm.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray()).get(20, TimeUnit.SECONDS);
            ClientGuiTest.waitFor("both tabs", () -> client.panel(SERVICE) != null && client.panel("<ClockService>::<localhost>") != null);
            assertThat(GuiActionRunner.execute(() -> client.tabs().getTitleAt(0))).as("the clock is listed first").startsWith("ClockService");
            ClientGuiTest.waitFor("the vehicle's tab in front", () -> GuiActionRunner.execute(
                    () -> client.tabs().getSelectedComponent() == client.panel(SERVICE)));
            ServiceLayoutPanel tab = GuiActionRunner.execute(() -> client.panel(SERVICE));
            assertThat(GuiActionRunner.execute(() -> gm.model().service(SERVICE).target())).isEqualTo(vehicle.mailbox());
            ClientGuiTest.waitFor("SS and the badge: on call", () -> GuiActionRunner.execute(
                    () -> tab.com().serviceStatusText().equals("available (on call, 1 call this run)")
                            && tab.console().badgeText().contains("on call")));
            vehicle.event(VehicleEvent.DIVED, "the caller hung up", null, null);
            ClientGuiTest.waitFor("SS and the badge: dived, together", () -> GuiActionRunner.execute(
                    () -> tab.com().serviceStatusText().equals("not available (dived, 1 call this run)")
                            && tab.console().badgeText().contains("dived")));
            vehicle.event(VehicleEvent.SURFACED, "Glider ru29 at surface", 41.63323, -70.53647);
            ClientGuiTest.waitFor("SS and the badge: on call again, the second call", () -> GuiActionRunner.execute(
                    () -> tab.com().serviceStatusText().equals("available (on call, 2 calls this run)")
                            && tab.console().badgeText().contains("on call")));
        } catch (Throwable t) {
            ClientGuiTest.screenshot("ConsoleGuiTest-opening-failure.png");
            throw t;
        } finally {
            window.cleanUp();
            gm.close();
            prefs.removeNode();
        }
    }
}
