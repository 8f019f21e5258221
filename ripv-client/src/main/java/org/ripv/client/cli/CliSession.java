package org.ripv.client.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.naming.MailboxAddress;

/**
 * Runs lines of the COM panel's command language against a connected server: {@code ?...}
 * server commands, {@code use MAILBOX}, {@code priority LEVEL}, {@code put LOCALFILE},
 * {@code get NAME [LOCALDIR]}, and anything else as a command for the current MailBox.
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
    private org.ripv.messages.TableResult lastTable;

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

    /** Runs one line. Returns false for {@code quit}. */
    public boolean run(String rawLine) throws IOException {
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
            case "help" -> local("Lines: ?COMMAND (server; ?help lists them) | use MAILBOX | priority normal|priority|urgent"
                    + " | put LOCALFILE [NAME] | get NAME [LOCALDIR] | export csv|json LOCALFILE | quit | anything else goes to the current MailBox");
            case "use" -> use(rest);
            case "priority" -> {
                try {
                    priority = Priority.parse(rest);
                    local("priority " + priority.name().toLowerCase(java.util.Locale.ROOT));
                } catch (IllegalArgumentException e) {
                    localError(ErrorCode.BAD_REQUEST, e.getMessage());
                }
            }
            case "put" -> put(rest);
            case "get" -> get(rest);
            case "export" -> export(rest);
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

    private void use(String address) {
        try {
            mailbox = MailboxAddress.parse(address).toString();
            local("using " + mailbox);
        } catch (IllegalArgumentException e) {
            localError(ErrorCode.UNKNOWN_MAILBOX, e.getMessage());
        }
    }

    private void send(String box, String body) throws IOException {
        OutgoingServerMessage reply = client.call(box, body, priority, timeout, printer::print);
        if (reply.footer().result() instanceof org.ripv.messages.TableResult t) {
            lastTable = t;
        }
        print(reply);
    }

    /** {@code export csv|json FILE}: the last table received, to a local file ({@link TableExport}). */
    private void export(String args) throws IOException {
        String[] a = args.isEmpty() ? new String[0] : args.split("\\s+", 2);
        if (a.length != 2 || !(a[0].equalsIgnoreCase("csv") || a[0].equalsIgnoreCase("json"))) {
            localError(ErrorCode.BAD_REQUEST, "usage: export csv|json LOCALFILE (writes the last query result)");
            return;
        }
        if (lastTable == null) {
            localError(ErrorCode.BAD_REQUEST, "no query result to export yet: run a SELECT first");
            return;
        }
        String text = a[0].equalsIgnoreCase("csv") ? TableExport.csv(lastTable) : TableExport.json(lastTable);
        Path file = Path.of(a[1]);
        Files.writeString(file, text, java.nio.charset.StandardCharsets.UTF_8);
        local("exported " + lastTable.rows().size() + " rows as " + a[0].toLowerCase(java.util.Locale.ROOT) + " to " + file);
    }

    private void put(String args) throws IOException {
        String[] a = args.isEmpty() ? new String[0] : args.split("\\s+");
        if (a.length < 1 || a.length > 2) {
            localError(ErrorCode.BAD_REQUEST, "usage: put LOCALFILE [NAME]");
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
            OutgoingServerMessage r = client.upload(local, name, (done, total) -> {
                if (!json && total > ClientSocketHandler.CHUNK) {
                    err.printf("  ... put %s %d/%d (%d%%)%n", name, done, total, total == 0 ? 100 : done * 100 / total);
                }
                return true;
            });
            print(r);
        } catch (RipvErrorException e) {
            print(e.reply());
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
                return true;
            });
            local("saved " + a[0] + " (" + Files.size(saved) + " bytes) to " + saved);
        } catch (RipvErrorException e) {
            print(e.reply());
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
