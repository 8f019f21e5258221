package org.ripv.server;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.util.Optional;
import org.ripv.commands.SingleLineCommand;
import org.ripv.managers.TaskManager;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.MalformedNameException;
import org.ripv.post.MailBox;
import org.ripv.server.files.FileTooLargeException;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.lock.OperatorLock;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.SecurityRefusal;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.services.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The RIPV Post Office's TaskManager (thesis figure 5.3). Header side: a {@code ?} command runs
 * here; anything else is checked (mailbox, service, permission, operator lock, attachment) and
 * forwarded to its service. Footer side: the reply goes to the client that asked, or is dropped
 * and logged when that client has gone.
 */
final class ServerTaskManager extends TaskManager<IncomingServerMessage, OutgoingServerMessage> {
    private static final Logger log = LoggerFactory.getLogger(ServerTaskManager.class);

    private final RIPVServer server;
    private final ServerCommands commands;

    ServerTaskManager(RIPVServer server) {
        this.server = server;
        this.commands = new ServerCommands(server, this::route);
    }

    @Override
    public void parseHeader(MailBox<IncomingServerMessage, OutgoingServerMessage> box, IncomingServerMessage request) {
        if (request.header().isServerCommand()) {
            commands.run(request);
            return;
        }
        OutgoingServerMessage refusal = route(request);
        if (refusal != null) {
            server.reply(refusal);
        }
    }

    /** Forwards the request, or returns the error reply that refuses it. */
    private OutgoingServerMessage route(IncomingServerMessage request) {
        Header h = request.header();
        if (h.mailboxAddress().isEmpty()) {
            return error(request, Ids.FID_NONE, ErrorCode.BAD_REQUEST,
                    "no mailbox chosen for '" + Header.abbreviate(h.body()) + "': pick one (use MAILBOX); ?mailboxes lists them");
        }
        MailboxAddress address;
        try {
            address = parsed(h.mailboxAddress());
        } catch (MalformedNameException e) {
            return error(request, Ids.FID_NONE, ErrorCode.UNKNOWN_MAILBOX, e.getMessage());
        }
        Optional<ServiceReference> found = server.service(address.service().toString());
        if (found.isEmpty()) {
            return error(request, Ids.FID_NONE, ErrorCode.UNKNOWN_SERVICE,
                    "no service " + address.service() + " is registered; ?services lists those that are");
        }
        ServiceReference ref = found.get();
        String sid = ref.descriptor().sid();
        if (h.body().isBlank()) {
            return error(request, sid, ErrorCode.BAD_REQUEST, "an empty command");
        }
        try {
            // Before any permit rule: a second line or a ^C inside a command is never the user's to send.
            SingleLineCommand.check(h.body(), SingleLineCommand.SERVER_MAX);
        } catch (IllegalArgumentException e) {
            log.info("refused a command from {} to {}: {}", h.origin().user(), address, e.getMessage());
            return error(request, sid, ErrorCode.BAD_REQUEST, e.getMessage());
        }
        Optional<PermitFile.User> user = server.permits().user(h.origin().user());
        if (user.isEmpty()) {
            return error(request, sid, ErrorCode.FORBIDDEN, "user '" + h.origin().user() + "' is no longer in the permit file");
        }
        PermitFile.Decision d = server.permits().decide(user.get(), address.service().service(), address.handle(), h.body());
        if (!d.allowed()) {
            return error(request, sid, ErrorCode.FORBIDDEN, "user '" + h.origin().user() + "' may not send '"
                    + Header.abbreviate(h.body().trim()) + "' to " + address + " (" + d.because() + ")");
        }
        OperatorLock lock = server.locks().get(address.toString());
        if (lock != null && !lock.expired() && !lock.user().equals(h.origin().user())) {
            return error(request, sid, ErrorCode.MAILBOX_LOCKED, address + " is locked by " + lock.user() + " until "
                    + java.time.Instant.ofEpochMilli(lock.untilMillis()) + "; try later");
        }
        if (server.dataLoop().plot(request, sid, address.toString(), server::reply)) {
            return null; // vis:sql, vis:track, ...: the server queries the database first (org.ripv.server.dataloop)
        }
        String ownFolder = org.ripv.server.files.ToVehicleFolder.DIR + "/" + org.ripv.server.files.FileStore.folderFor(address.toString()) + "/";
        String[] words = h.body().trim().split("\\s+");
        if (words[0].equals("tovehicle:put") && (words.length != 2 || !words[1].startsWith(ownFolder))) {
            // a vehicle is sent only its own folder's files (docs/serial.md#the-to-vehicle-folder)
            return error(request, sid, ErrorCode.BAD_FILE_NAME, "tovehicle:put sends a file of " + address + "'s own folder, "
                    + ownFolder + "NAME; not '" + Header.abbreviate(h.body().trim()) + "'");
        }
        Attachment attachment;
        try {
            attachment = attachmentFor(ref, h.body(), h.origin().user());
        } catch (SecurityRefusal e) {
            return error(request, sid, ErrorCode.FORBIDDEN, e.getMessage());
        } catch (FileTooLargeException e) {
            return error(request, sid, ErrorCode.TOO_LARGE, e.getMessage());
        } catch (NoSuchFileException e) {
            return error(request, sid, ErrorCode.BAD_FILE_NAME, org.ripv.server.dataloop.DataLoop.noSuchFile(sid, h.body(), e.getMessage()));
        } catch (IllegalArgumentException e) {
            return error(request, sid, ErrorCode.BAD_FILE_NAME, e.getMessage());
        } catch (IOException e) {
            return error(request, sid, ErrorCode.INTERNAL, "could not read the upload: " + e.getMessage());
        }
        Header stamped = h.withDestination(ref.descriptor().name()).withAttachment(attachment);
        server.forward(ref, new IncomingServiceMessage(stamped));
        return null;
    }

    /**
     * Addresses already parsed: a server talks to a few dozen MailBoxes, and parsing one is three
     * regular expressions per request. Bounded, so that a client sending made-up addresses cannot
     * grow it; only well-formed addresses are kept.
     */
    private final java.util.Map<String, MailboxAddress> addresses = new java.util.concurrent.ConcurrentHashMap<>();
    private static final int MAX_ADDRESSES = 4096;

    private MailboxAddress parsed(String text) {
        MailboxAddress known = addresses.get(text);
        if (known != null) {
            return known;
        }
        MailboxAddress a = MailboxAddress.parse(text);
        if (addresses.size() >= MAX_ADDRESSES) {
            addresses.clear();
        }
        addresses.put(text, a);
        return a;
    }

    /** The upload-directory file a command names after one of the service's attach prefixes. */
    private Attachment attachmentFor(ServiceReference ref, String body, String user) throws IOException {
        Attachment downloads = DownloadAttachments.forCommand(server.files(), ref.descriptor(), body,
                name -> DownloadRights.check(server.files(), server.permits(), user, name));
        if (downloads != null) {
            return downloads;
        }
        String trimmed = body.trim();
        for (String prefix : ref.descriptor().attachPrefixes()) {
            if (trimmed.regionMatches(true, 0, prefix, 0, prefix.length())) {
                String rest = trimmed.substring(prefix.length()).trim();
                if (rest.isEmpty()) {
                    throw new IllegalArgumentException("'" + prefix.trim() + "' needs the name of a file in the upload directory");
                }
                String name = rest.split("\\s+", 2)[0];
                return new Attachment(name, server.files().readUpload(name));
            }
        }
        return null;
    }

    static OutgoingServerMessage error(IncomingServerMessage request, String id, ErrorCode code, String text) {
        return request.reply(Footer.error(id, code, text).via(ServerReplies.SERVICE));
    }

    @Override
    public void parseFooter(MailBox<IncomingServerMessage, OutgoingServerMessage> box, OutgoingServerMessage reply) {
        if (server.workflows().reply(reply)) {
            return; // a workflow step's reply: the runner judges it
        }
        Optional<SocketHandler> client = server.client(reply.header().origin().clientId());
        if (client.isEmpty()) {
            log.info("dropped reply to #{}: client {} has disconnected", reply.header().messageId(),
                    reply.header().origin().clientId());
            return;
        }
        client.get().send(reply);
    }

    @Override
    public void failed(MailBox<IncomingServerMessage, OutgoingServerMessage> box, IncomingServerMessage request,
                       Throwable cause) {
        server.reply(error(request, Ids.FID_NONE, ErrorCode.INTERNAL, "the server failed on '"
                + Header.abbreviate(request.header().body()) + "': " + cause));
    }
}
