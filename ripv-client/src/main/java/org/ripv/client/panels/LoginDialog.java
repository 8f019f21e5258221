package org.ripv.client.panels;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.Frame;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.net.ConnectException;
import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionException;
import java.util.prefs.Preferences;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JPasswordField;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import javax.swing.UIManager;
import org.ripv.messages.SessionInfo;

/**
 * The log-in dialog: server ({@code host[:port]}), user and password. It remembers the last
 * server and user in {@link Preferences}, never the password. A refused log-in shows the
 * server's reason and keeps the dialog open.
 */
public final class LoginDialog extends JDialog {
    /** Port of a RIPVServer when none is given. */
    public static final int DEFAULT_PORT = 4444;

    /** Connects and logs in, off the event thread. */
    @FunctionalInterface
    public interface LogIn {
        CompletableFuture<SessionInfo> logIn(String host, int port, String user, char[] password);
    }

    private final JTextField server = new JTextField(22);
    private final JTextField user = new JTextField(22);
    private final JPasswordField password = new JPasswordField(22);
    private final JLabel message = new JLabel(" ");
    private final JButton ok = new JButton("Log in");
    private final Preferences prefs;
    private final LogIn action;
    private SessionInfo session;

    public LoginDialog(Frame owner, Preferences prefs, LogIn action) {
        super(owner, "RIPV — log in", true);
        this.prefs = prefs;
        this.action = action;
        setName("loginDialog");
        server.setName("serverField");
        user.setName("userField");
        password.setName("passwordField");
        message.setName("loginMessage");
        ok.setName("loginButton");
        server.setText(prefs.get("server", "localhost:" + DEFAULT_PORT));
        user.setText(prefs.get("user", System.getProperty("user.name", "")));
        server.setToolTipText("The RIPVServer: host or host:port (port " + DEFAULT_PORT + " when omitted)");

        JPanel form = new JPanel(new GridBagLayout());
        form.setBorder(BorderFactory.createEmptyBorder(10, 10, 4, 10));
        row(form, 0, "Server:", server);
        row(form, 1, "User:", user);
        row(form, 2, "Password:", password);
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 0;
        c.gridy = 3;
        c.gridwidth = 2;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.insets = new Insets(6, 0, 0, 0);
        form.add(message, c);

        JButton cancel = new JButton("Cancel");
        cancel.addActionListener(e -> dispose());
        ok.addActionListener(e -> submit());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(cancel);
        buttons.add(ok);
        getRootPane().setDefaultButton(ok);
        getContentPane().add(form, BorderLayout.CENTER);
        getContentPane().add(buttons, BorderLayout.SOUTH);
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        pack();
        setLocationRelativeTo(owner);
    }

    private static void row(JPanel p, int y, String label, Component field) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 0;
        c.gridy = y;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(2, 0, 2, 8);
        p.add(new JLabel(label), c);
        c.gridx = 1;
        c.weightx = 1;
        c.fill = GridBagConstraints.HORIZONTAL;
        p.add(field, c);
    }

    /** Fills the fields (the demo's auto log-in); null leaves a field as it is. */
    public void fill(String serverText, String userText, char[] pw) {
        if (serverText != null) {
            server.setText(serverText);
        }
        if (userText != null) {
            user.setText(userText);
        }
        if (pw != null) {
            password.setText(new String(pw));
        }
    }

    /** Presses "Log in". */
    public void submit() {
        HostPort hp;
        try {
            hp = HostPort.parse(server.getText(), DEFAULT_PORT);
        } catch (IllegalArgumentException e) {
            error(e.getMessage());
            return;
        }
        String u = user.getText().strip();
        if (u.isEmpty()) {
            error("enter a user name");
            return;
        }
        char[] pw = password.getPassword();
        ok.setEnabled(false);
        message.setForeground(UIManager.getColor("Label.foreground"));
        message.setText("connecting to " + hp + "...");
        CompletableFuture<SessionInfo> f = action.logIn(hp.host(), hp.port(), u, pw);
        Arrays.fill(pw, '\0');
        f.whenComplete((s, e) -> SwingUtilities.invokeLater(() -> {
            ok.setEnabled(true);
            if (e != null) {
                Throwable t = e instanceof CompletionException && e.getCause() != null ? e.getCause() : e;
                error(t instanceof ConnectException ? "cannot reach " + hp + ": connection refused"
                        : t.getMessage() == null ? t.toString() : t.getMessage());
                password.setText("");
                password.requestFocusInWindow();
                return;
            }
            session = s;
            prefs.put("server", server.getText().strip());
            prefs.put("user", u);
            dispose();
        }));
    }

    private void error(String text) {
        message.setForeground(new Color(0xB00020));
        message.setText("<html>" + escape(text) + "</html>");
        pack();
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** The session after a successful log-in, or null (cancelled, or still open). */
    public SessionInfo session() {
        return session;
    }

    /** The dialog's message line. */
    public String message() {
        return message.getText();
    }
}
