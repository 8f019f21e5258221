package org.ripv.server.requests;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.TablePages;
import org.ripv.messages.TableResult;
import org.ripv.naming.MailboxAddress;
import org.ripv.naming.MalformedNameException;
import org.ripv.server.dataloop.ServiceCalls;
import org.ripv.server.files.DownloadAttachments;
import org.ripv.server.files.DownloadRights;
import org.ripv.server.files.FileStore;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.SecurityRefusal;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.services.ServiceRegistry;

/**
 * The server's own requests to services ({@link ServiceCalls}): forwarded like a client's, with
 * client id {@code 000000}; the server's outbox hands their replies here instead of to a socket.
 */
public final class InternalCalls implements ServiceCalls {
    /** One of our requests: its future, its progress reports, and the pages of a table it is receiving. */
    private record Waiter(CompletableFuture<Footer> done, Consumer<Footer> progress, TablePages pages) {}

    private final ServiceRegistry services;
    private final Supplier<PermitFile> permits;
    private final FileStore files;
    private final RequestForwarder forwarder;
    private final AtomicLong ids = new AtomicLong();
    private final Map<Long, Waiter> waiting = new ConcurrentHashMap<>();

    public InternalCalls(ServiceRegistry services, Supplier<PermitFile> permits, FileStore files, RequestForwarder forwarder) {
        this.services = services;
        this.permits = permits;
        this.files = files;
        this.forwarder = forwarder;
    }

    @Override
    public List<String> services(String sid) {
        return services.all().stream().filter(r -> r.descriptor().sid().equals(sid)).map(r -> r.descriptor().name()).toList();
    }

    @Override
    public String whyNotDownload(String user, String downloadName) {
        try {
            DownloadRights.check(files, permits.get(), user, downloadName);
            return null;
        } catch (IOException | IllegalArgumentException e) { // a SecurityRefusal is one
            return e.getMessage();
        }
    }

    @Override
    public boolean permitted(String user, String mailbox, String body) {
        try {
            MailboxAddress a = MailboxAddress.parse(mailbox);
            PermitFile p = permits.get();
            return p.user(user).map(u -> p.decide(u, a.service().service(), a.handle(), body)
                    .allowed()).orElse(false);
        } catch (MalformedNameException e) {
            return false;
        }
    }

    @Override
    public CompletableFuture<Footer> call(String mailbox, String body, String user, List<String> roles, Attachment attachment,
                                          Consumer<Footer> progress) {
        CompletableFuture<Footer> done = new CompletableFuture<>();
        MailboxAddress address;
        try {
            address = MailboxAddress.parse(mailbox);
        } catch (MalformedNameException e) {
            done.complete(Footer.error(Ids.FID_NONE, ErrorCode.UNKNOWN_MAILBOX, e.getMessage()));
            return done;
        }
        Optional<ServiceReference> ref = services.find(address.service().toString());
        if (ref.isEmpty()) {
            done.complete(Footer.error(Ids.FID_NONE, ErrorCode.UNKNOWN_SERVICE, "no service " + address.service()
                    + " is registered"));
            return done;
        }
        Attachment a = attachment;
        if (a == null) {
            try {
                a = DownloadAttachments.forCommand(files, ref.get().descriptor(), body,
                        name -> DownloadRights.check(files, permits.get(), user, name));
            } catch (SecurityRefusal e) {
                done.complete(Footer.error(ref.get().descriptor().sid(), ErrorCode.FORBIDDEN, e.getMessage()));
                return done;
            } catch (IOException | IllegalArgumentException e) {
                done.complete(Footer.error(ref.get().descriptor().sid(), ErrorCode.BAD_FILE_NAME, e.getMessage()));
                return done;
            }
        }
        long id = ids.incrementAndGet();
        waiting.put(id, new Waiter(done, progress == null ? f -> { } : progress, new TablePages()));
        Header h = new Header(id, new IdBadge(IdBadge.SERVER.clientId(), user), roles, ref.get().descriptor().name(), mailbox,
                body, Priority.NORMAL, a);
        forwarder.forward(ref.get(), new IncomingServiceMessage(h));
        return done;
    }

    /** Takes a reply meant for one of our requests; false when it is a client's. */
    public boolean accept(OutgoingServerMessage reply) {
        if (!reply.header().origin().clientId().equals(IdBadge.SERVER.clientId())) {
            return false;
        }
        long id = reply.header().messageId();
        if (!reply.status().isFinal()) {
            Waiter w = waiting.get(id);
            if (w != null && TablePages.isPage(reply.footer())) {
                w.pages().add((TableResult) reply.footer().result());
            } else if (w != null) {
                w.progress().accept(reply.footer());
            }
            return true;
        }
        Waiter w = waiting.remove(id);
        if (w != null) {
            w.done().complete(w.pages().join(reply.footer()));
        }
        return true;
    }
}
