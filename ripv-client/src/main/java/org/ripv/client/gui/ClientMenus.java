package org.ripv.client.gui;

import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.List;
import java.util.Locale;
import java.util.prefs.Preferences;
import javax.swing.ButtonGroup;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JTabbedPane;
import javax.swing.KeyStroke;
import org.ripv.client.layout.QuadrantMenu;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.ServiceLayoutPanel;

/**
 * The main window's menus: Server (log in, log out, refresh, quit) and View (themes, the keys
 * to each part of the window, the quadrants, the Fleet window).
 */
record ClientMenus(RIPVClient window, GuiManager manager, Preferences prefs) {
    /** Server (log in, log out, refresh, quit) and View. */
    JMenuBar bar() {
        JMenuBar bar = new JMenuBar();
        JMenu server = new JMenu("Server");
        server.setMnemonic(KeyEvent.VK_S);
        JMenuItem login = new JMenuItem("Log in...", KeyEvent.VK_L);
        login.addActionListener(e -> window.showLogin(null, null, null, false));
        JMenuItem logout = new JMenuItem("Log out", KeyEvent.VK_O);
        logout.addActionListener(e -> manager.logOut());
        JMenuItem refresh = new JMenuItem("Refresh", KeyEvent.VK_R);
        refresh.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_F5, 0));
        refresh.addActionListener(e -> manager.refresh());
        JMenuItem quit = new JMenuItem("Quit", KeyEvent.VK_Q);
        quit.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_Q, InputEvent.CTRL_DOWN_MASK));
        quit.addActionListener(e -> window.frame().dispose());
        server.add(login);
        server.add(logout);
        server.add(refresh);
        server.addSeparator();
        server.add(quit);
        bar.add(server);
        bar.add(viewMenu());
        return bar;
    }

    /** View: themes, and keyboard ways to the parts of the window. */
    private JMenu viewMenu() {
        JTabbedPane tabs = window.tabs();
        JMenu view = new JMenu("View");
        view.setMnemonic(KeyEvent.VK_V);
        ButtonGroup themes = new ButtonGroup();
        for (Theme t : Theme.values()) {
            JRadioButtonMenuItem item = new JRadioButtonMenuItem(
                    t == Theme.LIGHT ? "Light theme" : "Dark theme", Theme.saved(prefs) == t);
            item.setName("theme-" + t.name().toLowerCase(Locale.ROOT));
            item.setMnemonic(t == Theme.LIGHT ? KeyEvent.VK_L : KeyEvent.VK_D);
            item.addActionListener(e -> t.choose(prefs));
            themes.add(item);
            view.add(item);
        }
        view.addSeparator();
        JMenuItem services = new JMenuItem("Services (SEL)", KeyEvent.VK_S);
        services.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_1, InputEvent.ALT_DOWN_MASK));
        services.addActionListener(e -> window.serviceTree().requestFocusInWindow());
        JMenuItem commandLine = new JMenuItem("Command line (COM)", KeyEvent.VK_C);
        commandLine.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_2, InputEvent.ALT_DOWN_MASK));
        commandLine.addActionListener(e -> {
            if (tabs.getSelectedComponent() instanceof ServiceLayoutPanel p) {
                p.com().focusCommand();
            }
        });
        JMenuItem mailboxes = new JMenuItem("MailBoxes (MAM)", KeyEvent.VK_M);
        mailboxes.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_3, InputEvent.ALT_DOWN_MASK));
        mailboxes.addActionListener(e -> {
            if (tabs.getSelectedComponent() instanceof ServiceLayoutPanel p) {
                p.mam().tree().requestFocusInWindow();
            }
        });
        JMenuItem files = new JMenuItem("Files (FIM)", KeyEvent.VK_F);
        files.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_4, InputEvent.ALT_DOWN_MASK));
        files.addActionListener(e -> {
            if (tabs.getSelectedComponent() instanceof ServiceLayoutPanel p) {
                p.fim().tree().requestFocusInWindow();
            }
        });
        JMenuItem next = new JMenuItem("Next service tab", KeyEvent.VK_N);
        next.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_PAGE_DOWN, InputEvent.CTRL_DOWN_MASK));
        next.addActionListener(e -> {
            if (tabs.getTabCount() > 0) {
                tabs.setSelectedIndex((tabs.getSelectedIndex() + 1) % tabs.getTabCount());
            }
        });
        for (JMenuItem i : List.of(services, commandLine, mailboxes, files, next)) {
            view.add(i);
        }
        view.addSeparator();
        QuadrantMenu.items(() -> tabs.getSelectedComponent() instanceof ServiceLayoutPanel p
                ? p.quadrants() : null).forEach(view::add);
        view.addSeparator();
        JMenuItem fleet = new JMenuItem("Fleet...", KeyEvent.VK_T);
        fleet.setName("fleetMenu");
        fleet.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_F, InputEvent.CTRL_DOWN_MASK
                | InputEvent.SHIFT_DOWN_MASK));
        fleet.addActionListener(e -> window.showFleet());
        view.add(fleet);
        return view;
    }
}
