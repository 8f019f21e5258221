package org.ripv.client.gui;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.prefs.Preferences;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.JTabbedPane;
import javax.swing.SwingUtilities;
import javax.swing.UIManager;
import org.ripv.client.fleet.FleetView;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ClientModel.Connection;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.client.panels.Buttons;
import org.ripv.client.panels.Colors;
import org.ripv.client.panels.LoginDialog;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.client.trees.ServiceTree;
import org.ripv.naming.ServiceName;

/**
 * The RIPVClient main window (thesis 4.1.2–4.1.3): the SEL panel's {@link ServiceTree} on the
 * left, a {@link JTabbedPane} with one {@link ServiceLayoutPanel} per registered service, a
 * banner when the connection is lost, and a status bar. Tabs follow the service list as services
 * register and vanish. Build and use it on the event thread; the {@link GuiManager} does all
 * network work elsewhere.
 *
 * <pre>{@code
 * ClientModel model = new ClientModel();
 * GuiManager manager = new GuiManager(model);
 * SwingUtilities.invokeLater(() -> {
 *     RIPVClient client = new RIPVClient(manager, Preferences.userNodeForPackage(RIPVClient.class));
 *     client.show();
 *     client.showLogin(null, null, null, false);
 * });
 * }</pre>
 */
public final class RIPVClient {
    private final GuiManager manager;
    private final ClientModel model;
    private final Preferences prefs;
    private final JFrame frame = new JFrame("RIPV Client");
    private final ServiceTree serviceTree;
    private final JTabbedPane tabs = new JTabbedPane();
    private final Map<String, ServiceLayoutPanel> panels = new LinkedHashMap<>();
    private final JLabel banner = new JLabel(" ");
    private final JLabel status = new JLabel(" ");
    private final JLabel connection = new JLabel(" ");
    private final CountDownLatch closed = new CountDownLatch(1);
    private final JSplitPane split;
    private final WindowLayout saved;
    private boolean syncing;
    /** Whether the window has shown the service the model chose to open on (the first vehicle's). */
    private boolean opened;
    private FleetView fleetView;
    private long lastFocusRefresh;

    public RIPVClient(GuiManager manager, Preferences prefs) {
        this.manager = manager;
        this.model = manager.model();
        this.prefs = prefs;
        frame.setName("ripvClient");
        serviceTree = new ServiceTree(this::selectService, (service, mailbox) -> {
            // A vehicle picked in SEL: its tab comes to the front with that MailBox as the target.
            selectService(service);
            manager.selectMailbox(service, mailbox);
        });
        tabs.setName("serviceTabs");
        tabs.addChangeListener(e -> {
            if (tabs.getSelectedComponent() instanceof ServiceLayoutPanel p) {
                if (!syncing) {
                    serviceTree.select(p.service());
                }
                p.com().focusCommand(); // the operator can type at once
            }
        });

        JButton refresh = Buttons.button("Refresh", KeyEvent.VK_R, "selRefresh",
                "Ask the server for its services again (?services); also every 15 s", e -> manager.refresh());
        JPanel sel = new JPanel(new BorderLayout(2, 2));
        sel.setBorder(BorderFactory.createTitledBorder("SEL — services"));
        sel.add(new JScrollPane(serviceTree), BorderLayout.CENTER);
        sel.add(refresh, BorderLayout.SOUTH);
        sel.setPreferredSize(new Dimension(330, 400)); // "<SerialPortServer>::<localhost>" and a vehicle's badge whole

        JPanel center = new JPanel(new BorderLayout());
        center.add(tabs, BorderLayout.CENTER);
        split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, sel, center);
        split.setName("selSplit");
        split.setResizeWeight(0.0);
        split.setContinuousLayout(true);
        // A sensible first size that pack() keeps, shrunk to fit small screens.
        Dimension screen = Toolkit.getDefaultToolkit().getScreenSize();
        split.setPreferredSize(new Dimension(Math.min(1360, screen.width - 40), Math.min(820, screen.height - 120)));

        banner.setName("connectionBanner");
        banner.setOpaque(true);
        banner.setBorder(BorderFactory.createEmptyBorder(4, 8, 4, 8));
        banner.setVisible(false);
        status.setName("statusBar");
        connection.setName("connectionLabel");
        JPanel bottom = new JPanel(new BorderLayout(8, 0));
        bottom.setBorder(BorderFactory.createEmptyBorder(2, 6, 2, 6));
        bottom.add(status, BorderLayout.CENTER);
        bottom.add(connection, BorderLayout.EAST);

        frame.setJMenuBar(new ClientMenus(this, manager, prefs).bar());
        frame.getContentPane().add(banner, BorderLayout.NORTH);
        frame.getContentPane().add(split, BorderLayout.CENTER);
        frame.getContentPane().add(bottom, BorderLayout.SOUTH);
        frame.setDefaultCloseOperation(JFrame.DISPOSE_ON_CLOSE);
        frame.addWindowFocusListener(new WindowAdapter() {
            @Override
            public void windowGainedFocus(WindowEvent e) {
                // Back from elsewhere: others may have added files meanwhile.
                long now = System.nanoTime();
                if (now - lastFocusRefresh > 5_000_000_000L && model.connection() == Connection.CONNECTED) {
                    lastFocusRefresh = now;
                    manager.refreshFileLists();
                }
            }
        });
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosing(WindowEvent e) {
                saveLayout();
            }

            @Override
            public void windowClosed(WindowEvent e) {
                manager.close();
                closed.countDown();
            }
        });
        saved = WindowLayout.load(prefs);
        restoreLayout();
        model.addListener(this::changed);
        syncServices();
        showConnection();
    }

    /** Opens the Fleet window (or brings it to the front) and refreshes it. */
    public FleetView showFleet() {
        if (fleetView == null || !fleetView.dialog().isDisplayable()) {
            fleetView = new FleetView(frame, manager);
        }
        fleetView.show();
        fleetView.dialog().toFront();
        return fleetView;
    }

    /** Shows the window. */
    public void show() {
        frame.setVisible(true);
    }

    public JFrame frame() {
        return frame;
    }

    /** Counts down when the window has closed and the manager stopped. */
    public CountDownLatch closedLatch() {
        return closed;
    }

    /**
     * Shows the log-in dialog (non-blocking for the caller: it is modal to the window only). With
     * {@code submit} and a password it logs in at once, as the demo does.
     */
    public LoginDialog showLogin(String server, String user, char[] password, boolean submit) {
        LoginDialog d = new LoginDialog(frame, prefs, manager::logIn);
        d.fill(server, user, password);
        // Modal: setVisible blocks in a nested event loop, so show it from a fresh event; the
        // auto log-in then runs inside that loop, with the dialog saying "connecting...".
        SwingUtilities.invokeLater(() -> d.setVisible(true));
        if (submit) {
            SwingUtilities.invokeLater(d::submit);
        }
        return d;
    }

    private void selectService(String service) {
        ServiceLayoutPanel p = panels.get(service);
        if (p != null) {
            syncing = true;
            tabs.setSelectedComponent(p);
            syncing = false;
        }
    }

    private void changed(ClientModel.Change c) {
        switch (c.kind()) {
            case SERVICES -> syncServices();
            case MAILBOXES -> {
                // The SEL tree shows each vehicle's state badge under its service.
                syncing = true;
                try {
                    serviceTree.update(model);
                } finally {
                    syncing = false;
                }
                ServiceLayoutPanel p = c.service() == null ? null : panels.get(c.service());
                if (p != null) {
                    p.update(model, c.kind());
                } else if (c.service() == null) {
                    panels.values().forEach(x -> x.update(model, c.kind()));
                }
            }
            case CONNECTION -> showConnection();
            case NOTICE -> {
                // The latest message only, on one line; the whole of it in the tooltip.
                status.setText(model.notice().isEmpty() ? " " : model.notice());
                status.setForeground(model.noticeIsError() ? Colors.error() : UIManager.getColor("Label.foreground"));
                status.setToolTipText(model.noticeDetail().isEmpty() ? null : model.noticeDetail());
            }
            default -> {
                if (c.service() == null) {
                    panels.values().forEach(p -> p.update(model, c.kind()));
                } else {
                    ServiceLayoutPanel p = panels.get(c.service());
                    if (p != null) {
                        p.update(model, c.kind());
                    }
                }
            }
        }
    }

    /** Adds tabs for new services, removes those of vanished ones. */
    private void syncServices() {
        syncing = true;
        try {
            panels.entrySet().removeIf(e -> {
                if (model.service(e.getKey()) == null) {
                    tabs.remove(e.getValue());
                    return true;
                }
                return false;
            });
            for (ServiceModel s : model.services()) {
                if (!panels.containsKey(s.name())) {
                    ServiceLayoutPanel p = new ServiceLayoutPanel(s, manager, manager.model());
                    p.dividers(quadrants());
                    panels.put(s.name(), p);
                    tabs.addTab(tabTitle(s.name()), null, p, s.name() + " — " + s.descriptor().description());
                    p.updateAll(model);
                }
            }
            serviceTree.update(model);
            if (!opened && !model.opening().isEmpty() && panels.containsKey(model.opening())) {
                opened = true; // once: after that, the tab is the user's choice
                tabs.setSelectedComponent(panels.get(model.opening()));
            }
            if (tabs.getSelectedComponent() instanceof ServiceLayoutPanel p) {
                serviceTree.select(p.service());
            }
        } finally {
            syncing = false;
        }
    }

    static String tabTitle(String service) {
        try {
            ServiceName n = ServiceName.parse(service);
            return n.service() + " @ " + n.host();
        } catch (IllegalArgumentException e) {
            return service;
        }
    }

    private void showConnection() {
        Connection c = model.connection();
        String who = model.session() == null ? "" : model.session().user() + "@";
        connection.setText(switch (c) {
            case CONNECTED -> "connected: " + who + model.server();
            case CONNECTING -> "connecting...";
            case LOST -> "connection lost";
            case DISCONNECTED -> "not connected";
        });
        frame.setTitle("RIPV Client" + (c == Connection.CONNECTED ? " — " + who + model.server() : ""));
        boolean show = c == Connection.LOST || (c == Connection.DISCONNECTED && !model.connectionDetail().isEmpty()
                && !model.connectionDetail().equals("logged out"));
        banner.setVisible(show);
        if (show) {
            banner.setText((c == Connection.LOST ? "Connection lost: " : "Not connected: ") + model.connectionDetail());
            banner.setBackground(c == Connection.LOST ? new Color(0xFFE08A) : new Color(0xF4C7C3));
            banner.setForeground(Color.BLACK);
        }
    }

    private void restoreLayout() {
        Rectangle screen = frame.getGraphicsConfiguration().getBounds();
        Rectangle b = saved.fitted(screen);
        if (b != null) {
            // Before the window has a peer, so the platform takes these bounds as they are.
            frame.setBounds(b);
            frame.validate();
        } else {
            frame.pack(); // a first run: the preferred size, where the platform puts new windows
            frame.setLocationByPlatform(true);
        }
        if (saved.maximized()) {
            frame.setExtendedState(frame.getExtendedState() | JFrame.MAXIMIZED_BOTH);
        }
        if (saved.selDivider() > 0) {
            split.setDividerLocation(saved.selDivider());
        }
    }

    /** The dividers new tabs get: the showing tab's, else the saved ones. */
    private int[] quadrants() {
        if (tabs.getSelectedComponent() instanceof ServiceLayoutPanel p && p.isShowing()) {
            return p.dividers();
        }
        return saved.quadrants();
    }

    /** Remembers the window's bounds and dividers (on closing; tests call it too). */
    public void saveLayout() {
        boolean max = (frame.getExtendedState() & JFrame.MAXIMIZED_BOTH) == JFrame.MAXIMIZED_BOTH;
        int[] q = tabs.getSelectedComponent() instanceof ServiceLayoutPanel p ? p.dividers() : saved.quadrants();
        new WindowLayout(max ? saved.bounds() : frame.getBounds(), max, split.getDividerLocation(), q).save(prefs);
    }

    /** The tab of a service, or null. */
    public ServiceLayoutPanel panel(String service) {
        return panels.get(service);
    }

    public ServiceTree serviceTree() {
        return serviceTree;
    }

    public JTabbedPane tabs() {
        return tabs;
    }
}
