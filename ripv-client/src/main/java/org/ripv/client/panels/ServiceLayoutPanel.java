package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Dimension;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JSplitPane;
import org.ripv.client.charts.PlotPanel;
import org.ripv.client.layout.Quadrants;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;

/**
 * One service's tab (thesis 4.1.3, figure 4.5): four quadrants with the COM panel top left, the
 * MAM panel top right, the FIM panel bottom right, and the service's fourth panel bottom left —
 * DAB ({@link DatabasePanel}) or DAV ({@link ImagePanel}) as its descriptor says. A service
 * without a fourth panel (the SerialPortServer) gets a COM panel spanning both rows, for more
 * reply area. The quadrants are split panes the operator can resize (and the window remembers);
 * Tab goes through them in the same order in every tab: COM, the fourth panel, MAM, FIM.
 */
public final class ServiceLayoutPanel extends JPanel {
    private final JSplitPane columns;
    private final JSplitPane left;
    private final JSplitPane right;
    private final String service;
    private final String kind;
    private final ComPanel com;
    private final MamPanel mam;
    private final FimPanel fim;
    private final DatabasePanel dab;
    private final PlotPanel plot;
    private final ImagePanel dav;
    private final ConsolePanel console;
    private final Quadrants quadrants;

    public ServiceLayoutPanel(ServiceModel model, GuiManager manager) {
        this(model, manager, null);
    }

    /** With {@code client} given, a service without a fourth panel gets the live console there. */
    public ServiceLayoutPanel(ServiceModel model, GuiManager manager, ClientModel client) {
        super(new BorderLayout());
        this.service = model.name();
        this.kind = model.panel();
        setName("service:" + service);
        com = new ComPanel(service, manager);
        mam = new MamPanel(service, manager);
        fim = new FimPanel(manager);
        dab = "DAB".equals(kind) ? new DatabasePanel(service, manager) : null;
        plot = "DAV".equals(kind) ? new PlotPanel(manager) : null; // the chart, or the JPEG
        dav = plot == null ? null : plot.image();
        console = dab == null && dav == null && client != null ? new ConsolePanel(service, client, manager) : null;
        JComponent fourth = dab != null ? dab : plot != null ? plot : console;

        // Fixed base sizes: GridBag then shares the window by weight alone, so the quadrants do
        // not jump about when a long mailbox name or path arrives.
        fix(com, 560, 300);
        fix(mam, 320, 200);
        fix(fim, 320, 240);
        if (fourth != null) {
            fix(fourth, 560, 260);
        }
        // Left column wider than the right; rows share the height.
        left = fourth == null ? null : split(JSplitPane.VERTICAL_SPLIT, com, fourth, 0.5, "leftSplit");
        right = split(JSplitPane.VERTICAL_SPLIT, mam, fim, 0.45, "rightSplit");
        columns = split(JSplitPane.HORIZONTAL_SPLIT, left != null ? left : com, right, 0.65, "columnSplit");
        add(columns, BorderLayout.CENTER);
        quadrants = new Quadrants(this, columns, left, right, com, fourth, mam, fim);
    }

    /** Enlarging, maximising and restoring this tab's quadrants (View menu, Ctrl+Shift+E / M / R). */
    public Quadrants quadrants() {
        return quadrants;
    }

    private static JSplitPane split(int orientation, JComponent a, JComponent b, double weight, String name) {
        JSplitPane s = new JSplitPane(orientation, true, a, b);
        s.setName(name);
        s.setResizeWeight(weight);
        s.setOneTouchExpandable(true);
        s.setBorder(null);
        return s;
    }

    /** Where the operator put the dividers: columns, left column (or -1), right column, in pixels. */
    public int[] dividers() {
        return new int[] {columns.getDividerLocation(), left == null ? -1 : left.getDividerLocation(), right.getDividerLocation()};
    }

    /** Puts the dividers where {@link #dividers()} said (values below 0 are left alone). */
    public void dividers(int[] at) {
        if (at == null || at.length != 3) {
            return;
        }
        if (at[0] > 0) {
            columns.setDividerLocation(at[0]);
        }
        if (left != null && at[1] > 0) {
            left.setDividerLocation(at[1]);
        }
        if (at[2] > 0) {
            right.setDividerLocation(at[2]);
        }
    }

    private static void fix(JComponent c, int w, int h) {
        c.setPreferredSize(new Dimension(w, h));
        c.setMinimumSize(new Dimension(w / 2, h / 2));
    }


    public String service() {
        return service;
    }

    /** Repaints the parts a change concerns; on the event thread. */
    public void update(ClientModel model, ClientModel.Kind what) {
        ServiceModel m = model.service(service);
        if (m == null) {
            return;
        }
        switch (what) {
            case COM -> {
                com.update(m);
                if (console != null) {
                    console.update(m);
                }
            }
            case MAILBOXES -> {
                mam.update(m);
                if (console != null) {
                    console.update(m);
                }
            }
            case TABLES -> {
                if (dab != null) {
                    dab.update(m);
                }
            }
            case IMAGE -> {
                if (plot != null) {
                    plot.update(m);
                }
            }
            case FILES -> fim.updateFiles(model);
            case TRANSFERS -> fim.updateTransfers(model);
            default -> updateAll(model);
        }
    }

    /** Repaints everything. */
    public void updateAll(ClientModel model) {
        ServiceModel m = model.service(service);
        if (m == null) {
            return;
        }
        com.update(m);
        mam.update(m);
        if (console != null) {
            console.update(m);
        }
        fim.updateFiles(model);
        fim.updateTransfers(model);
        if (dab != null) {
            dab.update(m);
        }
        if (plot != null) {
            plot.update(m);
        }
    }

    /** The live console, or null for a service with a DAB or DAV panel. */
    public ConsolePanel console() {
        return console;
    }

    public ComPanel com() {
        return com;
    }

    public MamPanel mam() {
        return mam;
    }

    public FimPanel fim() {
        return fim;
    }

    /** The DAB panel, or null. */
    public DatabasePanel dab() {
        return dab;
    }

    /** The DAV panel's JPEG view, or null. */
    public ImagePanel dav() {
        return dav;
    }

    /** The DAV panel (interactive chart, or the JPEG), or null. */
    public PlotPanel plot() {
        return plot;
    }
}
