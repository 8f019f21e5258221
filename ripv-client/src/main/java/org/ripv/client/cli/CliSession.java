package org.ripv.client.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxList;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.naming.MailboxAddress;

/**
 * Runs lines of the COM panel's command language against a connected server: {@code ?...}
 * server commands, {@code use MAILBOX}, {@code priority LEVEL}, {@code put LOCALFILE},
 * {@code get NAME [LOCALDIR]}, {@code send LINE} (LINE to the current MailBox verbatim, for a
 * vehicle command that shares a word with the CLI: {@code send put c_dive_target_depth 30},
 * {@code send exit}), and anything else as a command for the current MailBox.
 *
 * <p>{@link #cancel()} (Ctrl-C in the interactive CLI) stops waiting for the running request: a
 * transfer stops after its current chunk (an upload's part is dropped on the server); any other
 * request is cancelled on the server with {@code ?cancel ID}, whose answer is printed (withdrawn
 * before it ran, or the service asked to stop it; a service that cannot stop it says so), and
 * its late reply is ignored.
 */
public final class CliSession {
    private final ClientSocketHandler client;
    private final ReplyPrinter printer;
    private final PrintStream err;
    private final boolean json;
    private final Duration timeout;
    private String mailbox = "";
    private Priority priority = Priority.NORMAL;
    private boolean anyError;
    /** The last table or plot received, for {@code export}. */
    private final CliExport exports = new CliExport();
    /** The request being waited for, so that {@link #cancel()} can end the wait. */
    private volatile CompletableFuture<OutgoingServerMessage> waiting;
    /** The message id of the request being waited for, 0 for none (what {@code ?cancel} names). */
    private volatile long waitingId;
    private volatile boolean cancelled;

    public CliSession(ClientSocketHandler client, PrintStream out, PrintStream err, boolean json, Duration timeout) {
        this.client = client;
        this.printer = new ReplyPrinter(out, err, json);
        this.err = err;
        this.json = json;
        this.timeout = timeout;
    }

    /** True when any reply so far was an ERROR (the CLI then exits non-zero). */
    public boolean anyError() {
        return anyError;
    }

    public String mailbox() {
        return mailbox;
    }

    /** The first words that make a line the CLI's own (a vehicle command with one of them needs {@code send}). */
    public static final List<String> OWN_WORDS = List.of("use", "priority", "put", "get", "export", "key",
            "send", "help", "quit", "exit");

    /** The help of the CLI's own lines. */
    public static final String HELP = String.join("\n",
            "  Lines starting with one of the CLI's own words (" + String.join(", ", OWN_WORDS) + ") are the CLI's;",
            "  any other line goes to the current MailBox. send LINE sends a line that starts with one of them.",
            "  ?COMMAND                         a server command (?help lists them)",
            "  use MAILBOX                      send further lines to MAILBOX (a full address or its handle; ?mailboxes lists them)",
            "  priority normal|priority|urgent  the inbox further requests go to",
            "  put LOCALFILE [NAME] [--replace|--keep]",
            "                                   upload to the server's upload directory; when NAME is taken: replace it, or keep both",
            "  get NAME [LOCALDIR]              download from the server's download directory (default: the current directory)",
            "  export csv|json LOCALFILE        write the last query result to a local file (numbers as numbers, NULL as null)",
            "  export svg LOCALFILE             write the last plot (a vis: reply with data) as an SVG picture",
            "  send LINE                        send LINE to the current MailBox verbatim, even when it starts with",
            "                                   one of the CLI's words: send put c_dive_target_depth 30, send exit, send get m_battery",
            "  key KEY                          press a control key on the current MailBox's vehicle (ctrl-c, ctrl-r, …): ?key MAILBOX KEY",
            "  help                             this, and the current service's help",
            "  quit, exit                       end the session (Ctrl-D too); send exit leaves GliderDOS instead",
            "  anything else                    a command for the current MailBox");

    /**
     * Stops waiting for the running request (from another thread, e.g. a Ctrl-C handler). The
     * line that was running then reports that it was cancelled; the session stays usable.
     */
    public void cancel() {
        cancelled = true;
        CompletableFuture<OutgoingServerMessage> w = waiting;
        if (w != null) {
            w.cancel(false);
        }
    }

    /** Runs one line. Returns false for {@code quit}. */
    public boolean run(String rawLine) throws IOException {
        cancelled = false;
        String line = rawLine.strip();
        if (line.isEmpty() || line.startsWith("#")) {
            return true;
        }
        String[] w = line.split("\\s+", 2);
        String rest = w.length > 1 ? w[1].strip() : "";
        switch (w[0]) {
            case "quit", "exit" -> {
                return false;
            }
            case "help" -> help();
            case "use" -> use(rest);
            case "priority" -> {
                try {
                    priority = Priority.parse(rest);
                    local("priority " + priority.name().toLowerCase(Locale.ROOT));
                } catch (IllegalArgumentException e) {
                    localError(ErrorCode.BAD_REQUEST, e.getMessage());
                }
            }
            case "send" -> sendVerbatim(rawLine);
            case "put" -> put(rest);
            case "get" -> get(rest);
            case "export" -> export(rest);
            case "key" -> {
                // Ctrl-C at the terminal cancels the CLI's wait; a key for the vehicle is typed by name
                if (mailbox.isEmpty()) {
                    localError(ErrorCode.BAD_REQUEST, "no MailBox chosen for 'key " + rest + "': use MAILBOX first");
                } else if (rest.isEmpty() || rest.contains(" ")) {
                    localError(ErrorCode.BAD_REQUEST, "key takes one key name, e.g. key ctrl-c; got '" + rest + "'");
                } else {
                    send("", "?key " + mailbox + " " + rest);
                }
            }
            default -> {
                if (!line.startsWith("?") && mailbox.isEmpty()) {
                    localError(ErrorCode.BAD_REQUEST, "no MailBox chosen for '" + line + "': use MAILBOX first (?mailboxes lists them)");
                } else {
                    send(line.startsWith("?") ? "" : mailbox, line);
                }
            }
        }
        return true;
    }

    /** {@code send LINE}: LINE as typed (after the one space that follows send) to the current MailBox. */
    private void sendVerbatim(String rawLine) throws IOException {
        String after = rawLine.stripLeading().substring("send".length());
        String verbatim = after.isEmpty() ? "" : after.substring(1);
        if (verbatim.isBlank()) {
            localError(ErrorCode.BAD_REQUEST, "send takes the line to send, e.g. send put c_dive_target_depth 30");
        } else if (mailbox.isEmpty()) {
            localError(ErrorCode.BAD_REQUEST, "no MailBox chosen for 'send " + verbatim + "': use MAILBOX first (?mailboxes lists them)");
        } else {
            send(mailbox, verbatim);
        }
    }

    private void help() throws IOException {
        local("CLI help (lines this client understands):\n" + HELP);
        if (mailbox.isEmpty()) {
            local("Service help: choose a MailBox with use MAILBOX first; ?help lists the server's commands");
            return;
        }
        OutgoingServerMessage r = await(mailbox, "help", null);
        if (r == null) {
            return;
        }
        if (r.status() == Status.ERROR) {
            local("Service help (" + mailbox + "): none (" + r.footer().replyText() + ")");
        } else {
            local("Service help (" + mailbox + "):\n" + r.footer().replyText());
        }
    }

    private void use(String address) throws IOException {
        if (!address.isEmpty() && !address.contains("::")) {
            address = resolveHandle(address);
            if (address == null) {
                return;
            }
        }
        try {
            mailbox = MailboxAddress.parse(address).toString();
            local("using " + mailbox);
        } catch (IllegalArgumentException e) {
            localError(ErrorCode.UNKNOWN_MAILBOX, e.getMessage());
        }
    }

    /** The full address of the one MailBox whose handle is {@code handle}, or null (said why). */
    private String resolveHandle(String handle) throws IOException {
        OutgoingServerMessage r = await("", "?mailboxes", null);
        if (r == null) {
            return null;
        }
        List<String> matches = new ArrayList<>();
        if (r.footer().result() instanceof MailboxList list) {
            for (var s : list.mailboxes()) {
                try {
                    if (MailboxAddress.parse(s.address()).handle().equals(handle)) {
                        matches.add(s.address());
                    }
                } catch (IllegalArgumentException ignored) {
                    // not an address we can use
                }
            }
        }
        if (matches.size() == 1) {
            return matches.get(0);
        }
        localError(ErrorCode.UNKNOWN_MAILBOX, matches.isEmpty()
                ? "no MailBox has the handle '" + handle + "' (?mailboxes lists them)"
                : "the handle '" + handle + "' names " + matches.size() + " MailBoxes: " + String.join(", ", matches));
        return null;
    }

    private void send(String box, String body) throws IOException {
        OutgoingServerMessage reply = await(box, body, printer::print);
        if (reply != null) {
            exports.remember(reply.footer().result());
            print(reply);
        }
    }

    /** Sends and waits for the final reply; null when {@link #cancel()} ended the wait (said so). */
    private OutgoingServerMessage await(String box, String body, Consumer<OutgoingServerMessage> progress)
            throws IOException {
        Header h = Header.request(client.nextId(), box, body, priority);
        waitingId = h.messageId();
        try {
            return await(client.send(h, progress), body);
        } catch (CancellationException e) {
            return null;
        } finally {
            waitingId = 0;
        }
    }

    /** The final reply, or null when {@link #cancel()} ended the wait (said so). */
    private OutgoingServerMessage await(CompletableFuture<OutgoingServerMessage> f, String what) throws IOException {
        waiting = f;
        long id = waitingId;
        try {
            if (cancelled) {
                f.cancel(false);
            }
            return f.get(timeout.toMillis(), TimeUnit.MILLISECONDS);
        } catch (CancellationException e) {
            if (id > 0) {
                cancelOnServer(id, what);
            } else {
                cancelledNote(what);
            }
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for the server");
        } catch (TimeoutException e) {
            throw new IOException("no reply from " + client.server() + " within " + timeout.toSeconds() + " s");
        } catch (ExecutionException e) {
            throw e.getCause() instanceof IOException io ? io : new IOException(e.getCause());
        } finally {
            waiting = null;
        }
    }

    /** Asks the server to stop the request ({@code ?cancel ID}) and says what it answered. */
    private void cancelOnServer(long id, String what) {
        try {
            OutgoingServerMessage r = client.call("", "?cancel " + id, Priority.URGENT, Duration.ofSeconds(10), null);
            err.println("Cancelled: stopped waiting for '" + what + "'; the server: " + r.footer().replyText()
                    + (r.status() == Status.ERROR ? " [" + r.footer().errorCode() + "]" : ""));
        } catch (IOException e) {
            err.println("Cancelled: stopped waiting for '" + what + "'; ?cancel got no answer (" + e.getMessage()
                    + "): the server may still finish it");
        }
    }

    private void cancelledNote(String what) {
        err.println("Cancelled: stopped waiting for '" + what + "'; the server may still finish it (its reply will be ignored)");
    }

    private void export(String args) throws IOException {
        try {
            local(exports.export(args));
        } catch (IllegalArgumentException e) {
            localError(ErrorCode.BAD_REQUEST, e.getMessage());
        }
    }

    private void put(String args) throws IOException {
        List<String> words = new ArrayList<>(List.of(args.isEmpty() ? new String[0] : args.split("\\s+")));
        ClientSocketHandler.IfExists ifExists = ClientSocketHandler.IfExists.ASK;
        if (words.remove("--replace")) {
            ifExists = ClientSocketHandler.IfExists.REPLACE;
        }
        if (words.remove("--keep")) {
            if (ifExists == ClientSocketHandler.IfExists.REPLACE) {
                localError(ErrorCode.BAD_REQUEST, "put: --replace or --keep, not both");
                return;
            }
            ifExists = ClientSocketHandler.IfExists.KEEP;
        }
        String[] a = words.toArray(new String[0]);
        if (a.length < 1 || a.length > 2) {
            localError(ErrorCode.BAD_REQUEST, "usage: put LOCALFILE [NAME] [--replace|--keep]");
            return;
        }
        Path local = Path.of(a[0]);
        if (!Files.isRegularFile(local)) {
            localError(ErrorCode.BAD_FILE_NAME, "no local file '" + a[0] + "'");
            return;
        }
        String name = a.length == 2 ? a[1] : local.getFileName().toString();
        long size = Files.size(local);
        try {
            OutgoingServerMessage r = client.upload(local, name, ifExists, (done, total) -> {
                if (!json && total > ClientSocketHandler.CHUNK) {
                    err.printf("  ... put %s %d/%d (%d%%)%n", name, done, total, total == 0 ? 100 : done * 100 / total);
                }
                return !cancelled;
            });
            print(r);
        } catch (RipvErrorException e) {
            print(e.reply());
            if (e.reply().footer().errorCode() == ErrorCode.FILE_EXISTS && !json) {
                err.println("  (put " + args + " --replace to replace it, or --keep to keep both)");
            }
        } catch (IOException e) {
            if (!cancelled) {
                throw e;
            }
            cancelledNote("put " + name);
            return;
        }
        if (size == 0 && !json) {
            err.println("  (an empty file)");
        }
    }

    private void get(String args) throws IOException {
        String[] a = args.isEmpty() ? new String[0] : args.split("\\s+");
        if (a.length < 1 || a.length > 2) {
            localError(ErrorCode.BAD_REQUEST, "usage: get NAME [LOCALDIR]");
            return;
        }
        Path dir = a.length == 2 ? Path.of(a[1]) : Path.of(".");
        try {
            Path saved = client.download(a[0], dir, (done, total) -> {
                if (!json && total > ClientSocketHandler.CHUNK) {
                    err.printf("  ... get %s %d/%d (%d%%)%n", a[0], done, total, done * 100 / total);
                }
                return !cancelled;
            });
            local("saved " + a[0] + " (" + Files.size(saved) + " bytes) to " + saved);
        } catch (RipvErrorException e) {
            print(e.reply());
        } catch (IOException e) {
            if (!cancelled) {
                throw e;
            }
            cancelledNote("get " + a[0]);
        }
    }

    private void print(OutgoingServerMessage reply) {
        if (reply.status() == Status.ERROR) {
            anyError = true;
        }
        printer.print(reply);
    }

    private void local(String text) {
        printer.print(localReply(Footer.ok(Ids.FID_NONE, text, null)));
    }

    private void localError(ErrorCode code, String text) {
        print(localReply(Footer.error(Ids.FID_NONE, code, text)));
    }

    private OutgoingServerMessage localReply(Footer f) {
        return new OutgoingServerMessage(Header.request(0, mailbox, "", priority), f.via("cli"));
    }
}
