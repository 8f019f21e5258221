package org.ripv.server.commands;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.time.Instant;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Executor;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import org.ripv.commands.SingleLineCommand;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileData;
import org.ripv.messages.FileListing;
import org.ripv.messages.Footer;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.SessionInfo;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.clients.ServerSessions;
import org.ripv.server.files.DownloadRights;
import org.ripv.server.files.FileExistsException;
import org.ripv.server.files.FileStore;
import org.ripv.server.files.UploadMode;
import org.ripv.server.files.FileTooLargeException;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.SecurityRefusal;
import org.ripv.server.requests.RequestCancels;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.security.LoginThrottle;
import org.ripv.server.security.SecurityCommands;
import org.ripv.server.services.ServiceRegistry;
import org.ripv.server.session.ConsoleHub;
import org.ripv.server.store.AuditCommand;
import org.ripv.server.store.AuditTrail;
import org.ripv.server.store.StateStore;
import org.ripv.server.vehicles.MailboxArgument;
import org.ripv.server.vehicles.VehicleNames;
import org.ripv.server.workflow.Workflows;

/**
 * The server's own {@code ?} commands (Appendix B and docs/protocol.md). Each reply carries the
 * command's FID. Commands that must ask services ({@code ?mailboxes}, {@code ?status}) run off
 * the Post Office's thread so that a slow service cannot hold up everyone else.
 */
public final class ServerCommands {
    static final long MAX_DOWNLOAD_CHUNK = 1024 * 1024;
    static final long MAX_LOCK_SECONDS = 3600;

    private record Command(String fid, String usage, String help) {}

    private static final Map<String, Command> COMMANDS = new java.util.LinkedHashMap<>();

    static {
        COMMANDS.put("?help", new Command(Ids.FID_HELP, "?help", "this list"));
        COMMANDS.put("?ping", new Command(Ids.FID_PING, "?ping", "answers pong"));
        COMMANDS.put("?whoami", new Command(Ids.FID_WHOAMI, "?whoami", "your client id, user and roles"));
        COMMANDS.put("?dldir", new Command(Ids.FID_DLDIR, "?dldir", "the download directory (files from services)"));
        COMMANDS.put("?uldir", new Command(Ids.FID_ULDIR, "?uldir", "the upload directory (files from clients)"));
        COMMANDS.put("?dlfiles", new Command(Ids.FID_DLFILES, "?dlfiles", "list the download directory"));
        COMMANDS.put("?ulfiles", new Command(Ids.FID_ULFILES, "?ulfiles", "list the upload directory"));
        COMMANDS.put("?mailboxes", new Command(Ids.FID_MAILBOXES, "?mailboxes", "the MailBoxes of every service"));
        COMMANDS.put("?status", new Command(Ids.FID_STATUS, "?status MAILBOX", "available or not, busy, who holds its lock"));
        COMMANDS.put("?services", new Command(Ids.FID_SERVICES, "?services", "the registered services"));
        COMMANDS.put("?upload", new Command(Ids.FID_UPLOAD, "?upload NAME OFFSET TOTAL [replace|keep]",
                "one chunk of an upload (the clients' put); a taken NAME is refused unless replace or keep"));
        COMMANDS.put("?upload-cancel", new Command(Ids.FID_UPLOAD, "?upload-cancel NAME", "drop an unfinished upload"));
        COMMANDS.put("?download", new Command(Ids.FID_DOWNLOAD, "?download NAME OFFSET LENGTH", "one chunk of a download (the clients' get)"));
        COMMANDS.put("?delete", new Command(Ids.FID_DELETE, "?delete NAME", "delete NAME from the upload directory, or FOLDER/NAME from the download directory"));
        COMMANDS.put("?lock", new Command(Ids.FID_LOCK, "?lock MAILBOX [SECONDS]", "keep others from commanding a MailBox (default 300 s)"));
        COMMANDS.put("?unlock", new Command(Ids.FID_UNLOCK, "?unlock MAILBOX", "release your lock"));
        COMMANDS.put("?logins", new Command(Ids.FID_LOGINS, "?logins", "users and addresses with failed log-ins, and their blocks (needs a right)"));
        COMMANDS.put("?unlock-login", new Command(Ids.FID_UNLOCK_LOGIN, "?unlock-login USER|ADDRESS", "lift a log-in block or lock (needs a right)"));
        COMMANDS.put("?queue", new Command(Ids.FID_QUEUE, "?queue MAILBOX | add MAILBOX NAME | remove MAILBOX ID | clear MAILBOX",
                "the workflows queued for a vehicle's next call (docs/workflows.md)"));
        COMMANDS.put("?receipts", new Command(Ids.FID_RECEIPTS, "?receipts MAILBOX [--last N]", "what the last workflow runs did"));
        COMMANDS.put("?cancel", new Command(Ids.FID_CANCEL, "?cancel MESSAGE-ID [CLIENT-ID]", "stop a request that is queued or running"));
        COMMANDS.put("?key", new Command(Ids.FID_KEY, "?key MAILBOX KEY", "press a control key on a vehicle (ctrl-c, ctrl-r, …)"));
        COMMANDS.put("?watch", new Command(Ids.FID_WATCH, "?watch MAILBOX", "follow a MailBox's console: lines, commands, events"));
        COMMANDS.put("?unwatch", new Command(Ids.FID_UNWATCH, "?unwatch MAILBOX", "stop following it"));
        COMMANDS.put("?history", new Command(Ids.FID_HISTORY, "?history MAILBOX [--last N] [--since ISO-TIME]", "its transcript"));
        COMMANDS.put("?notify", new Command(Ids.FID_NOTIFY, "?notify add|list|remove ...", "e-mail or webhook on vehicle events"));
        COMMANDS.put("?audit", new Command(Ids.FID_AUDIT, "?audit [--last N] [--since ISO-TIME]", "the audit trail (needs a right)"));
        COMMANDS.put("?logout", new Command(Ids.FID_LOGOUT, "?logout", "end the session and close the connection"));
    }

    private final Supplier<PermitFile> permits;
    private final FileStore files;
    private final ServiceRegistry services;
    private final ServiceQueries queries;
    private final Map<String, OperatorLock> locks;
    private final ConsoleHub console;
    private final ServerSessions sessions;
    private final Workflows workflows;
    private final RequestCancels cancels;
    private final LoginThrottle throttle;
    private final AuditTrail audit;
    private final StateStore store;
    private final Function<String, Optional<SocketHandler>> clients;
    private final Executor fileWork;
    private final Executor checkers;
    private final Consumer<OutgoingServerMessage> outbox;
    /** Sends a request on to its MailBox's service as a client's command goes (checks included); a refusal, or null. */
    private final Function<IncomingServerMessage, OutgoingServerMessage> route;

    /** The parts the server's own commands read and change. */
    public record Parts(Supplier<PermitFile> permits, FileStore files, ServiceRegistry services, ServiceQueries queries,
                       Map<String, OperatorLock> locks, ServerSessions sessions, Workflows workflows, RequestCancels cancels,
                       LoginThrottle throttle, AuditTrail audit, StateStore store, Function<String, Optional<SocketHandler>> clients) {}

    /**
     * @param fileWork where commands that touch the disk run
     * @param checkers where commands that call services run
     * @param outbox   where the replies go (the Post Office's outbox)
     * @param route    forwards a request as a client's goes (for {@code ?key})
     */
    public ServerCommands(Parts parts, Executor fileWork, Executor checkers, Consumer<OutgoingServerMessage> outbox,
                          Function<IncomingServerMessage, OutgoingServerMessage> route) {
        this.permits = parts.permits();
        this.files = parts.files();
        this.services = parts.services();
        this.queries = parts.queries();
        this.locks = parts.locks();
        this.sessions = parts.sessions();
        this.console = parts.sessions().console();
        this.workflows = parts.workflows();
        this.cancels = parts.cancels();
        this.throttle = parts.throttle();
        this.audit = parts.audit();
        this.store = parts.store();
        this.clients = parts.clients();
        this.fileWork = fileWork;
        this.checkers = checkers;
        this.outbox = outbox;
        this.route = route;
    }

    /** Commands that touch the disk: they run on the file workers, not on the Post Office's thread. */
    private static final java.util.Set<String> FILE_WORK = java.util.Set.of("?upload", "?upload-cancel", "?download",
            "?dlfiles", "?ulfiles", "?delete", "?queue", "?receipts", "?history", "?notify", "?audit");

    /** Runs one {@code ?} command; its reply (or replies) go to the Post Office's outbox. */
    public void run(IncomingServerMessage request) {
        try {
            SingleLineCommand.check(request.header().body(), SingleLineCommand.SERVER_MAX);
        } catch (IllegalArgumentException e) {
            outbox.accept(ServerReplies.error(request, Ids.FID_NONE, ErrorCode.BAD_REQUEST, e.getMessage()));
            return;
        }
        String body = request.header().body().trim();
        String[] w = body.split("\\s+");
        String word = w[0].toLowerCase(java.util.Locale.ROOT);
        Command c = COMMANDS.get(word);
        if (c == null) {
            outbox.accept(ServerReplies.error(request, Ids.FID_NONE, ErrorCode.UNKNOWN_COMMAND,
                    "unknown server command '" + w[0] + "'; ?help lists them"));
            return;
        }
        int at = MailboxArgument.position(w);
        // A vehicle name stands for its MailBox; ?watch of an address no service has is refused at once.
        if (at > 0 && (!VehicleNames.isFullAddress(w[at]) || word.equals("?watch"))) {
            queries.known().thenAccept(known -> {
                try {
                    VehicleNames.Resolution r = VehicleNames.resolve(w[at], known.addresses(), known.notAnswering());
                    String why = !r.resolved() ? r.error() : word.equals("?watch") ? unheardOf(r.address(), known) : null;
                    if (why != null) {
                        outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.UNKNOWN_MAILBOX, why));
                    } else if (r.address().equals(w[at])) {
                        dispatch(request, c, w, word);
                    } else {
                        String named = MailboxArgument.replaced(w, at, r.address());
                        dispatch(withBody(request, named), c, named.split(" "), word);
                    }
                } catch (RuntimeException x) {
                    // off the Post Office's thread nothing else would answer: the client must not wait for ever
                    outbox.accept(ServerReplies.error(request, c.fid(), ErrorCode.INTERNAL, c.usage() + " failed: " + x));
                }
            });
            return;
        }
        dispatch(request, c, w, word);
    }

    private void dispatch(IncomingServerMessage request, Command c, String[] w, String word) {
        if (FILE_WORK.contains(word)) {
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
        return "no MailBox " + address + (services.find(service).isPresent() ? ": " + service + " does not list it"
                : ": no service " + service + " is registered") + " and nothing was ever heard from it; "
                + VehicleNames.whatThereIs(known.addresses(), known.notAnswering());
    }

    /** The request with its command line rewritten (a vehicle name replaced by its MailBox's full address). */
    private static IncomingServerMessage withBody(IncomingServerMessage request, String body) {
        org.ripv.messages.Header h = request.header();
        return new IncomingServerMessage(new org.ripv.messages.Header(h.messageId(), h.origin(), h.roles(), h.serviceDestination(),
                h.mailboxAddress(), body, h.priority(), h.attachment()));
    }

    private void runNow(IncomingServerMessage request, Command c, String[] w) {
        try {
            OutgoingServerMessage reply = execute(request, c, w);
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

    private OutgoingServerMessage execute(IncomingServerMessage request, Command c, String[] w) throws IOException {
        String user = request.header().origin().user();
                switch (w[0].toLowerCase(java.util.Locale.ROOT)) {
            case "?help": {
                StringBuilder b = new StringBuilder("Server commands:\n");
                COMMANDS.forEach((k, v) -> b.append(String.format("  %-32s %s  [FID %s]%n", v.usage(), v.help(), v.fid())));
                b.append("Anything else goes to the chosen MailBox of a service.");
                return ok(request, c, b.toString(), null);
            }
            case "?ping":
                return ok(request, c, "pong", null);
            case "?whoami":
                return ok(request, c, user + " on client " + request.header().origin().clientId() + " " + request.header().roles(),
                        new SessionInfo(request.header().origin().clientId(), user, request.header().roles(), "RIPVServer"));
            case "?logout":
                clients.apply(request.header().origin().clientId()).ifPresent(h -> {
                    h.send(ok(request, c, "goodbye", null));
                    h.close();
                });
                return null;
            case "?dldir": {
                String shown = shownPath(request, files.downloadDir(), "download");
                return ok(request, c, shown, new FileListing(shown, List.of()));
            }
            case "?uldir": {
                String shown = shownPath(request, files.uploadDir(), "upload");
                return ok(request, c, shown, new FileListing(shown, List.of()));
            }
            case "?dlfiles":
                return listing(request, c, files.listDownloads(), shownPath(request, files.downloadDir(), "download"));
            case "?ulfiles":
                return listing(request, c, files.listUploads(), shownPath(request, files.uploadDir(), "upload"));
            case "?delete": {
                permit(request, c);
                if (w.length != 2) {
                    throw new IllegalArgumentException("usage: " + c.usage());
                }
                String where = files.delete(w[1]);
                return ok(request, c, "deleted " + w[1] + " from the " + where, null);
            }
            case "?services":
                return queries.services(request);
            case "?mailboxes":
                queries.mailboxes(request);
                return null;
            case "?status":
                queries.status(request, MailboxAddress.parse(arg(w, 1, c)));
                return null;
            case "?upload": {
                PermitFile.User u = permit(request, c);
                if (w.length < 4 || w.length > 5 || request.header().attachment() == null) {
                    throw new IllegalArgumentException("usage: " + c.usage() + " with the chunk attached");
                }
                long offset = number(w[2], "OFFSET");
                long total = number(w[3], "TOTAL");
                UploadMode mode = UploadMode.parse(w.length == 5 ? w[4] : null);
                if (mode == UploadMode.REPLACE) {
                    // replacing is a right of its own (docs/permit.md): '?replace NAME' for RIPVServer
                    PermitFile.Decision d = permits.get().decide(u, ServerReplies.SERVICE, "", "?replace " + w[1]);
                    if (!d.allowed()) {
                        throw new SecurityRefusal("user '" + user + "' may not replace files in the upload directory ("
                                + d.because() + "); upload with 'keep' to store it under a new name");
                    }
                }
                if (org.ripv.server.files.ToVehicleFolder.isToVehicle(w[1])) {
                    toVehicleRight(u, user, w[1]);
                }
                FileStore.ChunkResult r = files.uploadChunk(request.header().origin().clientId(), user, w[1], offset, total,
                        request.header().attachment().data(), mode, permits.get().quota(u));
                String text;
                if (!r.complete()) {
                    text = "received " + r.received() + " of " + r.total() + " bytes of " + w[1];
                } else if (!r.storedAs().equals(w[1])) {
                    text = "stored as " + r.storedAs() + " (" + r.total() + " bytes) in the upload directory: " + w[1]
                            + " was taken and is kept as it was";
                } else {
                    text = "stored " + w[1] + " (" + r.total() + " bytes) in the upload directory"
                            + (mode == UploadMode.REPLACE ? " (replace)" : "");
                }
                return ok(request, c, text, r.complete() ? new FileListing("upload",
                        List.of(new FileListing.Entry(r.storedAs(), r.total(), System.currentTimeMillis()))) : null);
            }
            case "?upload-cancel":
                permit(request, c);
                files.abort(request.header().origin().clientId(), arg(w, 1, c));
                return ok(request, c, "dropped the unfinished upload of " + w[1], null);
            case "?download": {
                permit(request, c);
                if (w.length != 4) {
                    throw new IllegalArgumentException("usage: " + c.usage());
                }
                DownloadRights.check(files, permits.get(), user, w[1]);
                long offset = number(w[2], "OFFSET");
                int length = (int) Math.min(MAX_DOWNLOAD_CHUNK, number(w[3], "LENGTH"));
                Object[] chunk = files.readDownload(w[1], offset, length);
                byte[] data = (byte[]) chunk[1];
                long total = (Long) chunk[0];
                return ok(request, c, "bytes " + offset + ".." + (offset + data.length) + " of " + total + " of " + w[1],
                        new FileData(w[1], offset, total, data));
            }
            case "?queue":
                return workflows.queueCommand(request);
            case "?receipts":
                return workflows.receiptsCommand(request);
            case "?key":
                return key(request, w);
            case "?cancel":
                checkers.execute(() -> outbox.accept(cancels.command(request)));
                return null;
            case "?lock": {
                permit(request, c);
                MailboxAddress address = MailboxAddress.parse(arg(w, 1, c));
                long seconds = w.length >= 3 ? number(w[2], "SECONDS") : 300;
                if (seconds < 1 || seconds > MAX_LOCK_SECONDS) {
                    throw new IllegalArgumentException("a lock lasts 1 to " + MAX_LOCK_SECONDS + " seconds, not " + seconds);
                }
                OperatorLock mine = new OperatorLock(user, request.header().origin().clientId(),
                        System.currentTimeMillis() + seconds * 1000);
                OperatorLock now = locks.compute(address.toString(),
                        (k, old) -> old == null || old.expired() || old.user().equals(user)
                                || Workflows.isWorkflowClient(old.clientId()) ? mine : old);
                if (now != mine) {
                    return ServerReplies.error(request, c.fid(), ErrorCode.MAILBOX_LOCKED,
                            address + " is locked by " + now.user() + " until " + Instant.ofEpochMilli(now.untilMillis()));
                }
                console.serverEvent(address.toString(), org.ripv.messages.VehicleEvent.LOCK_TAKEN, user,
                        "until " + Instant.ofEpochMilli(mine.untilMillis()));
                sessions.lockTaken(address.toString(), mine);
                return ok(request, c, address + " locked by " + user + " until " + Instant.ofEpochMilli(mine.untilMillis()), null);
            }
            case "?unlock": {
                permit(request, c);
                MailboxAddress address = MailboxAddress.parse(arg(w, 1, c));
                OperatorLock l = locks.get(address.toString());
                if (l != null && !l.expired() && !l.user().equals(user)) {
                    return ServerReplies.error(request, c.fid(), ErrorCode.MAILBOX_LOCKED,
                            address + " is locked by " + l.user() + ", not by you");
                }
                if (locks.remove(address.toString()) != null && l != null && !l.expired()) {
                    console.serverEvent(address.toString(), org.ripv.messages.VehicleEvent.LOCK_RELEASED, user, "");
                }
                workflows.lockReleased(address.toString());
                return ok(request, c, address + " unlocked", null);
            }
            case "?logins", "?unlock-login":
                permit(request, c);
                return SecurityCommands.run(request, c.fid(), w, throttle);
            case "?audit":
                permit(request, c);
                return AuditCommand.run(request, c.fid(), w, audit, store);
            case "?watch", "?unwatch", "?history":
                return sessions.consoleCommands().run(request, c.fid(), w);
            case "?notify":
                return sessions.notifyCommands().run(request, c.fid(), w);
            default:
                throw new IllegalStateException("no handler for " + w[0]);
        }
    }

    /**
     * The server's own directories: an absolute path only for operators and admins, who run the
     * host; everybody else sees the area's name (no server paths to ordinary users).
     */
    private static String shownPath(IncomingServerMessage request, java.nio.file.Path dir, String area) {
        List<String> roles = request.header().roles();
        return roles.contains("operators") || roles.contains("admin") ? dir.toString() : area;
    }

    /**
     * A file for a vehicle ({@code to-vehicle/FOLDER/NAME}) needs the right {@code ?to-vehicle FOLDER}
     * (service RIPVServer, docs/permit.md), and FOLDER must be a MailBox's.
     */
    private void toVehicleRight(PermitFile.User u, String user, String name) {
        org.ripv.server.files.ToVehicleFolder.Name n = org.ripv.server.files.ToVehicleFolder.parse(name);
        PermitFile.Decision d = permits.get().decide(u, ServerReplies.SERVICE, "", "?to-vehicle " + n.folder());
        if (!d.allowed()) {
            throw new SecurityRefusal("user '" + user + "' may not put files for a vehicle in to-vehicle/" + n.folder() + " ("
                    + d.because() + "); that takes the right '?to-vehicle " + n.folder() + "' for RIPVServer");
        }
        if (!files.isMailboxFolder(n.folder())) {
            throw new IllegalArgumentException("no MailBox has the folder '" + n.folder() + "'; give the vehicle's folder"
                    + " as ?dlfiles names it (HANDLE@HOST@SERVICE)");
        }
    }

    private PermitFile.User permit(IncomingServerMessage request, Command c) {
        String user = request.header().origin().user();
        PermitFile.User u = permits.get().user(user).orElseThrow(
                () -> new SecurityRefusal("user '" + user + "' is no longer in the permit file"));
        PermitFile.Decision d = permits.get().decide(u, ServerReplies.SERVICE, "", request.header().body());
        if (!d.allowed()) {
            throw new SecurityRefusal("user '" + user + "' may not use " + c.usage().split(" ")[0] + " (" + d.because() + ")");
        }
        return u;
    }

    private static OutgoingServerMessage ok(IncomingServerMessage request, Command c, String text,
                                            org.ripv.messages.Result result) {
        return request.reply(Footer.ok(c.fid(), text, result).via(ServerReplies.SERVICE));
    }

    private static OutgoingServerMessage listing(IncomingServerMessage request, Command c, FileListing all, String shown) {
        FileListing l = new FileListing(shown, all.files());
        StringBuilder b = new StringBuilder(l.directory() + ": " + l.files().size() + " file(s)");
        for (FileListing.Entry e : l.files()) {
            b.append(String.format("%n%12d  %s  %s", e.size(), Instant.ofEpochMilli(e.modified()), e.name()));
        }
        return ok(request, c, b.toString(), l);
    }

    private static String arg(String[] w, int i, Command c) {
        if (w.length <= i) {
            throw new IllegalArgumentException("usage: " + c.usage());
        }
        return w[i];
    }

    private static long number(String s, String what) {
        try {
            return Long.parseLong(s);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(what + " must be a whole number, got '" + s + "'");
        }
    }



    /**
     * {@code ?key MAILBOX KEY}: goes to the MailBox as the command {@code ?key KEY}, through the
     * same checks as any command (the permit file decides on {@code ?key KEY}, so each key is a
     * right of its own; the operator lock holds), and the link's own list of keys decides last.
     */
    private OutgoingServerMessage key(IncomingServerMessage request, String[] w) {
        if (w.length != 3) {
            throw new IllegalArgumentException("usage: ?key MAILBOX KEY, e.g. ?key <SerialPortServer>::<host>ru29 ctrl-c");
        }
        org.ripv.messages.Header h = request.header();
        return route.apply(new IncomingServerMessage(new org.ripv.messages.Header(h.messageId(), h.origin(), h.roles(),
                h.serviceDestination(), w[1], "?key " + w[2].toLowerCase(java.util.Locale.ROOT), h.priority(), null)));
    }
}
