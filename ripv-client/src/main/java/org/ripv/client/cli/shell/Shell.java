package org.ripv.client.cli.shell;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import java.util.stream.Stream;
import org.jline.reader.Candidate;
import org.jline.reader.Completer;
import org.jline.reader.EndOfFileException;
import org.jline.reader.LineReader;
import org.jline.reader.LineReaderBuilder;
import org.jline.reader.ParsedLine;
import org.jline.reader.UserInterruptException;
import org.jline.terminal.Terminal;
import org.jline.terminal.TerminalBuilder;
import org.ripv.client.cli.CliSession;
import org.ripv.client.cli.ExitCodes;
import org.ripv.client.cli.Reconnect;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.naming.MailboxAddress;
import org.ripv.retry.Backoff;

/**
 * The interactive {@code ripv cli} on a terminal: a prompt with user, server and MailBox
 * ({@code alice@shore ru29> }), line editing, history kept across sessions, Tab completion
 * ({@link Completions}). Ctrl-C at the prompt clears the line; while a request runs it stops
 * waiting for it ({@link CliSession#cancel()}) and the prompt comes back. Ctrl-D or {@code quit}
 * ends the session with exit status 0.
 */
public final class Shell {
    /** Where history goes unless {@code --history} says otherwise. */
    public static Path defaultHistory() {
        return Path.of(System.getProperty("user.home"), ".ripv", "history");
    }

    /** How long the shell keeps trying to log in again before it gives up (a standby takes over within 15 s). */
    static final Duration RECONNECT_FOR = Duration.ofSeconds(30);

    private volatile CliSession session;
    private volatile ClientSocketHandler client;
    private final Path history;
    private final PrintStream err;
    private final Reconnect reconnect;
    private final Function<ClientSocketHandler, CliSession> sessions;
    private final List<ClientSocketHandler> made = new ArrayList<>();

    public Shell(CliSession session, ClientSocketHandler client, Path history, PrintStream err) {
        this(session, client, history, err, null, null);
    }

    /**
     * With {@code reconnect}, a lost connection is made again (the same server restarted, or a
     * standby of the list) and the session goes on in the MailBox it was in; {@code sessions}
     * makes the new connection's session.
     */
    public Shell(CliSession session, ClientSocketHandler client, Path history, PrintStream err, Reconnect reconnect,
                 Function<ClientSocketHandler, CliSession> sessions) {
        this.session = session;
        this.client = client;
        this.history = history;
        this.err = err;
        this.reconnect = reconnect;
        this.sessions = sessions;
    }

    /**
     * Reads and runs lines until Ctrl-D, {@code quit} or a lost connection.
     *
     * @return 0 when the user ended the session, 3 when the connection was lost
     */
    public int run() throws IOException {
        prepareHistory();
        try (Terminal terminal = TerminalBuilder.builder().system(true).name("ripv").build()) {
            TabCompleter completer = new TabCompleter(new Completions(new ServerFacts(client)));
            LineReader reader = LineReaderBuilder.builder().terminal(terminal).appName("ripv")
                    .completer(completer)
                    .variable(LineReader.HISTORY_FILE, history)
                    .option(LineReader.Option.DISABLE_EVENT_EXPANSION, true) // '!' belongs to SQL and vehicles
                    .option(LineReader.Option.HISTORY_IGNORE_DUPS, true)
                    .build();
            terminal.handle(Terminal.Signal.INT, signal -> session.cancel());
            err.println("Connected to " + client.server() + " as " + user() + ". help lists the commands, Tab completes,"
                    + " Ctrl-C stops waiting for a reply, Ctrl-D ends.");
            try {
                while (true) {
                    String line;
                    try {
                        line = reader.readLine(prompt(user(), client.server(), session.mailbox()));
                    } catch (UserInterruptException e) {
                        continue; // Ctrl-C at the prompt: a fresh line
                    } catch (EndOfFileException e) {
                        break;
                    }
                    if (!client.isOpen() && !reconnected(completer)) { // lost while waiting at the prompt
                        return ExitCodes.NO_SESSION;
                    }
                    if (!session.run(line)) {
                        break;
                    }
                    if (!client.isOpen()) {
                        if (!reconnected(completer)) {
                            return ExitCodes.NO_SESSION;
                        }
                        err.println("If '" + line + "' did not reach the server, run it again.");
                    }
                }
            } finally {
                reader.getHistory().save();
                for (ClientSocketHandler c : made) {
                    c.close();
                }
            }
        }
        return 0;
    }

    /** Logs in again (growing back-off, for {@link #RECONNECT_FOR}) and goes on in the same MailBox; false when it could not. */
    private boolean reconnected(TabCompleter completer) {
        String lost = client.server();
        if (reconnect == null) {
            err.println("Error: the connection to " + lost + " was lost");
            return false;
        }
        err.println("The connection to " + lost + " was lost; logging in again...");
        long end = System.nanoTime() + RECONNECT_FOR.toNanos();
        Backoff backoff = new Backoff(Duration.ofMillis(500), Duration.ofMillis(5000));
        Exception last = null;
        while (System.nanoTime() < end) {
            try {
                ClientSocketHandler c = reconnect.connect();
                made.add(c);
                String mailbox = session.mailbox();
                client = c;
                session = sessions.apply(c);
                completer.completions = new Completions(new ServerFacts(c));
                if (!mailbox.isEmpty()) {
                    session.run("use " + mailbox);
                }
                err.println("Logged in again to " + c.server() + ".");
                return true;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            } catch (Exception e) {
                last = e;
            }
            try {
                Thread.sleep(backoff.nextMillis());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        err.println("Error: could not log in again within " + RECONNECT_FOR.toSeconds() + " s"
                + (last == null ? "" : ": " + last.getMessage()));
        return false;
    }

    private String user() {
        return client.session() == null ? "?" : client.session().user();
    }

    /** {@code alice@shore ru29> }: the server's host without its port, the MailBox's handle. */
    static String prompt(String user, String server, String mailbox) {
        String host = server;
        int colon = host.lastIndexOf(':');
        if (colon > 0 && host.indexOf(':') == colon) {
            host = host.substring(0, colon);
        }
        String box = "";
        if (!mailbox.isEmpty()) {
            try {
                box = " " + MailboxAddress.parse(mailbox).handle();
            } catch (IllegalArgumentException e) {
                box = " " + mailbox;
            }
        }
        return user + "@" + host + box + "> ";
    }

    /** The history file and its folder, readable by the user only (commands can be private). */
    private void prepareHistory() throws IOException {
        Path dir = history.toAbsolutePath().getParent();
        if (dir != null && !Files.isDirectory(dir)) {
            Files.createDirectories(dir);
        }
        if (!Files.exists(history)) {
            Files.createFile(history);
            try {
                Files.setPosixFilePermissions(history, PosixFilePermissions.fromString("rw-------"));
            } catch (UnsupportedOperationException e) {
                // not a POSIX file system
            }
        }
    }

    /** JLine's side of {@link Completions}, and local file names after {@code put}. */
    private final class TabCompleter implements Completer {
        private volatile Completions completions;

        TabCompleter(Completions completions) {
            this.completions = completions;
        }

        @Override
        public void complete(LineReader reader, ParsedLine line, List<Candidate> candidates) {
            List<String> words = line.words();
            int index = line.wordIndex();
            if (index == 1 && !words.isEmpty() && words.get(0).equals("put")) {
                localFiles(line.word(), candidates);
                return;
            }
            for (String c : completions.candidates(words, index, session.mailbox())) {
                boolean prefixOnly = c.endsWith(":");
                String group = index == 0 ? Completions.group(c) : null;
                // the CLI's own words say so beside them: a line starting with one never reaches the vehicle
                String descr = Completions.OWN_GROUP.equals(group) ? Completions.OWN_MARK : null;
                candidates.add(new Candidate(c, c, group, descr, null, null, !prefixOnly));
            }
        }

        private void localFiles(String typed, List<Candidate> candidates) {
            int slash = typed.lastIndexOf('/');
            String dirPart = slash >= 0 ? typed.substring(0, slash + 1) : "";
            Path dir = Path.of(dirPart.isEmpty() ? "." : dirPart.startsWith("~/")
                    ? System.getProperty("user.home") + dirPart.substring(1) : dirPart);
            List<Candidate> found = new ArrayList<>();
            try (Stream<Path> s = Files.list(dir)) {
                s.forEach(p -> {
                    boolean isDir = Files.isDirectory(p);
                    String v = dirPart + p.getFileName() + (isDir ? "/" : "");
                    found.add(new Candidate(v, p.getFileName() + (isDir ? "/" : ""), null, null, null, null, !isDir));
                });
            } catch (IOException e) {
                return;
            }
            candidates.addAll(found);
        }
    }
}
