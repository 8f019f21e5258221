package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.Dimension;
import java.awt.GraphicsEnvironment;
import java.awt.Rectangle;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.function.BooleanSupplier;
import java.util.prefs.Preferences;
import org.assertj.swing.core.BasicRobot;
import org.assertj.swing.core.Robot;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.finder.JFileChooserFinder;
import org.assertj.swing.fixture.DialogFixture;
import org.assertj.swing.fixture.FrameFixture;
import org.assertj.swing.fixture.JFileChooserFixture;
import org.assertj.swing.timing.Condition;
import org.assertj.swing.timing.Pause;
import org.assertj.swing.timing.Timeout;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.gui.RIPVClient;
import org.ripv.client.gui.Theme;
import org.ripv.client.gui.WindowLayout;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;
import org.ripv.testing.Tools;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The reference scenario (SPEC §10) in the window with the keyboard only: log in with Enter, go
 * from tab to tab with Ctrl+PageDown, to the command line with Alt+2, upload with Alt+U and the
 * chooser's file name, recall with Up (per MailBox), switch to the dark theme with Alt+V D, and
 * the window's layout comes back in a new window. Needs a display: {@code -Dripv.gui.tests=true}
 * under Xvfb, as .ci/run does. With {@code -Dripv.screenshot.dir=DIR} it saves
 * {@code DIR/client-1280x800.png}, {@code client-1920x1080.png} (when the screen is that large)
 * and {@code client-dark.png}.
 */
@SuppressWarnings("deprecation") // AssertJ-Swing's robot takes the old InputEvent masks
@ResourceLock(Shared.DISPLAY)
class KeyboardScenarioGuiTest {
    static final Duration T = Duration.ofSeconds(30);
    static final String SERIAL = "<SerialPortServer>::<localhost>";
    static final String DATABASE = "<DatabaseServer>::<localhost>";
    static final String DATAVIS = "<DataVisServer>::<localhost>";
    static final String QUERY = "SELECT mission_id, name, startt, endt FROM mission ORDER BY startt DESC";
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;

    @BeforeEach
    void start() throws Exception {
        assumeTrue(Boolean.getBoolean("ripv.gui.tests"),
                "window tests run with -Dripv.gui.tests=true under a display (xvfb-run), as .ci/run does");
        assumeFalse(GraphicsEnvironment.isHeadless(), "window tests need java.awt.headless=false and a display");
        Tools.require("sb", "rb");
        sys = TestSystem.start(dir);
        sys.user("alice", "operators");
        sys.register(new ClockService("localhost"));
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), YMODEM);
        int port = glider.listen(0);
        LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(YMODEM);
        sys.register(new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("serial-work")));
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                new QueryLimits(1000, 30, QueryLimits.DEFAULT_MAX_RESULT_CHARS)));
        sys.register(new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))));
    }

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
    }

    static void waitFor(String what, BooleanSupplier check) {
        Pause.pause(new Condition(what) {
            @Override
            public boolean test() {
                return GuiActionRunner.execute(check::getAsBoolean);
            }
        }, Timeout.timeout(T.toMillis()));
    }

    /** Ctrl+PageDown until the service's tab is in front. */
    static void tabTo(FrameFixture window, RIPVClient client, String service) {
        for (int i = 0; i < 6 && !GuiActionRunner.execute(() -> client.panel(service).isShowing()); i++) {
            window.robot().pressAndReleaseKey(KeyEvent.VK_PAGE_DOWN, InputEvent.CTRL_MASK);
            window.robot().waitForIdle();
        }
        waitFor(service + "'s tab in front", () -> client.panel(service).isShowing());
        window.robot().pressAndReleaseKey(KeyEvent.VK_2, InputEvent.ALT_MASK); // to the command line
        window.robot().waitForIdle();
    }

    /** Types a line into the focused command line and presses Enter. */
    static void type(Robot robot, String line) {
        robot.enterText(line);
        robot.pressAndReleaseKey(KeyEvent.VK_ENTER);
        robot.waitForIdle();
    }

    @Test
    void theReferenceScenarioByKeyboard() throws Exception {
        Preferences prefs = Preferences.userRoot().node("org/ripv/test/" + UUID.randomUUID());
        Robot robot = BasicRobot.robotWithNewAwtHierarchy();
        GuiManager gm = GuiActionRunner.execute(() -> new GuiManager(new ClientModel()));
        RIPVClient client = GuiActionRunner.execute(() -> {
            Theme.saved(prefs).install();
            return new RIPVClient(gm, prefs);
        });
        FrameFixture window = new FrameFixture(robot, client.frame());
        Path binary = dir.resolve("GLIDER.BIN");
        Files.write(binary, new byte[20_000]);
        Path sample = Path.of("..", "docs", "samples", "glider-temperature.dat").toAbsolutePath().normalize();
        try {
            window.show(new Dimension(1280, 800));
            GuiActionRunner.execute(() -> client.showLogin("localhost:" + sys.server().port(), "alice", null, false));
            DialogFixture login = window.dialog("loginDialog");
            login.textBox("passwordField").focus();
            robot.enterText(TestSystem.PASSWORD);
            robot.pressAndReleaseKey(KeyEvent.VK_ENTER);
            waitFor("the dialog to close after logging in", () -> !login.target().isShowing());
            waitFor("all four services as tabs", () -> client.tabs().getTabCount() == 4);
            // Xvfb has no window manager to hand the focus back after the modal dialog: give it to the command line.
            GuiActionRunner.execute(() -> client.frame().toFront());
            window.textBox("commandField").click();
            robot.waitForIdle();

            ServiceLayoutPanel serial = GuiActionRunner.execute(() -> client.panel(SERIAL));
            ServiceLayoutPanel db = GuiActionRunner.execute(() -> client.panel(DATABASE));
            ServiceLayoutPanel vis = GuiActionRunner.execute(() -> client.panel(DATAVIS));

            tabTo(window, client, SERIAL);
            waitFor("the glider as TT", () -> gm.model().service(SERIAL).target().startsWith(SERIAL + "tcp-"));
            // Upload both files with Alt+U and the chooser's file name field.
            for (Path f : List.of(binary, sample)) {
                window.robot().pressAndReleaseKey(KeyEvent.VK_U, InputEvent.ALT_MASK);
                JFileChooserFixture chooser = JFileChooserFinder.findFileChooser().withTimeout(T.toMillis()).using(robot);
                chooser.fileNameTextBox().focus();
                robot.enterText(f.toString());
                robot.pressAndReleaseKey(KeyEvent.VK_ENTER);
                waitFor(f.getFileName() + " under UL", () -> serial.fim().tree().names(FileArea.UPLOAD)
                        .contains(f.getFileName().toString()));
                // Xvfb has no window manager to give the focus back after the modal chooser: take it.
                window.textBox("commandField").click();
            }
            type(robot, "?ulfiles");
            waitFor("the upload listing", () -> serial.com().replyText().contains("glider-temperature.dat"));
            type(robot, "dir");
            waitFor("the glider's dir", () -> serial.com().replyText().contains("MISSION1.LOG"));
            type(robot, "ymodem:get MISSION1.LOG");
            waitFor("the offloaded log under DL", () -> serial.fim().tree().names(FileArea.DOWNLOAD).stream()
                    .anyMatch(n -> n.endsWith("MISSION1.LOG"))); // HANDLE/NAME: each MailBox's folder

            tabTo(window, client, DATABASE);
            waitFor("the database as TT", () -> gm.model().service(DATABASE).target().startsWith(DATABASE));
            type(robot, QUERY);
            waitFor("a DAB tab with the query's rows", () -> db.dab().tabs().getTabCount() == 1
                    && db.dab().selectedTable().getRowCount() > 0);

            tabTo(window, client, DATAVIS);
            waitFor("the plotter as TT", () -> gm.model().service(DATAVIS).target().startsWith(DATAVIS));
            type(robot, "vis:glider-temperature.dat");
            waitFor("the plot in DAV", () -> vis.dav().image() != null);
            waitFor("the plot under DL", () -> vis.fim().tree().names(FileArea.DOWNLOAD).stream()
                    .anyMatch(n -> n.endsWith("glider-temperature.jpg")));
            waitFor("the progress bar gone", () -> gm.model().service(DATAVIS).progress() == null);

            tabTo(window, client, SERIAL);
            type(robot, "ymodem:put GLIDER.BIN");
            waitFor("the binary sent", () -> serial.com().replyText().contains("sent GLIDER.BIN"));
            type(robot, "GO");
            waitFor("the glider submerging", () -> serial.com().replyText().contains("submerging"));
            waitFor("SS to say the glider is not available",
                    () -> gm.model().service(SERIAL).serviceStatus().startsWith("not available"));
            // Up recalls this MailBox's last command.
            robot.pressAndReleaseKey(KeyEvent.VK_UP);
            waitFor("Up to recall GO", () -> "GO".equals(textOfFocusedCommandLine(client, SERIAL)));
            robot.pressAndReleaseKey(KeyEvent.VK_ESCAPE);
            GuiActionRunner.execute(() -> serial.com().clearCommand());

            shoot(client, robot, 1280, 800, "client-1280x800.png");
            shoot(client, robot, 1920, 1080, "client-1920x1080.png");

            // The dark theme from the View menu, by keyboard; remembered.
            window.robot().pressAndReleaseKey(KeyEvent.VK_V, InputEvent.ALT_MASK);
            robot.pressAndReleaseKey(KeyEvent.VK_D);
            robot.waitForIdle();
            waitFor("the dark theme", Theme.DARK::installed);
            assertThat(Theme.saved(prefs)).isEqualTo(Theme.DARK);
            GuiActionRunner.execute(() -> serial.com().clearCommand()); // the menu's D can reach the field too
            shoot(client, robot, 1280, 800, "client-dark.png");

            // The layout is remembered: a new window opens where this one was.
            GuiActionRunner.execute(() -> client.frame().setBounds(new Rectangle(10, 20, 1200, 760)));
            robot.waitForIdle();
            GuiActionRunner.execute(client::saveLayout);
            WindowLayout saved = WindowLayout.load(prefs);
            assertThat(saved.bounds()).isEqualTo(new Rectangle(10, 20, 1200, 760));
            RIPVClient again = GuiActionRunner.execute(() -> new RIPVClient(new GuiManager(new ClientModel()), prefs));
            assertThat(GuiActionRunner.execute(() -> again.frame().getBounds())).isEqualTo(new Rectangle(10, 20, 1200, 760));
            GuiActionRunner.execute(() -> again.frame().dispose());
        } catch (Throwable t) {
            try {
                java.awt.Rectangle screen = new java.awt.Rectangle(java.awt.Toolkit.getDefaultToolkit().getScreenSize());
                javax.imageio.ImageIO.write(new java.awt.Robot().createScreenCapture(screen), "png",
                        Path.of("target", "KeyboardScenarioGuiTest-failure.png").toFile());
            } catch (Exception | Error e) {
                t.addSuppressed(e);
            }
            throw t;
        } finally {
            GuiActionRunner.execute(() -> Theme.LIGHT.install());
            window.cleanUp();
            prefs.removeNode();
        }
    }

    static String textOfFocusedCommandLine(RIPVClient client, String service) {
        return client.panel(service).com().commandText();
    }

    /** With -Dripv.screenshot.dir, the window at that size (when the screen is large enough). */
    static void shoot(RIPVClient client, Robot robot, int w, int h, String name) throws Exception {
        String target = System.getProperty("ripv.screenshot.dir");
        if (target == null || target.isBlank()) {
            return;
        }
        Dimension screen = java.awt.Toolkit.getDefaultToolkit().getScreenSize();
        if (screen.width < w || screen.height < h) {
            System.err.println("no " + name + ": the screen is " + screen.width + "x" + screen.height);
            return;
        }
        GuiActionRunner.execute(() -> client.frame().setBounds(0, 0, w, h));
        robot.waitForIdle();
        java.awt.Robot awt = new java.awt.Robot();
        awt.mouseMove(w + 5 < screen.width ? w + 5 : 0, h + 5 < screen.height ? h + 5 : 0);
        Thread.sleep(1500); // let layout and any tooltip settle; a picture, not a test, waits here
        Files.createDirectories(Path.of(target));
        javax.imageio.ImageIO.write(awt.createScreenCapture(new Rectangle(0, 0, w, h)), "png", Path.of(target, name).toFile());
    }
}
