package org.ripv.client.gui;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import java.util.prefs.Preferences;
import javax.swing.SwingUtilities;
import org.ripv.client.cli.PasswordFile;
import org.ripv.client.cli.PasswordOptions;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.ServerTrustOptions;
import org.ripv.client.handlers.Tls;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.HostPort;
import org.ripv.client.panels.LoginDialog;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code ripv client [HOST[:PORT]] [--user U] [--password-file F | --password P]}: opens the
 * RIPVClient window and its log-in dialog, filled with what was given. With a password (the
 * demo) it logs in at once. Without a display it says to use {@code ripv cli} instead.
 *
 * <p>Exit codes: 0 when the window was closed, 1 when the password file cannot be read,
 * 2 for a usage error or no display.
 */
@Command(name = "client", mixinStandardHelpOptions = true,
        description = "Opens the RIPV operator GUI (log-in dialog, services, COM/MAM/FIM/DAB/DAV panels);"
                + " with --password-file (or --password) it logs in at once.",
        exitCodeOnInvalidInput = 2)
public final class ClientCommand implements Callable<Integer> {
    /** Exit code: no display (headless) or bad arguments. */
    public static final int EXIT_USAGE = 2;

    @Parameters(index = "0", arity = "0..1", paramLabel = "HOST[:PORT][,HOST2[:PORT]]",
            description = "The RIPVServer to log in to (default: the last one used, else localhost:4444); several,"
                    + " comma-separated (an active server and its standbys): whichever answers, on every reconnect too.")
    String server;

    @Option(names = "--user", paramLabel = "USER", description = "User name (default: the last one used).")
    String user;

    @Mixin
    PasswordOptions password;

    @Mixin
    ServerTrustOptions trust;

    private final PrintStream err;

    public ClientCommand() {
        this(System.err);
    }

    /** With the stream errors go to (tests). */
    public ClientCommand(PrintStream err) {
        this.err = err;
    }

    @Override
    public Integer call() throws Exception {
        if (server != null) {
            try {
                HostPort.parse(server, LoginDialog.DEFAULT_PORT);
            } catch (IllegalArgumentException e) {
                err.println("Error: " + e.getMessage());
                return EXIT_USAGE;
            }
        }
        char[] pw;
        try {
            pw = password.given(err, "--password-file");
        } catch (IllegalArgumentException e) {
            err.println("Error: " + e.getMessage());
            return EXIT_USAGE;
        } catch (PasswordFile.Unusable e) {
            err.println("Error: " + e.getMessage());
            return 1;
        }
        if (GraphicsEnvironment.isHeadless()) {
            noDisplay("DISPLAY unset or java.awt.headless=true");
            return EXIT_USAGE;
        }
        if (trust.knownHosts() != null) {
            System.setProperty(Tls.KNOWN_HOSTS_PROPERTY, trust.knownHosts().toString());
        }
        RIPVClient client;
        try {
            client = open(server, user, pw, trust.plain());
        } catch (AWTError | HeadlessException e) {
            // DISPLAY is set but no X server answers there.
            noDisplay(e.getMessage());
            return EXIT_USAGE;
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof AWTError || e.getCause() instanceof HeadlessException) {
                noDisplay(e.getCause().getMessage());
                return EXIT_USAGE;
            }
            throw e;
        }
        client.closedLatch().await();
        return 0;
    }

    private void noDisplay(String why) {
        String target = server == null ? "HOST[:PORT]" : server;
        err.println("Error: there is no display for the RIPV GUI (" + why + ").");
        err.println("Use the command-line client instead, e.g.:");
        err.println("  ripv cli --server " + target + " --user " + (user == null ? "USER" : user)
                + " --password-file FILE");
    }

    /**
     * Opens the window with FlatLaf and the log-in dialog, on the event thread; returns once it
     * is showing. A non-null password logs in at once.
     */
    public static RIPVClient open(String server, String user, char[] password) throws Exception {
        return open(server, user, password, false);
    }

    /** As {@link #open(String, String, char[])}; {@code plain} connects without TLS. */
    public static RIPVClient open(String server, String user, char[] password, boolean plain) throws Exception {
        AtomicReference<RIPVClient> ref = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            Preferences prefs = Preferences.userNodeForPackage(RIPVClient.class);
            Theme.saved(prefs).install(); // the theme chosen last time (View menu)
            GuiManager manager = plain ? new GuiManager(new ClientModel(), SwingUtilities::invokeLater,
                    ClientSocketHandler::connectPlain, GuiManager.Timings.DEFAULT)
                    : new GuiManager(new ClientModel());
            RIPVClient client = new RIPVClient(manager, prefs);
            client.show();
            client.showLogin(server, user, password, password != null);
            ref.set(client);
        });
        return ref.get();
    }

    /** The first line of the file, without its line end. */
    static char[] readPassword(Path file) throws IOException {
        return PasswordFile.read(file);
    }

    public static void main(String[] args) {
        System.exit(new CommandLine(new ClientCommand()).execute(args));
    }
}
