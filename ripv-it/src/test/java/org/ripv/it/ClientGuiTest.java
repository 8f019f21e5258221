package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.junit.jupiter.api.Assumptions.assumeFalse;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import com.formdev.flatlaf.FlatLightLaf;
import java.awt.GraphicsEnvironment;
import java.awt.event.KeyEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
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
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ClientModel.Connection;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.client.managers.Transfer;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.examples.ClockService;
import org.ripv.messages.FileListing;
import org.ripv.messages.SessionInfo;
import org.ripv.server.RIPVServer;
import org.ripv.server.ServerConfig;
import org.ripv.service.ServiceConnector;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.datavis.DataVisServer;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.serial.ymodem.YmodemConfig;
import org.ripv.services.simulator.GliderSimulator;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The RIPVClient against a real RIPVServer with the example ClockService registered over RMI.
 *
 * <p>The {@code manager...} tests drive the {@link GuiManager} and its model headless, as the
 * window does, and always run. The {@code window...} tests open the Swing window and drive it
 * with AssertJ-Swing; they need a display and run with {@code -Dripv.gui.tests=true} under Xvfb
 * (and {@code java.awt.headless=false} in the test JVM), as {@code .ci/run} does.
 */
@ResourceLock(Shared.DISPLAY)
class ClientGuiTest {
    static final Duration T = Duration.ofSeconds(20);
    static final String CLOCK = "<ClockService>::<localhost>";
    static final String CLOCK_BOX = CLOCK + "TTY1";

    static final String SERIAL = "<SerialPortServer>::<localhost>";
    static final String DATABASE = "<DatabaseServer>::<localhost>";
    static final String DATAVIS = "<DataVisServer>::<localhost>";
    static final YmodemConfig YMODEM = YmodemConfig.lrzsz().withTimeouts(Duration.ofSeconds(10),
            Duration.ofSeconds(1), Duration.ofSeconds(2), Duration.ofSeconds(1));
    static final String QUERY = "SELECT mission_id, name, startt, endt FROM mission ORDER BY startt DESC";

    @TempDir
    Path dir;
    TestSystem sys;
    UiThread ui;
    ClientModel model;
    GuiManager manager;
    GliderSimulator glider;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators");
        sys.register(new ClockService("localhost"));
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
        if (glider != null) {
            glider.close();
        }
    }

    /** The three services of the reference scenario, on their embedded defaults, plus a simulated glider on TCP. */
    void startTheThreeServices() throws Exception {
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), YMODEM);
        int port = glider.listen(0);
        LinkSettings link = LinkSettings.defaults("tcp://127.0.0.1:" + port).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(YMODEM);
        sys.register(new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("serial-work")));
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                new QueryLimits(1000, 30, QueryLimits.DEFAULT_MAX_RESULT_CHARS)));
        sys.register(new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))));
    }

    static Path sample() {
        Path p = Path.of("..", "docs", "samples", "glider-temperature.dat");
        assertThat(p).as("the demo's sample data file").exists();
        return p.toAbsolutePath().normalize();
    }

    // ---------------------------------------------------------------- headless: the manager and model

    /** The Swing event thread's stand-in: one thread owns the model. */
    static final class UiThread implements Executor, AutoCloseable {
        final ExecutorService thread = Executors.newSingleThreadExecutor(r -> new Thread(r, "test-ui"));

        @Override
        public void execute(Runnable r) {
            thread.execute(r);
        }

        <V> V get(Callable<V> c) throws Exception {
            try {
                return thread.submit(c).get(T.toMillis(), TimeUnit.MILLISECONDS);
            } catch (ExecutionException e) {
                throw (Exception) e.getCause();
            }
        }

        void run(Runnable r) throws Exception {
            get(() -> {
                r.run();
                return null;
            });
        }

        /** Reads {@code value} on this thread until {@code ok} holds; fails naming {@code what} and the last value. */
        <V> V until(String what, Duration timeout, Callable<V> value, java.util.function.Predicate<V> ok) throws Exception {
            long end = System.nanoTime() + timeout.toNanos();
            V v = get(value);
            while (!ok.test(v)) {
                if (System.nanoTime() > end) {
                    throw new AssertionError("timed out waiting for " + what + "; last value: " + v);
                }
                Thread.sleep(20);
                v = get(value);
            }
            return v;
        }

        @Override
        public void close() {
            thread.shutdownNow();
        }
    }

    GuiManager newManager(Duration refresh) {
        ui = new UiThread();
        model = new ClientModel();
        manager = new GuiManager(model, ui, ClientSocketHandler::connect,
                new GuiManager.Timings(refresh, Duration.ofMillis(200), Duration.ofSeconds(1)));
        return manager;
    }

    /** Waits, without polling on a timer, until the model satisfies the condition: re-checks after every change. */
    <V> V await(String what, Supplier<V> value, java.util.function.Predicate<V> ok) throws Exception {
        LinkedBlockingQueue<Object> changes = new LinkedBlockingQueue<>();
        ClientModel.Listener l = changes::add;
        ui.run(() -> model.addListener(l));
        long deadline = System.nanoTime() + T.toNanos();
        try {
            while (true) {
                V v = ui.get(value::get);
                if (ok.test(v)) {
                    return v;
                }
                long left = deadline - System.nanoTime();
                if (left <= 0 || changes.poll(left, TimeUnit.NANOSECONDS) == null) {
                    throw new AssertionError("timed out waiting for " + what + "; last value: " + v);
                }
            }
        } finally {
            ui.run(() -> model.removeListener(l));
        }
    }

    @Test
    void managerLogsInSeesTheServicesAndGetsTheClocksReply() throws Exception {
        newManager(Duration.ofSeconds(15));
        SessionInfo s = manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS);
        assertThat(s.user()).isEqualTo("alice");
        await("the clock in the service list", () -> model.serviceNames(), n -> n.contains(CLOCK));
        await("the clock's mailbox as the target", () -> model.service(CLOCK).target(), CLOCK_BOX::equals);
        await("the SS label", () -> model.service(CLOCK).serviceStatus(), ss -> ss.startsWith("available"));
        await("the FileTree's directories", () -> model.directory(FileArea.DOWNLOAD).path(),
                p -> p.equals(sys.downloadDir().toString()));

        ui.run(() -> manager.sendCommand(CLOCK, "echo hello glider"));
        await("the echo in the reply area", () -> model.service(CLOCK).transcriptText(), t -> t.contains("\nhello glider\n"));
        assertThat(ui.get(() -> model.service(CLOCK).lastAction())).isEqualTo("echo hello glider");

        ui.run(() -> manager.sendCommand(CLOCK, "fly"));
        await("the clock's error in the reply area", () -> model.service(CLOCK).transcript(),
                t -> t.stream().anyMatch(l -> l.kind() == ServiceModel.LineKind.ERROR && l.text().contains("not 'fly'")));

        ui.run(() -> manager.sendCommand(CLOCK, "?whoami"));
        await("?whoami typed in COM is answered there", () -> model.service(CLOCK).transcriptText(),
                t -> t.contains("alice on client"));
    }

    @Test
    void managerReportsAWrongPasswordWithTheServersMessage() throws Exception {
        newManager(Duration.ofSeconds(15));
        assertThatThrownBy(() -> manager.logIn("localhost", sys.server().port(), "alice", "wrong".toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS))
                .hasCauseInstanceOf(RipvErrorException.class);
        Connection c = await("disconnected", () -> model.connection(), x -> x == Connection.DISCONNECTED);
        assertThat(c).isEqualTo(Connection.DISCONNECTED);
        assertThat(ui.get(() -> model.connectionDetail())).isNotBlank();
        assertThat(manager.connection()).isNull();
    }

    @Test
    void managerUploadsWithProgressAndSeesTheFileInTheTree() throws Exception {
        newManager(Duration.ofSeconds(15));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS);
        Path local = dir.resolve("glider.bin");
        byte[] data = new byte[ClientSocketHandler.CHUNK * 2 + 100];
        new java.util.Random(7).nextBytes(data);
        Files.write(local, data);
        Transfer t = ui.get(() -> manager.upload(local));
        await("the upload to finish", () -> t.state(), st -> st != Transfer.State.RUNNING);
        assertThat(ui.get(t::state)).as(ui.get(t::detail)).isEqualTo(Transfer.State.DONE);
        assertThat(ui.get(t::done)).isEqualTo(data.length);
        assertThat(Files.readAllBytes(sys.uploadDir().resolve("glider.bin"))).isEqualTo(data);
        await("glider.bin under UL", () -> model.directory(FileArea.UPLOAD).files().stream()
                .map(FileListing.Entry::name).toList(), n -> n.contains("glider.bin"));

        // Download: put a file where services leave theirs, then fetch it.
        Files.write(sys.downloadDir().resolve("mission.log"), data);
        Path into = Files.createDirectories(dir.resolve("mine"));
        Transfer d = ui.get(() -> manager.download("mission.log", into));
        await("the download to finish", () -> d.state(), st -> st != Transfer.State.RUNNING);
        assertThat(Files.readAllBytes(into.resolve("mission.log"))).isEqualTo(data);

        Transfer bad = ui.get(() -> manager.download("no-such-file", into));
        await("the failed download", () -> bad.state(), st -> st == Transfer.State.FAILED);
        assertThat(ui.get(bad::detail)).contains("no-such-file");
        try (var files = Files.list(into)) {
            assertThat(files.map(p -> p.getFileName().toString()).toList()).containsExactly("mission.log");
        }
    }

    @Test
    void cancelledTransfersLeaveNothingBehind() throws Exception {
        newManager(Duration.ofSeconds(15));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS);
        byte[] data = new byte[ClientSocketHandler.CHUNK * 8];
        Path local = dir.resolve("big.bin");
        Files.write(local, data);
        // Cancelled before the first chunk is acknowledged: the transfer stops after it.
        Transfer up = ui.get(() -> {
            Transfer t = manager.upload(local);
            t.cancel();
            return t;
        });
        await("the upload to stop", () -> up.state(), st -> st != Transfer.State.RUNNING);
        assertThat(ui.get(up::state)).as(ui.get(up::detail)).isEqualTo(Transfer.State.CANCELLED);
        assertThat(ui.get(up::done)).isLessThan(data.length);
        assertThat(sys.uploadDir().resolve("big.bin")).doesNotExist();

        Files.write(sys.downloadDir().resolve("big.log"), data);
        Path into = Files.createDirectories(dir.resolve("into"));
        Transfer down = ui.get(() -> {
            Transfer t = manager.download("big.log", into);
            t.cancel();
            return t;
        });
        await("the download to stop", () -> down.state(), st -> st != Transfer.State.RUNNING);
        assertThat(ui.get(down::state)).isEqualTo(Transfer.State.CANCELLED);
        try (var files = Files.list(into)) {
            assertThat(files.toList()).as("no partial file").isEmpty();
        }
    }

    @Test
    void managerFollowsServicesThatAppearAndVanish() throws Exception {
        newManager(Duration.ofMillis(300));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS);
        await("the clock", () -> model.serviceNames(), n -> n.equals(List.of(CLOCK)));
        ClockService other = new ClockService("otherhost");
        ServiceConnector c = sys.register(other);
        await("the second clock to appear", () -> model.serviceNames(), n -> n.contains("<ClockService>::<otherhost>"));
        c.close();
        other.stop();
        await("the second clock to vanish", () -> model.serviceNames(), n -> n.equals(List.of(CLOCK)));
    }

    @Test
    void managerReconnectsAndLogsInAgainWhenTheServerComesBack() throws Exception {
        newManager(Duration.ofMillis(500));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS);
        await("connected", () -> model.connection(), c -> c == Connection.CONNECTED);
        int port = sys.server().port();
        int registry = sys.server().registryPort();
        sys.server().stop();
        await("the lost connection to show", () -> model.connection(), c -> c == Connection.LOST);
        assertThat(ui.get(() -> model.connectionDetail())).contains("lost the connection");

        try (RIPVServer again = new RIPVServer(ServerConfig.forTests(sys.dataDir()).withPorts(port, registry, -1))) {
            again.start();
            await("reconnected", () -> model.connection(), c -> c == Connection.CONNECTED);
            assertThat(ui.get(() -> model.session().user())).isEqualTo("alice");
            // The client's list may still show the clock from before the restart: wait for the
            // new server to have it, so the command below does not race its registration.
            long until = System.nanoTime() + T.toNanos();
            while (again.serviceCount() == 0 && System.nanoTime() < until) {
                Thread.sleep(50);
            }
            assertThat(again.serviceCount()).as("the clock registered with the restarted server").isEqualTo(1);
            ui.run(() -> manager.refreshServices());
            await("the clock registered again and listed", () -> model.serviceNames(), n -> n.contains(CLOCK));
            await("the clock's mailbox as the target again", () -> model.service(CLOCK) == null ? ""
                    : model.service(CLOCK).target(), CLOCK_BOX::equals);
            ui.run(() -> manager.sendCommand(CLOCK, "echo still here"));
            // the periodic refresh may replace the service list while we wait: read it null-safe
            await("a reply over the new connection", () -> model.service(CLOCK) == null ? ""
                    : model.service(CLOCK).transcriptText(),
                    t -> t.contains("\nstill here\n"));
            manager.close();
        }
    }

    @Test
    void managerRunsTheReferenceScenarioIntoEveryPanel() throws Exception {
        startTheThreeServices();
        newManager(Duration.ofSeconds(15));
        manager.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray())
                .get(T.toMillis(), TimeUnit.MILLISECONDS);
        await("the three services", () -> model.serviceNames(),
                n -> n.containsAll(List.of(SERIAL, DATABASE, DATAVIS, CLOCK)));
        await("the glider as the serial target", () -> model.service(SERIAL).target(), t -> t.startsWith(SERIAL + "tcp-"));
        await("the database target", () -> model.service(DATABASE).target(), t -> t.startsWith(DATABASE));
        await("the plotter target", () -> model.service(DATAVIS).target(), t -> t.startsWith(DATAVIS));

        // Upload a new binary and the data file; both show under UL.
        Path binary = dir.resolve("GLIDER.BIN");
        Files.write(binary, new byte[20_000]);
        ui.run(() -> {
            manager.upload(binary);
            manager.upload(sample());
        });
        await("both uploads in the FileTree", () -> model.directory(FileArea.UPLOAD).files().stream()
                .map(FileListing.Entry::name).toList(), n -> n.containsAll(List.of("GLIDER.BIN", "glider-temperature.dat")));

        // The glider: dir, then offload a log with YMODEM (progress, then the stored file under DL).
        ui.run(() -> manager.sendCommand(SERIAL, "dir"));
        await("the glider's listing", () -> model.service(SERIAL).transcriptText(), t -> t.contains("MISSION1.LOG"));
        ui.run(() -> manager.sendCommand(SERIAL, "ymodem:get MISSION1.LOG"));
        await("the offloaded log under DL", () -> model.directory(FileArea.DOWNLOAD).files().stream()
                .map(FileListing.Entry::name).toList(), n -> n.stream().anyMatch(x -> x.endsWith("/MISSION1.LOG")));
        assertThat(ui.get(() -> model.service(SERIAL).progress())).as("progress cleared at the end").isNull();

        // The database: a query opens a table in DAB.
        ui.run(() -> manager.sendCommand(DATABASE, QUERY));
        TableResultView table = await("the query's table", () -> model.service(DATABASE).tables().isEmpty() ? null
                : new TableResultView(model.service(DATABASE).tables().get(0).query(),
                model.service(DATABASE).tables().get(0).rows().size()), v -> v != null);
        assertThat(table.query()).isEqualTo(QUERY);
        assertThat(table.rows()).isPositive();

        // The plotter: vis: of the uploaded file shows a JPEG in DAV.
        ui.run(() -> manager.sendCommand(DATAVIS, "vis:glider-temperature.dat"));
        ServiceModel.Picture pic = await("the plot", () -> model.service(DATAVIS).picture(), p -> p != null);
        assertThat(pic.image()).as("the JPEG decodes").isNotNull();
        assertThat(pic.image().getWidth()).isGreaterThan(100);

        // The new binary goes to the glider; then GO.
        ui.run(() -> manager.sendCommand(SERIAL, "ymodem:put GLIDER.BIN"));
        await("the binary on the glider", () -> model.service(SERIAL).transcriptText(), t -> t.contains("sent GLIDER.BIN"));
        assertThat(glider.directory().resolve("GLIDER.BIN")).hasSize(20_000);
        ui.run(() -> manager.sendCommand(SERIAL, "GO"));
        await("the glider submerging", () -> model.service(SERIAL).transcriptText(), t -> t.contains("submerging"));
    }

    record TableResultView(String query, int rows) {}

    // ---------------------------------------------------------------- the window (AssertJ-Swing, under Xvfb)

    static void requireDisplay() {
        assumeTrue(Boolean.getBoolean("ripv.gui.tests"),
                "window tests run with -Dripv.gui.tests=true under a display (xvfb-run), as .ci/run does");
        assumeFalse(GraphicsEnvironment.isHeadless(),
                "window tests need java.awt.headless=false and a display (DISPLAY is '" + System.getenv("DISPLAY") + "')");
    }

    @Test
    void windowLogsInAfterAWrongPasswordShowsServicesAndTalksToTheClock() throws Exception {
        requireDisplay();
        Preferences prefs = Preferences.userRoot().node("org/ripv/test/" + UUID.randomUUID());
        Robot robot = BasicRobot.robotWithNewAwtHierarchy();
        RIPVClient client = GuiActionRunner.execute(() -> {
            FlatLightLaf.setup();
            return new RIPVClient(new GuiManager(new ClientModel()), prefs);
        });
        FrameFixture window = new FrameFixture(robot, client.frame());
        try {
            window.show();
            GuiActionRunner.execute(() -> client.showLogin("localhost:" + sys.server().port(), "alice", null, false));

            DialogFixture login = window.dialog("loginDialog");
            login.textBox("passwordField").enterText("not the password");
            javax.swing.JButton loginButton = login.button("loginButton").target();
            javax.swing.JLabel loginMessage = login.label("loginMessage").target();
            press(() -> login.button("loginButton"), () -> !login.target().isShowing() || !loginButton.isEnabled()
                    || loginMessage.getText().contains("password"));
            Pause.pause(new Condition("the server's refusal in the dialog") {
                @Override
                public boolean test() {
                    return GuiActionRunner.execute(() -> login.target().isShowing()
                            && login.label("loginMessage").target().getText().contains("password"));
                }
            }, Timeout.timeout(T.toMillis()));
            login.requireVisible();

            login.textBox("passwordField").setText("");
            login.textBox("passwordField").enterText(TestSystem.PASSWORD);
            press(() -> login.button("loginButton"), () -> !login.target().isShowing() || !loginButton.isEnabled());
            Pause.pause(new Condition("the dialog to close after logging in") {
                @Override
                public boolean test() {
                    return GuiActionRunner.execute(() -> !login.target().isShowing());
                }
            }, Timeout.timeout(T.toMillis()));
            assertThat(prefs.get("user", "")).isEqualTo("alice");
            assertThat(prefs.get("server", "")).isEqualTo("localhost:" + sys.server().port());
            assertThat(prefs.keys()).doesNotContain("password");

            Pause.pause(new Condition("the clock's tab and tree node") {
                @Override
                public boolean test() {
                    return GuiActionRunner.execute(() -> client.panel(CLOCK) != null
                            && client.serviceTree().services().contains(CLOCK));
                }
            }, Timeout.timeout(T.toMillis()));
            ServiceLayoutPanel tab = GuiActionRunner.execute(() -> client.panel(CLOCK));
            assertThat(tab.dab()).as("the clock has no DAB panel: its fourth quadrant is the live console").isNull();
            assertThat(tab.console()).isNotNull();
            Pause.pause(new Condition("TT to name the clock's mailbox") {
                @Override
                public boolean test() {
                    return window.label("talkingTo").text().equals(CLOCK_BOX);
                }
            }, Timeout.timeout(T.toMillis()));

            // Xvfb has no window manager to hand focus back after the modal dialog: take it.
            GuiActionRunner.execute(() -> {
                client.frame().toFront();
                client.frame().requestFocus();
            });
            robot.waitForIdle();
            window.textBox("commandField").click();
            window.textBox("commandField").enterText("echo over the sea");
            window.textBox("commandField").pressAndReleaseKeys(KeyEvent.VK_ENTER);
            Pause.pause(new Condition("the reply in the reply area") {
                @Override
                public boolean test() {
                    return GuiActionRunner.execute(() -> tab.com().replyText().contains("\nover the sea\n"));
                }
            }, Timeout.timeout(T.toMillis()));
            window.label("lastAction").requireText("echo over the sea");
            window.textBox("commandField").pressAndReleaseKeys(KeyEvent.VK_UP);
            window.textBox("commandField").requireText("echo over the sea");

            // UL through the file chooser; the file shows in the FileTree under UL.
            Path local = dir.resolve("new-binary.bin");
            Files.write(local, new byte[5000]);
            window.button("ulButton").click();
            // A first JFileChooser is slow to build on a busy machine: allow for it.
            JFileChooserFixture chooser = JFileChooserFinder.findFileChooser().withTimeout(T.toMillis()).using(robot);
            // Clicking Open is lost now and then under Xvfb without a window manager; approve as the
            // chooser's own Open action does.
            GuiActionRunner.execute(() -> {
                chooser.target().setSelectedFile(local.toFile());
                chooser.target().approveSelection();
            });
            Pause.pause(new Condition("new-binary.bin in the FileTree") {
                @Override
                public boolean test() {
                    return GuiActionRunner.execute(() -> tab.fim().tree().names(FileArea.UPLOAD).contains("new-binary.bin"));
                }
            }, Timeout.timeout(T.toMillis()));
            assertThat(sys.uploadDir().resolve("new-binary.bin")).hasSize(5000);
        } catch (Throwable t) {
            screenshot("ClientGuiTest-failure.png");
            throw t;
        } finally {
            window.cleanUp();
            prefs.removeNode();
        }
    }

    /** Waits for a condition evaluated on the event thread. */
    static void waitFor(String what, java.util.function.BooleanSupplier check) {
        Pause.pause(new Condition(what) {
            @Override
            public boolean test() {
                return GuiActionRunner.execute(check::getAsBoolean);
            }
        }, Timeout.timeout(2 * T.toMillis()));
    }

    /**
     * Clicks a button with the robot and waits for a sign that it was pressed ({@code pressed}:
     * its effect, or the button busy or gone); when there is none within 5 s, presses it with
     * {@code doClick} (at most twice more). Under Xvfb without a window manager a robot click now
     * and then lands beside a button just laid out — CI's failure screenshots show the button
     * focused and nothing done — and these tests are of the window, not of the X pointer.
     */
    static void press(java.util.function.Supplier<org.assertj.swing.fixture.JButtonFixture> button,
                      java.util.function.BooleanSupplier pressed) throws InterruptedException {
        for (int attempt = 1; attempt <= 3; attempt++) {
            if (attempt == 1) {
                button.get().click();
            } else {
                javax.swing.JButton b;
                try {
                    b = button.get().target();
                } catch (RuntimeException gone) {
                    return; // the button went away: it was pressed
                }
                GuiActionRunner.execute(() -> b.doClick());
            }
            long end = System.nanoTime() + java.time.Duration.ofSeconds(5).toNanos();
            while (System.nanoTime() < end) {
                if (GuiActionRunner.execute(pressed::getAsBoolean)) {
                    return;
                }
                Thread.sleep(100);
            }
        }
    }

    /** Types a command into the showing tab's COM panel and presses Enter. */
    static void command(FrameFixture window, String text) {
        window.textBox("commandField").setText(text);
        window.textBox("commandField").pressAndReleaseKeys(KeyEvent.VK_ENTER);
    }

    @Test
    void windowShowsEveryPanelAfterTheReferenceScenario() throws Exception {
        requireDisplay();
        startTheThreeServices();
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
            GuiActionRunner.execute(() -> client.showLogin("localhost:" + sys.server().port(), "alice",
                    TestSystem.PASSWORD.toCharArray(), true));
            waitFor("all four services as tabs", () -> client.tabs().getTabCount() == 4);
            GuiActionRunner.execute(() -> {
                client.frame().toFront();
                client.frame().requestFocus();
            });
            robot.waitForIdle();

            // Upload the new binary and the data file (UL's chooser is driven in the other window test).
            Path binary = dir.resolve("GLIDER.BIN");
            Files.write(binary, new byte[20_000]);
            GuiActionRunner.execute(() -> {
                gm.upload(binary);
                gm.upload(sample());
            });

            ServiceLayoutPanel serial = GuiActionRunner.execute(() -> client.panel(SERIAL));
            ServiceLayoutPanel db = GuiActionRunner.execute(() -> client.panel(DATABASE));
            ServiceLayoutPanel vis = GuiActionRunner.execute(() -> client.panel(DATAVIS));
            showTab(client, SERIAL);
            waitFor("the glider as TT", () -> gm.model().service(SERIAL).target().startsWith(SERIAL + "tcp-"));
            window.textBox("commandField").click();
            command(window, "?ulfiles");
            waitFor("the upload listing", () -> serial.com().replyText().contains("glider-temperature.dat"));
            command(window, "dir");
            waitFor("the glider's dir", () -> serial.com().replyText().contains("MISSION1.LOG"));
            command(window, "ymodem:get MISSION1.LOG");
            waitFor("the offloaded log under DL", () -> serial.fim().tree().names(FileArea.DOWNLOAD).stream()
                    .anyMatch(n -> n.endsWith("/MISSION1.LOG"))); // HANDLE/NAME: each MailBox's folder

            showTab(client, DATABASE);
            waitFor("the database as TT", () -> gm.model().service(DATABASE).target().startsWith(DATABASE));
            command(window, QUERY);
            waitFor("a DAB tab titled with the query", () -> db.dab().tabs().getTabCount() == 1
                    && QUERY.equals(db.dab().tabs().getToolTipTextAt(0)) && db.dab().selectedTable().getRowCount() > 0);

            showTab(client, DATAVIS);
            waitFor("the plotter as TT", () -> gm.model().service(DATAVIS).target().startsWith(DATAVIS));
            command(window, "vis:glider-temperature.dat");
            waitFor("the plot in DAV", () -> vis.dav().image() != null);
            waitFor("the plot under DL", () -> vis.fim().tree().names(FileArea.DOWNLOAD).stream()
                    .anyMatch(n -> n.endsWith("/glider-temperature.jpg")));
            waitFor("the progress bar gone", () -> gm.model().service(DATAVIS).progress() == null);
            screenshotOf(client, "client.png");

            showTab(client, DATABASE);
            robot.waitForIdle();
            screenshotOf(client, "client-database.png");

            showTab(client, SERIAL);
            command(window, "ymodem:put GLIDER.BIN");
            waitFor("the binary sent", () -> serial.com().replyText().contains("sent GLIDER.BIN"));
            command(window, "GO");
            waitFor("the glider submerging", () -> serial.com().replyText().contains("submerging"));
            waitFor("SS to say the glider is not available", () -> gm.model().service(SERIAL).serviceStatus()
                    .startsWith("not available"));
            robot.waitForIdle();
            screenshotOf(client, "client-serial.png");
        } catch (Throwable t) {
            screenshot("ClientGuiTest-scenario-failure.png");
            throw t;
        } finally {
            window.cleanUp();
            prefs.removeNode();
        }
    }

    /**
     * Brings a service's tab to the front as picking it in the SEL tree does (clicks on tabs are
     * lost now and then under Xvfb without a window manager), and waits until it shows.
     */
    static void showTab(RIPVClient client, String service) {
        GuiActionRunner.execute(() -> client.tabs().setSelectedComponent(client.panel(service)));
        waitFor(service + "'s tab in front", () -> client.panel(service).isShowing()
                && service.equals(client.serviceTree().selectedService()));
    }

    /** The tab titles RIPVClient gives services. */
    static final class RIPVClientTitles {
        static String of(String service) {
            org.ripv.naming.ServiceName n = org.ripv.naming.ServiceName.parse(service);
            return n.service() + " @ " + n.host();
        }
    }

    /** With -Dripv.screenshot.dir=DIR, saves the window as DIR/name (the docs' pictures). */
    static void screenshotOf(RIPVClient client, String name) throws Exception {
        String target = System.getProperty("ripv.screenshot.dir");
        if (target == null || target.isBlank()) {
            return;
        }
        java.awt.Rectangle r = GuiActionRunner.execute(() -> new java.awt.Rectangle(client.frame().getLocationOnScreen(),
                client.frame().getSize()));
        // Park the mouse outside the window so no tooltip covers the picture.
        java.awt.Robot awt = new java.awt.Robot();
        awt.mouseMove(r.x + r.width + 50, r.y + r.height + 50);
        awt.waitForIdle();
        Thread.sleep(1500); // let a tooltip that was showing time out; a picture, not a test, waits here
        Files.createDirectories(Path.of(target));
        javax.imageio.ImageIO.write(new java.awt.Robot().createScreenCapture(r), "png", Path.of(target, name).toFile());
    }

    /** Saves the screen under target/ to see what a failed window test saw. */
    static void screenshot(String name) {
        try {
            java.awt.Rectangle screen = new java.awt.Rectangle(java.awt.Toolkit.getDefaultToolkit().getScreenSize());
            javax.imageio.ImageIO.write(new java.awt.Robot().createScreenCapture(screen), "png",
                    Path.of("target", name).toFile());
        } catch (Exception | Error e) {
            System.err.println("could not save a screenshot: " + e);
        }
    }
}
