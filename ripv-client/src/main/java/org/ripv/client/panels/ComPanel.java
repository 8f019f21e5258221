package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Font;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.event.ActionEvent;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.util.List;
import java.util.Locale;
import javax.swing.AbstractAction;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.UIManager;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.managers.ProgressText;
import org.ripv.client.managers.ServiceModel;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;

/**
 * The COmmunications Management panel (thesis 4.1.3.1, figure 4.6): the command line (Enter
 * sends, Up/Down recall), the priority selector, the status labels Talking To [TT], Last Action
 * [LA], Priority [PR] and Service Status [SS], the reply area [RA] and a progress bar for long
 * commands (YMODEM transfers).
 */
public final class ComPanel extends JPanel {
    private final String service;
    private final GuiManager manager;
    private final JTextField command = new JTextField();
    private final JComboBox<Priority> priority = new JComboBox<>(Priority.values());
    private final JLabel talkingTo = value("talkingTo");
    private final JLabel lastAction = value("lastAction");
    private final JLabel priorityLabel = value("priorityLabel");
    private final JLabel serviceStatus = value("serviceStatus");
    private final JTextArea replies = new JTextArea();
    private final RunningPanel running;
    private final CommandHistory history = new CommandHistory();
    private long shownRevision = -1;
    private String shownTarget;
    private boolean updating;
    private List<ServiceModel.Running> shownRunning = List.of();

    public ComPanel(String service, GuiManager manager) {
        super(new BorderLayout(4, 4));
        this.service = service;
        this.manager = manager;
        this.running = new RunningPanel(service, manager);
        setName("com");
        setBorder(BorderFactory.createTitledBorder("COM — communications"));

        JPanel labels = new JPanel(new GridBagLayout());
        addLabel(labels, 0, "TT", "Talking To: the MailBox plain commands go to", talkingTo);
        addLabel(labels, 1, "LA", "Last Action: the last command sent", lastAction);
        addLabel(labels, 2, "PR", "Priority: the inbox the next command waits in (normal, priority, urgent)", priorityLabel);
        addLabel(labels, 3, "SS", "Service Status: whether the MailBox can take commands now", serviceStatus);

        replies.setName("replyArea");
        replies.setEditable(false);
        replies.setLineWrap(true); // long replies wrap instead of hiding past the right edge
        replies.setWrapStyleWord(true);
        replies.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        replies.setToolTipText("RA: the Reply Area — replies, errors and progress");
        JScrollPane scroll = new JScrollPane(replies);
        scroll.setPreferredSize(new Dimension(420, 180));

        command.setName("commandField");
        command.setToolTipText("Command for the MailBox (dir, SQL, vis:FILE) or ?server command; Enter sends, Up/Down recall");
        command.addActionListener(e -> send());
        command.addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) {
                String recalled = switch (e.getKeyCode()) {
                    case KeyEvent.VK_UP -> history.up(command.getText());
                    case KeyEvent.VK_DOWN -> history.down();
                    default -> null;
                };
                if (recalled != null) {
                    command.setText(recalled);
                    e.consume();
                }
            }
        });
        priority.setName("priorityBox");
        JLabel priorityKey = new JLabel("Priority:");
        priorityKey.setDisplayedMnemonic(KeyEvent.VK_P);
        priorityKey.setLabelFor(priority);
        priority.setToolTipText("PR: priority of the next command");
        priority.addActionListener(e -> {
            if (!updating) {
                manager.setPriority(service, (Priority) priority.getSelectedItem());
            }
        });
        JButton send = new JButton("Send");
        send.setMnemonic(KeyEvent.VK_N);
        send.setName("sendButton");
        send.addActionListener(e -> send());
        JButton clear = Buttons.button("Clear", KeyEvent.VK_E, "clearButton",
                "Empty the reply area (Alt+E)", e -> manager.clearTranscript(service));

        JPanel line = new JPanel(new BorderLayout(4, 0));
        JLabel commandLabel = new JLabel("Command:");
        commandLabel.setDisplayedMnemonic(KeyEvent.VK_C); // Alt+C: back to the command line
        commandLabel.setLabelFor(command);
        line.add(commandLabel, BorderLayout.WEST);
        line.add(command, BorderLayout.CENTER);
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT, 4, 0));
        buttons.add(priorityKey);
        buttons.add(priority);
        buttons.add(send);
        buttons.add(clear);
        line.add(buttons, BorderLayout.EAST);

        running.setVisible(false);
        // Escape anywhere in COM cancels the newest running request, as its Cancel button does.
        getInputMap(WHEN_ANCESTOR_OF_FOCUSED_COMPONENT).put(KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0),
                "ripv-cancel");
        getActionMap().put("ripv-cancel", new AbstractAction() {
            @Override
            public void actionPerformed(ActionEvent e) {
                List<ServiceModel.Running> now = shownRunning;
                if (!now.isEmpty()) {
                    manager.cancel(service, now.get(now.size() - 1).messageId());
                }
            }
        });

        JPanel south = new JPanel(new BorderLayout(0, 2));
        south.add(running, BorderLayout.NORTH);
        south.add(line, BorderLayout.SOUTH);

        add(labels, BorderLayout.NORTH);
        add(scroll, BorderLayout.CENTER);
        add(south, BorderLayout.SOUTH);
    }

    private static JLabel value(String name) {
        JLabel l = new JLabel(" ");
        l.setName(name);
        return l;
    }

    private static void addLabel(JPanel p, int row, String abbrev, String tip, JLabel value) {
        JLabel key = new JLabel(abbrev + ":");
        key.setToolTipText(tip);
        key.setFont(key.getFont().deriveFont(Font.BOLD));
        value.setToolTipText(tip);
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = row;
        c.gridx = 0;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(1, 2, 1, 6);
        p.add(key, c);
        c.gridx = 1;
        c.weightx = 1;
        c.fill = GridBagConstraints.HORIZONTAL;
        p.add(value, c);
    }

    private void send() {
        String text = command.getText();
        if (text.isBlank()) {
            return;
        }
        manager.sendCommand(service, text);
        command.setText("");
    }

    /** Repaints from the model; on the event thread. */
    public void update(ServiceModel m) {
        updating = true;
        try {
            talkingTo.setText(m.target().isEmpty() ? "(no MailBox picked)" : m.target());
            lastAction.setText(m.lastAction().isEmpty() ? " " : m.lastAction());
            priorityLabel.setText(m.priority().name().toLowerCase(Locale.ROOT) + " (" + m.priority().level() + ")");
            priority.setSelectedItem(m.priority());
            serviceStatus.setText(m.serviceStatus().isEmpty() ? " " : m.serviceStatus());
            colourStatus();
            // A value too long for the panel shows whole in its tooltip.
            tip(talkingTo, "Talking To", m.target());
            tip(lastAction, "Last Action", m.lastAction());
            tip(serviceStatus, "Service Status", m.serviceStatus());
            if (m.transcriptRevision() != shownRevision) {
                replies.setText(m.transcriptText());
                replies.setCaretPosition(replies.getDocument().getLength());
                shownRevision = m.transcriptRevision();
                // Something was sent or answered: recall starts again from the newest command.
                history.reset(m.history());
            }
            if (!m.target().equals(shownTarget)) {
                shownTarget = m.target(); // each MailBox has its own history
                history.reset(m.history());
            }
            running.update(m);
            shownRunning = m.running();
        } finally {
            updating = false;
        }
    }

    /** SS in red when the MailBox cannot take commands, in the current theme's red. */
    private void colourStatus() {
        serviceStatus.setForeground(serviceStatus.getText().startsWith("not") ? Colors.error()
                : UIManager.getColor("Label.foreground"));
    }

    /** A theme change: SS takes the new theme's red (it was set for the old one). */
    @Override
    public void updateUI() {
        super.updateUI();
        if (serviceStatus != null) {
            SwingUtilities.invokeLater(this::colourStatus); // after the labels took the new look
        }
    }

    private static void tip(JLabel label, String what, String value) {
        label.setToolTipText(value.isBlank() ? what : what + ": " + value);
    }

    /** "ymodem:get LOG  12 KB / 64 KB  1 KB/s  0:52 left": the COM progress bar's words. */
    static String progressText(Progress p) {
        return ProgressText.of(p);
    }

    /** The running requests' progress bars' words, oldest first. */
    public List<String> runningTexts() {
        return running.texts();
    }

    /** Puts the keyboard focus in the command line (when its tab is shown). */
    public void focusCommand() {
        SwingUtilities.invokeLater(command::requestFocusInWindow);
    }

    /** What the command line holds. */
    public String commandText() {
        return command.getText();
    }

    /** Empties the command line. */
    public void clearCommand() {
        command.setText("");
    }

    /** The reply area's text (for tests and copy). */
    public String replyText() {
        return replies.getText();
    }

    /** What the SS label shows (for tests). */
    public String serviceStatusText() {
        return serviceStatus.getText();
    }
}
