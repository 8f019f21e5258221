package org.ripv.server.requests;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Function;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.FileListing;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Footer;
import org.ripv.messages.ImageResult;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Result;
import org.ripv.messages.Status;
import org.ripv.messages.TablePages;
import org.ripv.server.dataloop.DataLoop;
import org.ripv.server.files.FileStore;
import org.ripv.server.handlers.SocketHandler;
import org.ripv.server.paging.PageRelay;
import org.ripv.server.services.ServiceReference;
import org.ripv.server.workflow.Workflows;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The footer side's first half: a service's reply arrives (on an RMI thread), is matched to the
 * request the server forwarded, and any files in it are stored in the download directory before
 * the reply is posted to the RIPV Post Office's outbox for its client.
 */
public final class ServiceReplies {
    private static final Logger log = LoggerFactory.getLogger(ServiceReplies.class);

    /** Pages of query results on their way to clients (issue 38); its threads end when idle, so one serves every server in the JVM. */
    private static final PageRelay PAGES = new PageRelay();

    private final PendingRequests pending;
    private final RequestCancels cancels;
    private final FileStore files;
    private final DataLoop dataLoop;
    private final Consumer<OutgoingServerMessage> outbox;
    private final Function<String, Optional<SocketHandler>> clients;

    /**
     * @param dataLoop takes the replies whose files go to the database first
     * @param outbox   where the replies go (the Post Office's outbox)
     */
    public ServiceReplies(PendingRequests pending, RequestCancels cancels, FileStore files, DataLoop dataLoop,
                          Consumer<OutgoingServerMessage> outbox, Function<String, Optional<SocketHandler>> clients) {
        this.pending = pending;
        this.cancels = cancels;
        this.files = files;
        this.dataLoop = dataLoop;
        this.outbox = outbox;
        this.clients = clients;
    }

    /** A reply from {@code ref}, as its service called it back. */
    public void accept(ServiceReference ref, OutgoingServiceMessage reply) {
        String service = ref.descriptor().name();
        PendingRequests.Pending p = reply.status().isFinal() ? pending.complete(reply.header(), service)
                : pending.touch(reply.header(), service);
        if (p == null) {
            log.info("dropped a reply from {} to #{} of client {}: no such request is pending there (timed out, or the client left)",
                    ref, reply.header().messageId(), reply.header().origin().clientId());
            return;
        }
        Footer f = reply.footer();
        if (!f.serviceId().equals(ref.descriptor().sid())) {
            f = new Footer(ref.descriptor().sid(), f.status(), f.errorCode(), f.route(), f.replyText(), f.result());
        }
        Result sent = f.result();
        f = store(f, folderOf(p.header().mailboxAddress()));
        f = cancels.judge(p, f);
        // Route by the header the server sent, never by what the service wrote back.
        OutgoingServerMessage out = new IncomingServerMessage(p.header()).reply(f.via(ServerReplies.SERVICE));
        if (TablePages.isPage(f)) {
            String clientId = p.header().origin().clientId();
            PAGES.relay(out, ref, clients, IdBadge.SERVER.clientId().equals(clientId) || Workflows.isWorkflowClient(clientId),
                    outbox);
            return;
        }
        if (!dataLoop.downloaded(out, sent, outbox)) { // DBA files go to the database first
            outbox.accept(out);
        }
    }

    /** The MailBox's whole address: each MailBox's files live in a folder of their own (FileStore#folderFor). */
    private static String folderOf(String mailboxAddress) {
        return mailboxAddress;
    }

    /**
     * Writes files from a reply into the MailBox's folder of the download directory and replaces
     * their bytes with a listing of the names they are fetched by ({@code FOLDER/NAME}).
     */
    private Footer store(Footer f, String folder) {
        Result r = f.result();
        List<FileData> parts = r instanceof FileData d ? List.of(d) : r instanceof FileBundle b ? b.files() : List.of();
        try {
            if (r instanceof ImageResult img) {
                String as = files.storeDownload(folder, img.name(), img.jpeg());
                return f.withText(storedAs(f.replyText(), List.of(as)));
            }
            if (parts.isEmpty()) {
                return f;
            }
            List<FileListing.Entry> stored = new ArrayList<>();
            List<String> names = new ArrayList<>();
            for (FileData d : parts) {
                if (d.offset() != 0 || !d.isLast()) {
                    throw new IOException("a service sent part of '" + d.name() + "' where a whole file belongs");
                }
                String as = files.storeDownload(folder, d.name(), d.data());
                names.add(as);
                stored.add(new FileListing.Entry(as, d.data().length, System.currentTimeMillis()));
            }
            return f.withText(storedAs(f.replyText(), names)).withResult(new FileListing("download", stored));
        } catch (IOException | IllegalArgumentException e) {
            log.warn("could not store a file from a reply: {}", e.getMessage());
            return new Footer(f.serviceId(), Status.ERROR, ErrorCode.TRANSFER_FAILED, f.route(),
                    (f.replyText().isEmpty() ? "" : f.replyText() + "\n") + "the server could not store the file: " + e.getMessage(),
                    null);
        }
    }

    private static String storedAs(String text, List<String> names) {
        return (text.isEmpty() ? "" : text + "\n") + "stored in the download directory as " + String.join(", ", names);
    }
}
