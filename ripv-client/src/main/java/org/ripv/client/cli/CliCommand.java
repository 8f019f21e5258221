package org.ripv.client.cli;

import java.io.BufferedReader;
import java.io.Console;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import javax.net.SocketFactory;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.Failover;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.client.handlers.ServerTrustOptions;
import org.ripv.client.handlers.Tls;
import org.ripv.client.handlers.TrustStoreOptions;
import org.ripv.client.cli.shell.Shell;
import org.ripv.failover.ServerList;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code ripv cli}: the headless client, for people at a terminal and for scripts. On a terminal
 * without {@code --exec} or {@code --follow} it is interactive ({@link Shell}); otherwise it runs the {@code --exec}
 * lines or standard input's. Exit codes: 0 every reply OK (interactive: the user ended it),
 * 1 some reply was an ERROR, 2 bad command line, 3 could not connect or log in, or lost the connection.
 */
@Command(name = "cli", mixinStandardHelpOptions = true,
        description = {"Talks to a RIPVServer in the COM panel's command language: interactively on a terminal "
                + "(prompt, history, Tab completion; help lists the commands), or from --exec lines or standard input.",
                "The password comes from --password-file, else $RIPV_PASSWORD, else the terminal (not echoed)."})
public final class CliCommand implements Callable<Integer> {
    public static final int EXIT_ERROR_REPLY = ExitCodes.ERROR_REPLY;
    public static final int EXIT_NO_SESSION = ExitCodes.NO_SESSION;

    @Option(names = "--server", required = true, paramLabel = "HOST[:PORT][,HOST2[:PORT]]",
            description = "The server (port 4444 unless given); several, comma-separated (an active server and its standbys):"
                    + " the first that answers.")
    String server;
    @Option(names = "--user", required = true, description = "User name.")
    String user;
    @Mixin
    PasswordOptions password;
    @Option(names = "--json", description = "One JSON object per reply line.")
    boolean json;
    @Option(names = "--exec", paramLabel = "LINE", description = "A line to run (repeatable); without any, lines come from standard input.")
    List<String> exec;
    @Option(names = "--tls", hidden = true, description = "Connect over TLS (the default; kept for old scripts).")
    boolean tls;
    @Mixin
    ServerTrustOptions trust;
    @Mixin
    TrustStoreOptions truststore;
    @Option(names = "--history", paramLabel = "FILE", description = "The interactive CLI's history (default ~/.ripv/history).")
    Path history;

    @Option(names = "--follow", paramLabel = "MAILBOX", description = "Print the MailBox's live console (lines, commands, events) until Ctrl-C, after any --exec lines;"
            + " MAILBOX is a full address or a vehicle's name (sim01).")
    String follow;
    @Option(names = "--no-reconnect", description = "With --follow or on a terminal: end (exit 3) when the connection is lost, instead"
            + " of logging in again to the server (or the first of --server's list that answers) and going on.")
    boolean noReconnect;
    @Option(names = "--timeout", defaultValue = "3600", description = "Seconds to wait for one reply (default ${DEFAULT-VALUE}; the server fails silent requests sooner).")
    long timeout;

    private final InputStream in;
    private final PrintStream out;
    private final PrintStream err;

    public CliCommand() {
        this(System.in, System.out, System.err);
    }

    public CliCommand(InputStream in, PrintStream out, PrintStream err) {
        this.in = in;
        this.out = out;
        this.err = err;
    }

    @Override
    public Integer call() throws IOException {
        ServerList servers;
        try {
            servers = ServerList.parse(server, 4444);
        } catch (IllegalArgumentException e) {
            err.println("Error: " + e.getMessage());
            return 2;
        }
        String host = servers.first().host();
        char[] pw;
        try {
            pw = password(host);
        } catch (PasswordFile.Unusable | IllegalArgumentException e) {
            err.println("Error: " + e.getMessage());
            return 2;
        }
        if (pw == null) {
            err.println("Error: no password: give --password-file, set RIPV_PASSWORD, or run on a terminal to be asked");
            return 2;
        }
        if (trust.plain() && (truststore.given() || tls)) {
            err.println("Error: --plain excludes --tls and --truststore");
            return 2;
        }
        ClientSocketHandler client;
        SocketFactory trusted;
        try {
            trusted = truststore.socketFactory();
            client = connect(servers, trusted);
        } catch (IOException e) {
            err.println("Error: cannot connect to " + servers + ": " + e.getMessage());
            return EXIT_NO_SESSION;
        }
        // --follow runs all night, a terminal session for hours: both keep the password to log in again
        // after a server restart or a standby's takeover.
        char[] again = (follow != null || interactive()) && !noReconnect ? pw.clone() : null;
        try (client) {
            try {
                client.login(user, pw);
            } catch (RipvErrorException e) {
                err.println("Error: log-in refused: " + e.getMessage());
                return EXIT_NO_SESSION;
            } finally {
                Arrays.fill(pw, '\0');
            }
            CliSession session = new CliSession(client, out, err, json, Duration.ofSeconds(timeout));
            Reconnect reconnect = again == null ? null : () -> {
                ClientSocketHandler c = connect(servers, trusted);
                char[] p = again.clone();
                try {
                    c.login(user, p);
                    return c;
                } catch (Exception e) {
                    c.close();
                    throw e;
                } finally {
                    Arrays.fill(p, '\0');
                }
            };
            try {
                if (interactive()) {
                    return new Shell(session, client, history != null ? history : Shell.defaultHistory(), err, reconnect,
                            c -> new CliSession(c, out, err, json, Duration.ofSeconds(timeout))).run();
                }
                if (exec != null && !exec.isEmpty()) {
                    for (String line : exec) {
                        if (!session.run(line)) {
                            break;
                        }
                    }
                } else if (follow == null) {
                    BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
                    String line;
                    while ((line = r.readLine()) != null && session.run(line)) {
                        out.flush();
                    }
                }
            } catch (IOException e) {
                err.println("Error: " + e.getMessage());
                return EXIT_NO_SESSION;
            }
            out.flush();
            if (follow != null) {
                try {
                    return new ConsoleFollower(client, out, err, json, reconnect).follow(follow,
                            Duration.ofSeconds(Math.min(timeout, 60)));
                } catch (IOException e) {
                    err.println("Error: " + e.getMessage());
                    return EXIT_NO_SESSION;
                }
            }
            return session.anyError() ? EXIT_ERROR_REPLY : 0;
        } finally {
            if (again != null) {
                Arrays.fill(again, '\0');
            }
        }
    }

    /** Connects to the first server of the list that answers; a standby is trusted only as Tls#trustOnFirstUse says for lists. */
    private ClientSocketHandler connect(ServerList servers, SocketFactory trusted) throws IOException {
        return new Failover(servers, err::println).connect((h, p) -> ClientSocketHandler.connect(h, p,
                trust.plain() ? SocketFactory.getDefault() : trusted != null ? trusted
                        : Tls.trustOnFirstUse(h, p, trust.knownHosts() != null ? trust.knownHosts() : Tls.defaultKnownHosts(), err::println, servers),
                servers.size() > 1 ? Failover.CONNECT : Duration.ofSeconds(10)));
    }

    /** A person at a terminal, with no --exec lines and nothing to --follow: the interactive CLI. */
    private boolean interactive() {
        return in == System.in && System.console() != null && (exec == null || exec.isEmpty()) && follow == null;
    }

    private char[] password(String host) throws IOException {
        if (password.any()) {
            return password.given(err, "--password-file, $RIPV_PASSWORD or let the CLI ask");
        }
        String env = System.getenv("RIPV_PASSWORD");
        if (env != null) {
            return env.toCharArray();
        }
        Console console = in == System.in ? System.console() : null;
        return console == null ? null : console.readPassword("Password for %s@%s: ", user, host);
    }
}
