package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import com.formdev.flatlaf.FlatLightLaf;
import java.awt.Point;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.geom.Point2D;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
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
import org.ripv.client.charts.PlotPanel;
import org.ripv.client.fleet.FleetModel;
import org.ripv.client.fleet.FleetView;
import org.ripv.client.gui.RIPVClient;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.layout.QuadrantState;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.messages.ChartData;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;
import org.ripv.services.datavis.DataVisServer;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Issue 13's GUI against the real services (server, DatabaseServer on embedded Derby with the
 * shared Slocum files ingested, DataVisServer with the built-in worker): a plot's reply carries
 * its data through server and socket into an interactive chart; the Fleet view's queries; and,
 * under Xvfb with -Dripv.gui.tests=true, the window: the track chart with the value under the
 * mouse, a quadrant maximised and restored by keyboard, the Fleet window (the docs' pictures
 * with -Dripv.screenshot.dir=../docs/images).
 */
@ResourceLock(Shared.DISPLAY)
class DataViewsGuiTest {
    static final Path SHARED = Path.of("../ripv-services/src/test/resources/slocum");
    static final String DATABASE = "<DatabaseServer>::<localhost>";
    static final String DATAVIS = "<DataVisServer>::<localhost>";
    /** AssertJ-Swing's robot takes the old modifier masks. */
    @SuppressWarnings("deprecation")
    static final int CTRL_SHIFT = InputEvent.CTRL_MASK | InputEvent.SHIFT_MASK;

    @TempDir
    Path dir;
    TestSystem sys;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        sys.register(new DatabaseServer("localhost", List.of(EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1")),
                QueryLimits.defaults()));
        sys.register(new DataVisServer("localhost", DataVisServer.Config.of(dir.resolve("vis"))));
        for (String f : List.of("unit_363_2013_245_6_6.mrg", "cp_388_2016_012_0_0.mrg")) {
            Files.copy(SHARED.resolve(f), sys.downloadDir().resolve(f));
        }
        try (ClientSocketHandler h = sys.login("alice")) {
            OutgoingServerMessage r = h.call(DATABASE + "TTY1", "ingest unit_363_2013_245_6_6.mrg cp_388_2016_012_0_0.mrg",
                    Priority.NORMAL, Duration.ofSeconds(120), null);
            assertThat(r.status()).as(r.footer().replyText()).isEqualTo(Status.OK);
        }
    }

    @AfterEach
    void stop() {
        sys.close();
    }

    @Test
    void aTracksDataReachesTheClientAndTheFleetQueriesOpenNoTab() throws Exception {
        ClientModel model = new ClientModel();
        ClientGuiTest.UiThread ui = new ClientGuiTest.UiThread();
        try (GuiManager gm = new GuiManager(model, ui, org.ripv.client.handlers.ClientSocketHandler::connect,
                GuiManager.Timings.DEFAULT)) {
            gm.logIn("localhost", sys.server().port(), "alice", TestSystem.PASSWORD.toCharArray()).get(30, TimeUnit.SECONDS);
            waitUntil(() -> ui.get(() -> model.service(DATAVIS) != null && !model.service(DATAVIS).mailboxes().isEmpty()
                    && model.service(DATABASE) != null && !model.service(DATABASE).mailboxes().isEmpty()));
            ui.run(() -> {
                gm.selectMailbox(DATAVIS, DATAVIS + "TTY1");
                gm.sendCommand(DATAVIS, "vis:track unit_363");
            });
            waitUntil(() -> ui.get(() -> model.service(DATAVIS).picture() != null));
            ImageResult img = ui.get(() -> model.service(DATAVIS).picture().result());
            assertThat(img.jpeg()[0] & 0xff).isEqualTo(0xFF); // the JPEG is still there
            ChartData c = img.chart();
            assertThat(c).as("the built-in worker's reply carries the chart's data").isNotNull();
            assertThat(c.kind()).isEqualTo(ChartData.Kind.TRACK);
            assertThat(c.newest()).isNotNull();
            assertThat(c.newest().label()).contains("2013-09-05");
            assertThat(c.series().get(0).size()).isEqualTo((int) c.rows());
            double lat = c.newest().y();
            assertThat(lat).isBetween(49.0, 51.0); // Station Papa, in decimal degrees

            TableResult latest = (TableResult) gm.ask(DATABASE + "TTY1", FleetModel.LATEST_SQL).get(60, TimeUnit.SECONDS)
                    .footer().result();
            TableResult recent = (TableResult) gm.ask(DATABASE + "TTY1", FleetModel.RECENT_SQL).get(60, TimeUnit.SECONDS)
                    .footer().result();
            FleetModel fleet = new FleetModel();
            fleet.update(List.of(), latest, recent, "");
            assertThat(fleet.vehicles()).extracting(FleetModel.Vehicle::name).containsExactly("cp_388", "unit_363");
            FleetModel.Vehicle papa = fleet.vehicles().get(1);
            assertThat(papa.lat()).isEqualTo(lat);
            assertThat(papa.trackLon()).hasSize((int) c.rows());
            // An ingested file exports like any query result (docs/client.md, DAB): its values, long form.
            TableResult file = (TableResult) gm.ask(DATABASE + "TTY1", "SELECT r.row_no, r.t AS time_utc, s.name AS sensor,"
                    + " s.unit, r.value FROM reading r JOIN sensor_def s ON s.sensor_id = r.sensor_id"
                    + " JOIN data_file f ON f.file_id = r.file_id WHERE f.name = 'cp_388_2016_012_0_0.mrg'"
                    + " ORDER BY r.row_no, s.name").get(60, TimeUnit.SECONDS).footer().result();
            assertThat(file.rows()).hasSizeGreaterThan(100);
            assertThat(org.ripv.export.TableExport.json(file)).contains("\"SENSOR\":\"m_depth\",\"UNIT\":\"m\",\"VALUE\":");
            assertThat(org.ripv.export.TableExport.csv(file)).startsWith("ROW_NO,TIME_UTC,SENSOR,UNIT,VALUE\r\n");
            Thread.sleep(300); // a reply dispatched as a table would land now
            assertThat(ui.get(() -> model.service(DATABASE).tables())).as("the Fleet's queries open no DAB tab").isEmpty();
        } finally {
            ui.close();
        }
    }

    @Test
    void theCliExportsAPlotsDataLikeAQueryResult() throws Exception {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        Path json = dir.resolve("track.json");
        Path table = dir.resolve("after.csv");
        Path svg = dir.resolve("depth-cli.svg");
        int code = new picocli.CommandLine(new org.ripv.client.cli.CliCommand(new java.io.ByteArrayInputStream(new byte[0]),
                new java.io.PrintStream(out, true, StandardCharsets.UTF_8), new java.io.PrintStream(out, true, StandardCharsets.UTF_8)))
                .execute("--server", "localhost:" + sys.server().port(), "--user", "alice", "--password", TestSystem.PASSWORD,
                        "--timeout", "120", "--exec", "use " + DATAVIS + "TTY1", "--exec", "vis:depth unit_363",
                        "--exec", "export json " + json, "--exec", "export svg " + svg, "--exec", "use " + DATABASE + "TTY1",
                        "--exec", "SELECT vehicle FROM positions FETCH FIRST 1 ROWS ONLY", "--exec", "export csv " + table,
                        "--exec", "export svg " + dir.resolve("table.svg"));
        String said = out.toString(StandardCharsets.UTF_8);
        assertThat(code).as(said).isNotZero(); // the last export: a table is no plot
        assertThat(said).contains("exported the plot's data (1 series,").contains("exported the plot (1 series,")
                .contains("no plot to export as SVG");
        assertThat(Files.readString(svg)).startsWith("<?xml").contains("depth of unit_363").contains("<path");
        assertThat(dir.resolve("table.svg")).doesNotExist();
        assertThat(Files.readString(json)).startsWith("{\"title\":\"depth of unit_363\",\"kind\":\"depth\"")
                .contains("\"unit\":\"m\"");
        assertThat(Files.readString(table)).as("a table after the plot: the table").startsWith("VEHICLE\r\n");
    }

    static void waitUntil(java.util.concurrent.Callable<Boolean> check) throws Exception {
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (!check.call()) {
            assertThat(System.nanoTime()).as("timed out").isLessThan(deadline);
            Thread.sleep(50);
        }
    }

    @Test
    void windowDrawsTheTrackInteractivelyMaximisesAQuadrantAndShowsTheFleet() throws Exception {
        ClientGuiTest.requireDisplay();
        Preferences prefs = Preferences.userRoot().node("org/ripv/test/" + UUID.randomUUID());
        Robot robot = BasicRobot.robotWithNewAwtHierarchy();
        GuiManager gm = GuiActionRunner.execute(() -> new GuiManager(new ClientModel()));
        RIPVClient client = GuiActionRunner.execute(() -> {
            FlatLightLaf.setup();
            return new RIPVClient(gm, prefs);
        });
        FrameFixture window = new FrameFixture(robot, client.frame());
        FleetView fleet = null;
        // A simulated glider on a SerialPortServer: a vehicle MailBox with a call state for the Fleet.
        org.ripv.services.simulator.GliderSimulator glider = new org.ripv.services.simulator.GliderSimulator(
                dir.resolve("glider"), Duration.ofSeconds(3), ClientGuiTest.YMODEM);
        int gliderPort = glider.listen(0);
        sys.register(new org.ripv.services.serial.SerialPortServer("localhost", List.of(
                org.ripv.services.serial.LinkSettings.defaults("tcp://127.0.0.1:" + gliderPort)
                        .withIdleTimeout(Duration.ofSeconds(1)).withReconnectEvery(Duration.ofMillis(300))
                        .withYmodem(ClientGuiTest.YMODEM)), null, false, dir.resolve("serial-work")));
        try {
            window.show();
            GuiActionRunner.execute(() -> client.frame().setSize(1400, 900));
            GuiActionRunner.execute(() -> client.showLogin("localhost:" + sys.server().port(), "alice",
                    TestSystem.PASSWORD.toCharArray(), true));
            ClientGuiTest.waitFor("the three services as tabs", () -> client.tabs().getTabCount() == 3);
            GuiActionRunner.execute(() -> {
                client.frame().toFront();
                client.frame().requestFocus();
            });
            ServiceLayoutPanel vis = GuiActionRunner.execute(() -> client.panel(DATAVIS));
            ClientGuiTest.showTab(client, DATAVIS);
            ClientGuiTest.waitFor("the plotter as TT", () -> gm.model().service(DATAVIS).target().startsWith(DATAVIS));
            window.textBox("commandField").click();
            ClientGuiTest.command(window, "vis:track unit_363");
            PlotPanel plot = vis.plot();
            ClientGuiTest.waitFor("the track as an interactive chart", plot::showsChart);
            ClientGuiTest.waitFor("the progress bar gone", () -> gm.model().service(DATAVIS).progress() == null);
            robot.waitForIdle();

            // The mouse over the newest fix: the readout under the chart names it in degrees.
            ChartData c = GuiActionRunner.execute(plot::data);
            Point2D at = GuiActionRunner.execute(() -> plot.screenPoint(c.newest().x(), c.newest().y()));
            robot.moveMouse(plot.chartPanel(), new Point((int) at.getX(), (int) at.getY()));
            ClientGuiTest.waitFor("the value under the cursor", () -> plot.readoutText().contains("° N")
                    && plot.readoutText().contains("° W"));
            ClientGuiTest.screenshotOf(client, "client-chart-track.png");

            // Zoom by keyboard on the focused chart, reset with 0.
            GuiActionRunner.execute(() -> plot.chartPanel().requestFocusInWindow());
            robot.waitForIdle();
            double span = GuiActionRunner.execute(() -> plot.chart().getXYPlot().getDomainAxis().getRange().getLength());
            robot.pressAndReleaseKeys(KeyEvent.VK_ADD);
            ClientGuiTest.waitFor("zoomed in by +", () -> plot.chart().getXYPlot().getDomainAxis().getRange().getLength() < span * 0.9);
            robot.pressAndReleaseKeys(KeyEvent.VK_0);
            ClientGuiTest.waitFor("reset by 0", () -> Math.abs(plot.chart().getXYPlot().getDomainAxis().getRange().getLength()
                    - span) < span * 0.01);

            // Maximise the DAV quadrant with Ctrl+Shift+M (the chart has the focus), restore the same way.
            robot.pressAndReleaseKey(KeyEvent.VK_M, CTRL_SHIFT);
            ClientGuiTest.waitFor("DAV alone in the tab", () -> vis.quadrants().state().mode() == QuadrantState.Mode.MAXIMISED
                    && !vis.com().isShowing() && plot.isShowing());
            GuiActionRunner.execute(() -> gm.sendCommand(DATAVIS, "vis:depth cp_388"));
            ClientGuiTest.waitFor("the depth chart", () -> plot.data() != null && plot.data().kind() == ChartData.Kind.DEPTH);
            ClientGuiTest.waitFor("the progress bar gone", () -> gm.model().service(DATAVIS).progress() == null);
            robot.waitForIdle();
            ClientGuiTest.screenshotOf(client, "client-chart-maximised.png");
            GuiActionRunner.execute(() -> plot.chartPanel().requestFocusInWindow());
            robot.pressAndReleaseKey(KeyEvent.VK_M, CTRL_SHIFT);
            ClientGuiTest.waitFor("the four quadrants back", () -> vis.com().isShowing() && vis.mam().isShowing());

            // Enlarge by keyboard: the chart gets three quarters; restore puts the dividers back.
            robot.pressAndReleaseKey(KeyEvent.VK_E, CTRL_SHIFT);
            ClientGuiTest.waitFor("DAV enlarged", () -> vis.quadrants().state().mode() == QuadrantState.Mode.ENLARGED
                    && plot.getWidth() > vis.getWidth() * 0.6);
            robot.pressAndReleaseKey(KeyEvent.VK_R, CTRL_SHIFT);
            ClientGuiTest.waitFor("restored", () -> vis.quadrants().state().mode() == QuadrantState.Mode.NORMAL);

            // Save as SVG and PNG, the data as CSV.
            Path svg = dir.resolve("depth.svg");
            Path csv = dir.resolve("depth.csv");
            GuiActionRunner.execute(() -> {
                plot.export(PlotPanel.Format.SVG, svg);
                plot.export(PlotPanel.Format.CSV, csv);
            });
            waitUntil(() -> Files.exists(svg) && Files.exists(csv));
            assertThat(Files.readString(svg, StandardCharsets.UTF_8)).contains("<svg").contains("depth of cp_388")
                    .contains("<path").contains("depth (m)");
            assertThat(Files.readAllLines(csv).get(0)).isEqualTo("series,unit,x,time_utc,y");

            // The Fleet window by its key.
            robot.pressAndReleaseKey(KeyEvent.VK_F, CTRL_SHIFT);
            ClientGuiTest.waitFor("the Fleet window with both gliders and the vehicle MailBox", () -> {
                java.awt.Window[] ws = client.frame().getOwnedWindows();
                for (java.awt.Window w : ws) {
                    if (w.isShowing() && "fleetView".equals(w.getName())) {
                        javax.swing.JTable t = (javax.swing.JTable) find(w, "fleetTable");
                        return t != null && t.getRowCount() == 3;
                    }
                }
                return false;
            });
            fleet = GuiActionRunner.execute(() -> client.showFleet());
            FleetView f = fleet;
            ClientGuiTest.waitFor("the fleet refreshed", () -> f.statusText().startsWith("3 vehicle(s)"));
            ClientGuiTest.waitFor("the glider's call state", () -> {
                f.refresh();
                return f.model().vehicles().stream().anyMatch(v -> v.mailbox().startsWith("<SerialPortServer>")
                        && !v.state().isEmpty());
            });
            assertThat(GuiActionRunner.execute(() -> f.model().vehicles().stream().filter(v -> v.name().equals("unit_363"))
                    .findFirst().orElseThrow().fixTime())).isPositive();
            assertThat(GuiActionRunner.execute(() -> {
                for (int r = 0; r < f.table().getRowCount(); r++) {
                    if (f.table().getValueAt(r, 0).toString().startsWith("unit_363")) {
                        return f.table().getValueAt(r, 3).toString();
                    }
                }
                return "no row";
            })).endsWith("days ago");
            assertThat(GuiActionRunner.execute(() -> gm.model().service(DATABASE).tables())).isEmpty();
            robot.waitForIdle();
            screenshotOfWindow(f.dialog(), "client-fleet.png");
        } catch (Throwable t) {
            ClientGuiTest.screenshot("DataViewsGuiTest-failure.png");
            throw t;
        } finally {
            if (fleet != null) {
                FleetView f = fleet;
                GuiActionRunner.execute(() -> f.dialog().dispose());
            }
            window.cleanUp();
            prefs.removeNode();
            glider.close();
        }
    }

    static java.awt.Component find(java.awt.Container root, String name) {
        for (java.awt.Component k : root.getComponents()) {
            if (name.equals(k.getName())) {
                return k;
            }
            if (k instanceof java.awt.Container inner) {
                java.awt.Component c = find(inner, name);
                if (c != null) {
                    return c;
                }
            }
        }
        return null;
    }

    static void screenshotOfWindow(java.awt.Window w, String name) throws Exception {
        String target = System.getProperty("ripv.screenshot.dir");
        if (target == null || target.isBlank()) {
            return;
        }
        java.awt.Rectangle r = GuiActionRunner.execute(() -> new java.awt.Rectangle(w.getLocationOnScreen(), w.getSize()));
        Thread.sleep(500);
        Files.createDirectories(Path.of(target));
        javax.imageio.ImageIO.write(new java.awt.Robot().createScreenCapture(r), "png", Path.of(target, name).toFile());
    }
}
