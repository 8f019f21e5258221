package org.ripv.server.commands;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Executor;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.ripv.commands.SingleLineCommand;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.SessionInfo;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.clients.ServerSessions;
import org.ripv.server.files.FileExistsException;
import org.ripv.server.files.FileStore;
import org.ripv.server.files.FileTooLargeException;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.SecurityRefusal;
import org.ripv.server.plans.Plans;
import org.ripv.server.requests.RequestCancels;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.security.LoginThrottle;
import org.ripv.server.security.SecurityCommands;
import org.ripv.server.services.ServiceRegistry;
import org.ripv.server.session.ConsoleCommands;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.store.AuditCommand;
import org.ripv.server.store.AuditTrail;
import org.ripv.server.store.StateStore;
import org.ripv.server.surfacing.SurfacingCommands;
import org.ripv.server.vehicles.MailboxArgument;
import org.ripv.server.vehicles.VehicleNames;
import org.ripv.server.workflow.Workflows;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * The server's own {@code ?} commands (Appendix B and docs/protocol.md): {@link #table} names
 * each once, and {@link #run} takes a request through the same steps for all of them — one line,
 * a known word, a vehicle name resolved to its MailBox, the permit file for a gated command, then
 * the command on its thread, its failures answered with the command's FID. Commands that must ask
 * services ({@code ?mailboxes}, {@code ?status}) answer when the services have, so that a slow
 * service cannot hold up everyone else.
 */
public final class ServerCommands {
    /** The parts the server's own commands read and change. */
    public record Parts(Supplier<PermitFile> permits, FileStore files, ServiceRegistry services, ServiceQueries queries,
                        Map<String, OperatorLock> locks, ServerSessions sessions, Workflows workflows, Plans plans, RequestCancels cancels,
                        LoginThrottle throttle, AuditTrail audit, StateStore store, Function<String, Optional<SocketHandler>> clients) {}

    private final Parts parts;
    private final ConsoleHub console;
    private final CommandTable table;
    private final Executor fileWork;
    private final Consumer<OutgoingServerMessage> outbox;
    /** Sends a request on to its MailBox's service as a client's command goes (checks included); a refusal, or null. */
    private final Function<IncomingServerMessage, OutgoingServerMessage> route;

    /**
     * @param fileWork where commands that touch the disk run
     * @param checkers where commands that call services run
     * @param outbox   where the replies go (the Post Office's outbox)
     * @param route    forwards a request as a client's goes (for {@code ?key})
     */
    public ServerCommands(Parts parts, Executor fileWork, Executor checkers, Consumer<OutgoingServerMessage> outbox,
                          Function<IncomingServerMessage, OutgoingServerMessage> route) {
        this.parts = parts;
        this.console = parts.sessions().console();
        this.fileWork = fileWork;
        this.outbox = outbox;
        this.route = route;
        this.table = table(checkers);
    }

    /**
     * Every server command, in the order {@code ?help} lists them. To add one: a line here (word,
     * FID from {@link Ids}, usage — or, for a command with options, {@code parsed} and its picocli
     * options class, from which the usage is written — help, {@code .needsRight()} when the permit
     * file must allow it, {@code .onFileWork()} when it touches the disk) and its handler, best in a
     * class of its own.
     */
    private CommandTable table(Executor checkers) {
        FileCommands files = new FileCommands(parts.files(), parts.permits());
        LockCommands locks = new LockCommands(parts.locks(), console, parts.sessions()::lockTaken,
                parts.workflows()::lockReleased);
        ServiceQueries queries = parts.queries();
        return new CommandTable()
                .add(ServerCommand.open("?help", Ids.FID_HELP, "?help", "this list", c -> c.ok(this.table.help(), null))
                        .servedBeforeLogin())
                .add(ServerCommand.open("?ping", Ids.FID_PING, "?ping", "answers pong", c -> c.ok("pong", null)).servedBeforeLogin())
                .add(ServerCommand.open("?whoami", Ids.FID_WHOAMI, "?whoami", "your client id, user and roles", this::whoami))
                .add(ServerCommand.open("?dldir", Ids.FID_DLDIR, "?dldir", "the download directory (files from services)",
                        files::dldir))
                .add(ServerCommand.open("?uldir", Ids.FID_ULDIR, "?uldir", "the upload directory (files from clients)",
                        files::uldir))
                .add(ServerCommand.open("?dlfiles", Ids.FID_DLFILES, "?dlfiles", "list the download directory",
                        files::dlfiles).onFileWork())
                .add(ServerCommand.open("?ulfiles", Ids.FID_ULFILES, "?ulfiles", "list the upload directory",
                        files::ulfiles).onFileWork())
                .add(ServerCommand.open("?mailboxes", Ids.FID_MAILBOXES, "?mailboxes", "the MailBoxes of every service", c -> {
                    queries.mailboxes(c.request());
                    return null;
                }))
                .add(ServerCommand.open("?status", Ids.FID_STATUS, "?status MAILBOX", "available or not, busy, who holds its lock",
                        c -> {
                            queries.status(c.request(), MailboxAddress.parse(c.arg(1)));
                            return null;
                        }))
                .add(ServerCommand.open("?services", Ids.FID_SERVICES, "?services", "the registered services",
                        c -> queries.services(c.request())))
                .add(ServerCommand.open("?upload", Ids.FID_UPLOAD, "?upload NAME OFFSET TOTAL [replace|keep]",
                        "one chunk of an upload (the clients' put); a taken NAME is refused unless replace or keep",
                        files::upload).needsRight().onFileWork())
                .add(ServerCommand.open("?upload-cancel", Ids.FID_UPLOAD, "?upload-cancel NAME", "drop an unfinished upload",
                        files::uploadCancel).needsRight().onFileWork())
                .add(ServerCommand.open("?download", Ids.FID_DOWNLOAD, "?download NAME OFFSET LENGTH",
                        "one chunk of a download (the clients' get)", files::download).needsRight().onFileWork())
                .add(ServerCommand.open("?delete", Ids.FID_DELETE, "?delete NAME",
                        "delete NAME from the upload directory, or FOLDER/NAME from the download directory",
                        files::delete).needsRight().onFileWork())
                .add(ServerCommand.open("?lock", Ids.FID_LOCK, "?lock MAILBOX [SECONDS]",
                        "keep others from commanding a MailBox (default 300 s)", locks::lock).needsRight())
                .add(ServerCommand.open("?unlock", Ids.FID_UNLOCK, "?unlock MAILBOX", "release your lock", locks::unlock).needsRight())
                .add(ServerCommand.open("?logins", Ids.FID_LOGINS, "?logins",
                        "users and addresses with failed log-ins, and their blocks (needs a right)",
                        c -> SecurityCommands.run(c.request(), c.command().fid(), c.words(), parts.throttle())).needsRight())
                .add(ServerCommand.open("?unlock-login", Ids.FID_UNLOCK_LOGIN, "?unlock-login USER|ADDRESS",
                        "lift a log-in block or lock (needs a right)",
                        c -> SecurityCommands.run(c.request(), c.command().fid(), c.words(), parts.throttle())).needsRight())
                .add(ServerCommand.open("?queue", Ids.FID_QUEUE, "?queue MAILBOX | add MAILBOX NAME [--typed] | remove MAILBOX ID | clear MAILBOX",
                        "the workflows queued for a vehicle's next call (docs/workflows.md)",
                        c -> parts.workflows().queueCommand(c.request())).onFileWork())
                .add(ServerCommand.parsed("?receipts", Ids.FID_RECEIPTS, Workflows.ReceiptOptions::new,
                        "what the last workflow runs did", c -> parts.workflows().receiptsCommand(c.request(),
                                c.options(Workflows.ReceiptOptions.class))).onFileWork())
                .add(ServerCommand.open("?plan", Ids.FID_PLAN,
                        "?plan MAILBOX check FILE | send FILE [as NAME] | set NAME VALUE | forecast FILE [SPEED] | save FILE [as NAME]"
                                + " | history NAME [N] | current",
                        "check a Slocum behaviour file (.ma), send it on the next call, queue a put, forecast its legs, keep its versions,"
                                + " or show the goto list the glider runs (docs/plans.md)",
                        c -> parts.plans().planCommand(c.request())).onFileWork())
                .add(ServerCommand.open("?changes", Ids.FID_CHANGES, "?changes [MAILBOX]",
                        "each change sent to a vehicle: queued, sent, received, in effect or not, or cancelled",
                        c -> parts.plans().changesCommand(c.request())).onFileWork())
                .add(ServerCommand.parsed("?surfacings", Ids.FID_SURFACINGS, SurfacingCommands.Options::new,
                        "its call records: one per surfacing (docs/surfacings.md)",
                        c -> parts.sessions().surfacingCommands().run(c.request(), c.command().fid(),
                                c.options(SurfacingCommands.Options.class))).onFileWork())
                .add(ServerCommand.parsed("?dac", Ids.FID_DAC, Dac::new,
                        "a DatabaseServer's DAC deliveries: profiles, QC, what was pushed, what failed and why (docs/dac.md)", this::dac))
                .add(ServerCommand.open("?cancel", Ids.FID_CANCEL, "?cancel MESSAGE-ID [CLIENT-ID]",
                        "stop a request that is queued or running", c -> {
                            checkers.execute(() -> outbox.accept(parts.cancels().command(c.request())));
                            return null;
                        }))
                .add(ServerCommand.open("?key", Ids.FID_KEY, "?key MAILBOX KEY", "press a control key on a vehicle (ctrl-c, ctrl-r, …)",
                        this::key))
                .add(ServerCommand.open("?watch", Ids.FID_WATCH, "?watch MAILBOX", "follow a MailBox's console: lines, commands, events",
                        this::consoleCommand))
                .add(ServerCommand.open("?unwatch", Ids.FID_UNWATCH, "?unwatch MAILBOX", "stop following it", this::consoleCommand))
                .add(ServerCommand.parsed("?history", Ids.FID_HISTORY, ConsoleCommands.History::new, "its transcript",
                        c -> parts.sessions().consoleCommands().history(c.request(), c.command().fid(),
                                c.options(ConsoleCommands.History.class))).onFileWork())
                .add(ServerCommand.open("?notify", Ids.FID_NOTIFY, "?notify add|list|remove ...", "e-mail or webhook on vehicle events",
                        c -> parts.sessions().notifyCommands().run(c.request(), c.command().fid(), c.words())).onFileWork())
                .add(ServerCommand.parsed("?audit", Ids.FID_AUDIT, AuditCommand.Options::new, "the audit trail (needs a right)",
                        c -> AuditCommand.run(c.request(), c.command().fid(), c.options(AuditCommand.Options.class), parts.audit(),
                                parts.store()))
                        .needsRight().onFileWork())
                .add(ServerCommand.open("?logout", Ids.FID_LOGOUT, "?logout", "end the session and close the connection", c -> {
                    parts.clients().apply(c.clientId()).ifPresent(h -> {
                        h.send(c.ok("goodbye", null));
                        h.close();
                    });
                    return null;
                }));
    }

    /** The commands by word: what {@code ?help} lists and the clients complete. */
    public CommandTable commands() {
        return table;
    }

    /** Runs one {@code ?} command; its reply (or replies) go to the Post Office's outbox. */
    public void run(IncomingServerMessage request) {
        try {
            SingleLineCommand.check(request.header().body(), SingleLineCommand.SERVER_MAX);
        } catch (IllegalArgumentException e) {
            outbox.accept(ServerReplies.error(request, Ids.FID_NONE, ErrorCode.BAD_REQUEST, e.getMessage()));
            return;
        }
        String[] w = request.header().body().trim().split("\\s+");
        ServerCommand c = table.find(w[0]).orElse(null);
        if (c == null) {
            outbox.accept(ServerReplies.error(request, Ids.FID_NONE, ErrorCode.UNKNOWN_COMMAND,
                    "unknown server command '" + w[0] + "'; ?help lists them"));
            return;
        }
        boolean watch = c.word().equals("?watch");
        int at = MailboxArgument.position(w);
        // A vehicle name stands for its MailBox; ?watch of an address no service has is refused at once.
        if (at > 0 && (!VehicleNames.isFullAddress(w[at]) || watch)) {
            parts.queries().known().thenAccept(known -> {
                try {
                    VehicleNames.Resolution r = VehicleNames.resolve(w[at], known.addresses(), known.notAnswering());
                    String why = !r.resolved() ? r.error() : watch ? unheardOf(r.address(), known) : null;
                    if (why != null) {
                        outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.UNKNOWN_MAILBOX, why));
                    } else if (r.address().equals(w[at])) {
                        dispatch(request, c, w);
                    } else {
                        String named = MailboxArgument.replaced(w, at, r.address());
                        dispatch(withBody(request, named), c, named.split(" "));
                    }
                } catch (RuntimeException x) {
                    // off the Post Office's thread nothing else would answer: the client must not wait for ever
                    outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.INTERNAL, c.usage() + " failed: " + x));
                }
            });
            return;
        }
        dispatch(request, c, w);
    }

    private void dispatch(IncomingServerMessage request, ServerCommand c, String[] w) {
        if (c.runs() == ServerCommand.Runs.FILE_WORK) {
            fileWork.execute(() -> runNow(request, c, w));
        } else {
            runNow(request, c, w);
        }
    }

    /**
     * Why a full address cannot be watched, or null: no answering service lists it and the server
     * has never heard from it (a MailBox of a service that is down now can still be watched).
     */
    private String unheardOf(String address, ServiceQueries.Known known) {
        if (known.addresses().contains(address) || console.state(address) != null) {
            return null;
        }
        String service = MailboxAddress.parse(address).service().toString();
        return "no MailBox " + address + (parts.services().find(service).isPresent() ? ": " + service + " does not list it"
                : ": no service " + service + " is registered") + " and nothing was ever heard from it; "
                + VehicleNames.whatThereIs(known.addresses(), known.notAnswering());
    }

    /** The request with its command line rewritten (a vehicle name replaced by its MailBox's full address). */
    private static IncomingServerMessage withBody(IncomingServerMessage request, String body) {
        Header h = request.header();
        return new IncomingServerMessage(new Header(h.messageId(), h.origin(), h.roles(), h.serviceDestination(),
                h.mailboxAddress(), body, h.priority(), h.attachment()));
    }

    private void runNow(IncomingServerMessage request, ServerCommand c, String[] w) {
        try {
            PermitFile.User user = c.gated() ? permit(request, c) : null;
            Object options = c.parse(w);
            OutgoingServerMessage reply = c.handler().run(new Call(request, c, w, user, options));
            if (reply != null) {
                outbox.accept(reply);
            }
        } catch (FileTooLargeException e) {
            outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.TOO_LARGE, e.getMessage()));
        } catch (NoSuchFileException e) {
            outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.BAD_FILE_NAME, e.getMessage()));
        } catch (FileExistsException e) {
            outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.FILE_EXISTS, e.getMessage()));
        } catch (SecurityRefusal e) {
            outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.FORBIDDEN, e.getMessage()));
        } catch (IllegalArgumentException e) {
            outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.BAD_REQUEST, e.getMessage()));
        } catch (IOException e) {
            outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.INTERNAL, c.usage() + " failed: " + e.getMessage()));
        }
    }

    /** A gated command: the permit file must allow the whole line for RIPVServer. */
    private PermitFile.User permit(IncomingServerMessage request, ServerCommand c) {
        String user = request.header().origin().user();
        PermitFile permits = parts.permits().get();
        PermitFile.User u = permits.user(user).orElseThrow(
                () -> new SecurityRefusal("user '" + user + "' is no longer in the permit file"));
        PermitFile.Decision d = permits.decide(u, ServerReplies.SERVICE, "", request.header().body());
        if (!d.allowed()) {
            throw new SecurityRefusal("user '" + user + "' may not use " + c.word() + " (" + d.because() + ")");
        }
        return u;
    }

    private OutgoingServerMessage whoami(Call c) {
        Header h = c.request().header();
        return c.ok(c.userName() + " on client " + c.clientId() + " " + h.roles(),
                new SessionInfo(c.clientId(), c.userName(), h.roles(), ServerReplies.SERVICE));
    }

    private OutgoingServerMessage consoleCommand(Call c) throws IOException {
        return parts.sessions().consoleCommands().run(c.request(), c.command().fid(), c.words());
    }

    /** The words of {@code ?dac}, read by picocli through the command table. */
    static final class Dac {
        @Parameters(index = "0", paramLabel = "MAILBOX")
        String mailbox;
        @Parameters(index = "1", arity = "0..1", paramLabel = "GLIDER")
        String glider;
        @Option(names = "--json")
        boolean json;
    }

    /**
     * {@code ?dac MAILBOX [GLIDER] [--json]}: asks the DatabaseServer MailBox for its deliveries
     * ({@code dac:status}), as the user's own command, so the permit file and the service's answer
     * are those of any command to it.
     */
    private OutgoingServerMessage dac(Call c) {
        Dac d = c.options(Dac.class);
        MailboxAddress.parse(d.mailbox);
        String body = "dac:status" + (d.glider == null ? "" : " " + d.glider) + (d.json ? " --json" : "");
        Header h = c.request().header();
        return route.apply(new IncomingServerMessage(new Header(h.messageId(), h.origin(), h.roles(),
                h.serviceDestination(), d.mailbox, body, h.priority(), null)));
    }

    /**
     * {@code ?key MAILBOX KEY}: goes to the MailBox as the command {@code ?key KEY}, through the
     * same checks as any command (the permit file decides on {@code ?key KEY}, so each key is a
     * right of its own; the operator lock holds), and the link's own list of keys decides last.
     */
    private OutgoingServerMessage key(Call c) {
        String[] w = c.words();
        if (w.length != 3) {
            throw new IllegalArgumentException("usage: ?key MAILBOX KEY, e.g. ?key <SerialPortServer>::<host>ru29 ctrl-c");
        }
        Header h = c.request().header();
        return route.apply(new IncomingServerMessage(new Header(h.messageId(), h.origin(), h.roles(),
                h.serviceDestination(), w[1], "?key " + w[2].toLowerCase(Locale.ROOT), h.priority(), null)));
    }
}
