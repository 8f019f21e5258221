package org.ripv.client.fleet;

import java.awt.BorderLayout;
import java.awt.Dialog;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.function.LongSupplier;
import javax.swing.BorderFactory;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTable;
import javax.swing.KeyStroke;
import javax.swing.SwingConstants;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.DefaultTableCellRenderer;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.client.panels.Buttons;
import org.ripv.export.TableExport;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.SessionState;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/**
 * The Fleet window (View → Fleet, Ctrl+Shift+F): every vehicle with its call state, last fix,
 * time since it, position and a small track; Refresh (Alt+R, also every minute), Plot track
 * (Alt+P: {@code vis:track VEHICLE} in the DataVisServer's tab), Export CSV / JSON (Alt+C, Alt+J).
 * The ages tick every 10 s. Build and use it on the event thread.
 */
public final class FleetView {
    /** The table's columns. */
    static final List<String> COLUMNS = List.of("Vehicle", "State", "Last fix (UTC)", "Since", "Latitude", "Longitude",
            "Source", "Track");
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm", Locale.ROOT)
            .withZone(ZoneOffset.UTC);

    private final GuiManager manager;
    private final LongSupplier clock;
    private final FleetModel fleet = new FleetModel();
    private final JDialog dialog;
    private final Rows rows = new Rows();
    private final JTable table = new JTable(rows);
    private final JLabel status = new JLabel(" ");
    private final Timer tick;
    private final Timer refreshTimer;

    public FleetView(Window owner, GuiManager manager) {
        this(owner, manager, System::currentTimeMillis);
    }

    FleetView(Window owner, GuiManager manager, LongSupplier clock) {
        this.manager = manager;
        this.clock = clock;
        dialog = new JDialog(owner, "RIPV Fleet", Dialog.ModalityType.MODELESS);
        dialog.setName("fleetView");
        table.setName("fleetTable");
        table.setRowHeight(56);
        table.setAutoCreateRowSorter(true);
        table.getColumnModel().getColumn(COLUMNS.indexOf("Track")).setCellRenderer(new TrackCell());
        table.getColumnModel().getColumn(COLUMNS.indexOf("Track")).setPreferredWidth(170);
        int[] widths = {165, 75, 130, 110, 85, 95, 120, 160};
        for (int c = 0; c < widths.length; c++) {
            table.getColumnModel().getColumn(c).setPreferredWidth(widths[c]);
        }
        DefaultTableCellRenderer degrees = new DefaultTableCellRenderer() {
            @Override
            protected void setValue(Object value) {
                setText(value instanceof Double d ? String.format(Locale.ROOT, "%.5f", d) : "—");
            }
        };
        degrees.setHorizontalAlignment(SwingConstants.RIGHT);
        table.getColumnModel().getColumn(4).setCellRenderer(degrees);
        table.getColumnModel().getColumn(5).setCellRenderer(degrees);
        status.setName("fleetStatus");
        JPanel buttons = Buttons.row(
                Buttons.button("Refresh", KeyEvent.VK_R, "fleetRefresh",
                        "Ask the database and the server again (also every minute)", e -> refresh()),
                Buttons.button("Plot track", KeyEvent.VK_P, "fleetPlot",
                        "vis:track VEHICLE in the DataVisServer's tab", e -> plotSelected()),
                Buttons.button("Export CSV", KeyEvent.VK_C, "fleetCsv", "This table as CSV", e -> export(false)),
                Buttons.button("Export JSON", KeyEvent.VK_J, "fleetJson", "This table as JSON", e -> export(true)));
        JPanel south = new JPanel(new BorderLayout());
        south.add(status, BorderLayout.NORTH);
        south.add(buttons, BorderLayout.SOUTH);
        JPanel content = new JPanel(new BorderLayout(4, 4));
        content.setBorder(BorderFactory.createEmptyBorder(6, 6, 6, 6));
        content.add(new JScrollPane(table), BorderLayout.CENTER);
        content.add(south, BorderLayout.SOUTH);
        dialog.setContentPane(content);
        dialog.getRootPane().registerKeyboardAction(e -> dialog.dispose(), KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0),
                JComponent.WHEN_IN_FOCUSED_WINDOW);
        dialog.setSize(1000, 420);
        dialog.setLocationRelativeTo(owner);
        tick = new Timer(10_000, e -> rows.fireTableRowsUpdated(0, Math.max(0, rows.getRowCount() - 1)));
        refreshTimer = new Timer(60_000, e -> refresh());
        dialog.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                tick.stop();
                refreshTimer.stop();
            }
        });
    }

    /** Shows the window and asks for the data. */
    public void show() {
        dialog.setVisible(true);
        tick.start();
        refreshTimer.start();
        refresh();
        table.requestFocusInWindow();
    }

    public JDialog dialog() {
        return dialog;
    }

    public JTable table() {
        return table;
    }

    public FleetModel model() {
        return fleet;
    }

    public String statusText() {
        return status.getText();
    }

    /** Asks the DatabaseServer for the positions and takes the MailBoxes the client knows; on the event thread. */
    public CompletableFuture<Void> refresh() {
        List<MailboxStatus> mailboxes = new ArrayList<>();
        String database = null;
        for (ServiceModel s : manager.model().services()) {
            boolean vehicles = Ids.SID_SERIAL.equals(s.descriptor().sid());
            for (MailboxStatus m : s.mailboxes()) {
                // A SerialPortServer MailBox is a vehicle even before it has said anything (no session yet).
                mailboxes.add(m.session() == null && vehicles ? m.withSession(new SessionState(
                        SessionState.State.UNKNOWN, 0, null, null, 0, null)) : m);
            }
            if (database == null && "DAB".equals(s.panel()) && !s.mailboxes().isEmpty()) {
                database = s.mailboxes().get(0).address();
            }
        }
        if (database == null) {
            apply(mailboxes, null, null, "no DatabaseServer with a MailBox is registered: positions from ?mailboxes only");
            return CompletableFuture.completedFuture(null);
        }
        status.setText("asking " + database + " ...");
        String db = database;
        CompletableFuture<OutgoingServerMessage> latest = manager.ask(db, FleetModel.LATEST_SQL);
        CompletableFuture<OutgoingServerMessage> recent = manager.ask(db, FleetModel.RECENT_SQL);
        CompletableFuture<Void> done = new CompletableFuture<>();
        latest.thenCombine(recent, (a, b) -> new OutgoingServerMessage[] {a, b}).whenComplete((r, e) ->
                SwingUtilities.invokeLater(() -> {
                    if (e != null) {
                        apply(mailboxes, null, null, "the positions query failed: " + e.getMessage());
                    } else {
                        String problem = "";
                        TableResult[] t = new TableResult[2];
                        for (int i = 0; i < 2; i++) {
                            if (r[i].status() == Status.ERROR) {
                                problem = db + ": " + r[i].footer().replyText();
                            } else if (r[i].footer().result() instanceof TableResult table) {
                                t[i] = table;
                            }
                        }
                        apply(mailboxes, t[0], t[1], problem);
                    }
                    done.complete(null);
                }));
        return done;
    }

    private void apply(List<MailboxStatus> mailboxes, TableResult latest, TableResult recent, String problem) {
        fleet.update(mailboxes, latest, recent, problem);
        rows.fireTableDataChanged();
        String when = DateTimeFormatter.ofPattern("HH:mm:ss", Locale.ROOT).withZone(ZoneOffset.UTC)
                .format(Instant.ofEpochMilli(clock.getAsLong()));
        status.setText(fleet.vehicles().size() + " vehicle(s), updated " + when + " UTC"
                + (problem == null || problem.isEmpty() ? "" : " — " + problem));
    }

    private FleetModel.Vehicle selected() {
        int r = table.getSelectedRow();
        return r < 0 ? null : fleet.vehicles().get(table.convertRowIndexToModel(r));
    }

    private void plotSelected() {
        FleetModel.Vehicle v = selected();
        if (v == null) {
            manager.showNotice("pick a vehicle in the Fleet table first", true);
            return;
        }
        for (ServiceModel s : manager.model().services()) {
            if ("DAV".equals(s.panel())) {
                if (s.target().isEmpty() && !s.mailboxes().isEmpty()) {
                    manager.selectMailbox(s.name(), s.mailboxes().get(0).address());
                }
                manager.sendCommand(s.name(), "vis:track " + v.name());
                manager.showNotice("vis:track " + v.name() + " sent to " + s.name() + ": the plot shows in its DAV panel", false);
                return;
            }
        }
        manager.showNotice("no DataVisServer is registered to plot the track", true);
    }

    /** The table as a query result, for the shared CSV/JSON writer. */
    public TableResult asTable() {
        List<String[]> out = new ArrayList<>();
        long now = clock.getAsLong();
        for (FleetModel.Vehicle v : fleet.vehicles()) {
            out.add(new String[] {v.name(), v.mailbox(), v.state(),
                    v.fixTime() > 0 ? Instant.ofEpochMilli(v.fixTime()).toString() : null,
                    v.fixTime() > 0 ? Long.toString((now - v.fixTime()) / 1000) : null,
                    Double.isNaN(v.lat()) ? null : Double.toString(v.lat()),
                    Double.isNaN(v.lon()) ? null : Double.toString(v.lon()), v.source(),
                    Integer.toString(v.trackLon() == null ? 0 : v.trackLon().length)});
        }
        return new TableResult("fleet", List.of("vehicle", "mailbox", "state", "last_fix_utc", "seconds_since_fix", "lat", "lon",
                "source", "track_points"), List.of("VARCHAR", "VARCHAR", "VARCHAR", "TIMESTAMP", "BIGINT", "DOUBLE", "DOUBLE",
                "VARCHAR", "INTEGER"), out, false);
    }

    private void export(boolean json) {
        JFileChooser chooser = new JFileChooser();
        chooser.setSelectedFile(new File(json ? "fleet.json" : "fleet.csv"));
        if (chooser.showSaveDialog(dialog) == JFileChooser.APPROVE_OPTION) {
            TableResult t = asTable();
            manager.save(chooser.getSelectedFile().toPath(),
                    (json ? TableExport.json(t) : TableExport.csv(t)).getBytes(StandardCharsets.UTF_8));
        }
    }

    /** The table's rows: the fleet model's vehicles, ages against the clock. */
    private final class Rows extends AbstractTableModel {
        @Override
        public int getRowCount() {
            return fleet.vehicles().size();
        }

        @Override
        public int getColumnCount() {
            return COLUMNS.size();
        }

        @Override
        public String getColumnName(int c) {
            return COLUMNS.get(c);
        }

        @Override
        public Class<?> getColumnClass(int c) {
            return c == 4 || c == 5 ? Double.class : Object.class;
        }

        @Override
        public Object getValueAt(int r, int c) {
            FleetModel.Vehicle v = fleet.vehicles().get(r);
            return switch (c) {
                case 0 -> {
                    String handle = v.mailbox().substring(v.mailbox().lastIndexOf('>') + 1);
                    yield v.mailbox().isEmpty() || handle.equalsIgnoreCase(v.name()) ? v.name() : v.name() + "  (" + handle + ")";
                }
                case 1 -> v.state().isEmpty() ? "—" : v.state();
                case 2 -> v.fixTime() > 0 ? TIME.format(Instant.ofEpochMilli(v.fixTime())) : "—";
                case 3 -> FleetModel.age(v.fixTime(), clock.getAsLong());
                case 4 -> Double.isNaN(v.lat()) ? null : v.lat();
                case 5 -> Double.isNaN(v.lon()) ? null : v.lon();
                case 6 -> v.source();
                default -> v;
            };
        }

    }
}
