package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.Font;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JLabel;
import javax.swing.JTextField;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.Timer;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ConsoleModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ServiceModel;
import org.ripv.client.managers.SessionStates;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.SessionState;

/**
 * The live console of the service's target MailBox (docs/sessions.md): everything the vehicle
 * says, asked or not, commands with their users, transfers and events, as the server pushes
 * them to every watcher; above it a badge with the call state and the time since last contact.
 * The client watches the target from the moment it is picked; the command line stays in COM.
 * "Older" fetches earlier lines from the server's transcript ({@code ?history}); the search
 * field shows only the lines that contain its text.
 */
public final class ConsolePanel extends JPanel {
    private final ClientModel model;
    private final String service;
    private final JLabel badge = new JLabel(" ");
    private final JTextArea text = new JTextArea();
    private final JTextField search = new JTextField(14);
    private final JLabel matches = new JLabel();
    private final Timer clock;
    private String mailbox = "";
    private long shownRevision = -1;
    private SessionState serverState;

    public ConsolePanel(String service, ClientModel model, GuiManager manager) {
        super(new BorderLayout(4, 4));
        this.service = service;
        this.model = model;
        setName("console");
        setBorder(BorderFactory.createTitledBorder("Console — live"));
        badge.setName("consoleBadge");
        text.setName("consoleArea");
        text.setEditable(false);
        text.setFont(new Font(Font.MONOSPACED, Font.PLAIN, text.getFont().getSize()));
        search.setName("consoleSearch");
        search.setToolTipText("Show only the lines that contain this text");
        search.getDocument().addDocumentListener(new DocumentListener() {
            @Override
            public void insertUpdate(DocumentEvent e) {
                searchChanged();
            }

            @Override
            public void removeUpdate(DocumentEvent e) {
                searchChanged();
            }

            @Override
            public void changedUpdate(DocumentEvent e) {
                searchChanged();
            }
        });
        JButton older = new JButton("Older");
        older.setName("consoleOlder");
        older.setToolTipText("Fetch earlier lines from the server's transcript (?history)");
        older.addActionListener(e -> manager.loadHistory(mailbox));
        JPanel top = new JPanel(new BorderLayout(4, 0));
        JPanel tools = new JPanel(new FlowLayout(FlowLayout.RIGHT, 4, 0));
        tools.add(matches);
        tools.add(new JLabel("Find:"));
        tools.add(search);
        tools.add(older);
        top.add(badge, BorderLayout.CENTER);
        top.add(tools, BorderLayout.EAST);
        add(top, BorderLayout.NORTH);
        add(new JScrollPane(text), BorderLayout.CENTER);
        add(keyBar(manager), BorderLayout.SOUTH);
        model.console().addListener(changed -> {
            if (changed.equals(mailbox)) {
                repaintConsole();
            }
        });
        // "last contact N min ago" moves on by itself.
        clock = new Timer(30_000, e -> showBadge());
        clock.start();
    }

    /** The keys a Slocum pilot presses at surfacing; the link decides which it allows (docs/serial.md#control-keys). */
    static final List<String> KEYS = List.of("ctrl-c", "ctrl-r", "ctrl-e", "ctrl-f");

    /** A button per key: each sends {@code ?key MAILBOX KEY}, whose reply (the vehicle's answer) shows in the COM panel. */
    private JPanel keyBar(GuiManager manager) {
        JPanel bar = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        bar.setName("consoleKeys");
        bar.add(new JLabel("Send key:"));
        for (String key : KEYS) {
            JButton b = new JButton("Ctrl-" + key.substring(5).toUpperCase(Locale.ROOT));
            b.setName("key-" + key);
            b.setToolTipText("Press " + b.getText() + " on the vehicle (?key MAILBOX " + key + ")");
            b.addActionListener(e -> {
                if (!mailbox.isEmpty()) {
                    manager.sendCommand(service, "?key " + mailbox + " " + key);
                }
            });
            bar.add(b);
        }
        return bar;
    }

    /** Follows the service's target and its status; on the event thread. */
    public void update(ServiceModel m) {
        String target = m.target();
        serverState = m.mailboxes().stream().filter(s -> s.address().equals(target)).map(MailboxStatus::session)
                .filter(Objects::nonNull).findFirst().orElse(null);
        if (!target.equals(mailbox)) {
            mailbox = target;
            shownRevision = -1;
            setBorder(BorderFactory.createTitledBorder("Console — live" + (target.isEmpty() ? "" : ": " + handle(target))));
        }
        repaintConsole();
    }

    private String handle(String address) {
        return address.startsWith(service) ? address.substring(service.length()) : address;
    }

    private void repaintConsole() {
        long rev = model.console().revision(mailbox);
        if (rev != shownRevision) {
            shownRevision = rev;
            StringBuilder b = new StringBuilder();
            String find = search.getText().strip().toLowerCase(Locale.ROOT);
            List<ConsoleEntry> all = model.console().entries(mailbox);
            int shown = 0;
            for (ConsoleEntry e : all) {
                String line = ConsoleModel.text(e);
                if (find.isEmpty() || line.toLowerCase(Locale.ROOT).contains(find)) {
                    b.append(line).append('\n');
                    shown++;
                }
            }
            matches.setText(find.isEmpty() ? "" : shown + " of " + all.size());
            text.setText(b.toString());
            text.setCaretPosition(text.getDocument().getLength());
        }
        showBadge();
    }

    /** The server's state for the MailBox, brought up to date by the console's own entries since. */
    SessionState state() {
        SessionState s = serverState;
        for (ConsoleEntry e : model.console().entries(mailbox)) {
            s = SessionStates.apply(s, e);
        }
        return s;
    }

    private void showBadge() {
        String b = ConsoleModel.badge(state(), Instant.now());
        badge.setText(b.isEmpty() ? (mailbox.isEmpty() ? "no MailBox picked" : "nothing heard from it yet") : b);
    }

    private void searchChanged() {
        shownRevision = -1;
        repaintConsole();
    }

    public String consoleText() {
        return text.getText();
    }

    public String badgeText() {
        return badge.getText();
    }

    @Override
    public void removeNotify() {
        clock.stop();
        super.removeNotify();
    }
}
