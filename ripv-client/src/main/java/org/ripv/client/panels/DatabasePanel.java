package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.FontMetrics;
import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import java.awt.event.KeyEvent;
import java.io.File;
import java.math.BigDecimal;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.table.AbstractTableModel;
import javax.swing.table.TableRowSorter;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.export.TableExport;
import org.ripv.messages.TableResult;

/**
 * The DAtaBase panel (thesis 4.1.3, figure 4.5): one tab per query, titled with the query, each
 * a sortable {@link JTable} (numbers sort as numbers); Copy puts the selected rows (or all) on
 * the clipboard as tab-separated text, Export CSV writes the table to a file, Close drops the tab.
 */
public final class DatabasePanel extends JPanel {
    private static final Set<String> NUMERIC = Set.of("TINYINT", "SMALLINT", "INTEGER", "INT", "BIGINT", "REAL",
            "FLOAT", "DOUBLE", "DECIMAL", "NUMERIC", "INT2", "INT4", "INT8", "FLOAT4", "FLOAT8", "SERIAL", "BIGSERIAL");

    private final String service;
    private final GuiManager manager;
    private final JTabbedPane tabs = new JTabbedPane(JTabbedPane.TOP, JTabbedPane.SCROLL_TAB_LAYOUT);
    private final List<TableResult> shown = new ArrayList<>();
    private final JLabel empty = new JLabel("Send SQL from the COM panel; each query's answer opens a tab here.");

    public DatabasePanel(String service, GuiManager manager) {
        super(new BorderLayout(4, 4));
        this.service = service;
        this.manager = manager;
        setName("dab");
        setBorder(BorderFactory.createTitledBorder("DAB — query results"));
        tabs.setName("queryTabs");

        JButton copy = Buttons.button("Copy", KeyEvent.VK_Y, "copyButton",
                "Copy the selected rows (all rows when none is selected) as tab-separated text", e -> copy());
        JButton export = Buttons.button("Export CSV", KeyEvent.VK_X, "exportButton",
                "Save this tab's table as a CSV file", e -> export(false));
        JButton json = Buttons.button("Export JSON", KeyEvent.VK_J, "exportJsonButton",
                "Save this tab's table as JSON: numbers as numbers, NULL as null", e -> export(true));
        JButton close = new JButton("Close");
        close.setMnemonic(KeyEvent.VK_W);
        close.setToolTipText("Close this tab");
        close.addActionListener(e -> {
            int i = tabs.getSelectedIndex();
            if (i >= 0) {
                manager.closeTable(service, i);
            }
        });
        JPanel buttons = Buttons.row(copy, export, json, close);
        add(empty, BorderLayout.NORTH);
        add(tabs, BorderLayout.CENTER);
        add(buttons, BorderLayout.SOUTH);
    }

    /** Adds and removes tabs to match the model; a new table becomes the selected tab. */
    public void update(ServiceModel m) {
        List<TableResult> now = m.tables();
        // Tables are only appended or removed, so walk both lists and reconcile in order.
        int i = 0;
        while (i < shown.size()) {
            if (i < now.size() && now.get(i) == shown.get(i)) {
                i++;
            } else {
                shown.remove(i);
                tabs.removeTabAt(i);
            }
        }
        for (int j = shown.size(); j < now.size(); j++) {
            TableResult t = now.get(j);
            shown.add(t);
            tabs.addTab(title(t.query()), null, tableView(t), t.query());
            tabs.setSelectedIndex(tabs.getTabCount() - 1);
        }
        empty.setVisible(shown.isEmpty());
    }

    static String title(String query) {
        String q = query.strip().replaceAll("\\s+", " ");
        return q.length() <= 40 ? q : q.substring(0, 37) + "...";
    }

    private JPanel tableView(TableResult t) {
        JTable table = new JTable(new ResultModel(t));
        table.setName("table-" + tabs.getTabCount());
        table.setAutoCreateRowSorter(false);
        table.setRowSorter(new TableRowSorter<>(table.getModel()));
        table.setAutoResizeMode(JTable.AUTO_RESIZE_OFF);
        table.setFillsViewportHeight(true);
        // Widths from the header and the first rows' text, so short tables need no dragging.
        FontMetrics fm = table.getFontMetrics(table.getFont());
        for (int c = 0; c < t.columns().size(); c++) {
            int w = fm.stringWidth(t.columns().get(c)) + 24;
            for (int r = 0; r < Math.min(50, t.rows().size()); r++) {
                String v = t.rows().get(r)[c];
                w = Math.max(w, (v == null ? 0 : fm.stringWidth(v)) + 16);
            }
            table.getColumnModel().getColumn(c).setPreferredWidth(Math.max(60, Math.min(360, w)));
        }
        JPanel p = new JPanel(new BorderLayout());
        p.add(new JScrollPane(table), BorderLayout.CENTER);
        JLabel info = new JLabel(t.rows().size() + " row(s)" + (t.truncated() ? " — truncated at the service's limit" : ""));
        p.add(info, BorderLayout.SOUTH);
        p.putClientProperty("table", table);
        return p;
    }

    /** The JTable of the selected tab, or null. */
    public JTable selectedTable() {
        if (tabs.getSelectedComponent() instanceof JPanel p && p.getClientProperty("table") instanceof JTable t) {
            return t;
        }
        return null;
    }

    public JTabbedPane tabs() {
        return tabs;
    }

    private void copy() {
        JTable t = selectedTable();
        if (t == null) {
            return;
        }
        TableResult r = shown.get(tabs.getSelectedIndex());
        String text = TableText.tsv(t, r.columns());
        Toolkit.getDefaultToolkit().getSystemClipboard().setContents(new StringSelection(text), null);
        manager.showNotice("copied " + (t.getSelectedRowCount() == 0 ? t.getRowCount() : t.getSelectedRowCount())
                + " row(s)", false);
    }

    private void export(boolean json) {
        int i = tabs.getSelectedIndex();
        if (i < 0) {
            return;
        }
        TableResult r = shown.get(i);
        JFileChooser chooser = new JFileChooser();
        chooser.setDialogTitle("Export " + title(r.query()) + (json ? " as JSON" : " as CSV"));
        chooser.setSelectedFile(new File("query-" + (i + 1) + (json ? ".json" : ".csv")));
        if (chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            manager.save(chooser.getSelectedFile().toPath(), exported(i, json));
        }
    }

    /** What Export CSV / Export JSON write for a tab ({@link org.ripv.export.TableExport}, shared with the CLI). */
    public byte[] exported(int tab, boolean json) {
        TableResult r = shown.get(tab);
        return (json ? TableExport.json(r) : TableText.csv(r)).getBytes(StandardCharsets.UTF_8);
    }

    /** A read-only table model over a {@link TableResult}; numeric SQL types sort as numbers. */
    public static final class ResultModel extends AbstractTableModel {
        private final TableResult t;
        private final boolean[] numeric;

        public ResultModel(TableResult t) {
            this.t = t;
            this.numeric = new boolean[t.columns().size()];
            for (int c = 0; c < numeric.length; c++) {
                String type = t.types().get(c).toUpperCase(Locale.ROOT);
                numeric[c] = NUMERIC.contains(type.replaceAll("\\(.*", "").trim());
                if (numeric[c]) {
                    for (String[] row : t.rows()) {
                        if (row[c] != null && parse(row[c]) == null) {
                            numeric[c] = false; // a value we cannot read as a number: sort as text
                            break;
                        }
                    }
                }
            }
        }

        private static BigDecimal parse(String s) {
            try {
                return new BigDecimal(s.trim());
            } catch (NumberFormatException e) {
                return null;
            }
        }

        @Override
        public int getRowCount() {
            return t.rows().size();
        }

        @Override
        public int getColumnCount() {
            return t.columns().size();
        }

        @Override
        public String getColumnName(int column) {
            return t.columns().get(column);
        }

        @Override
        public Class<?> getColumnClass(int column) {
            return numeric[column] ? BigDecimal.class : String.class;
        }

        @Override
        public Object getValueAt(int row, int column) {
            String v = t.rows().get(row)[column];
            return v == null || !numeric[column] ? v : parse(v);
        }
    }
}
