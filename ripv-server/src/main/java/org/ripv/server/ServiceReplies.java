package org.ripv.server;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.FileListing;
import org.ripv.messages.Footer;
import org.ripv.messages.ImageResult;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Result;
import org.ripv.server.requests.PendingRequests;
import org.ripv.server.requests.ServerReplies;
import org.ripv.server.services.ServiceReference;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The footer side's first half: a service's reply arrives (on an RMI thread), is matched to the
 * request the server forwarded, and any files in it are stored in the download directory before
 * the reply is posted to the RIPV Post Office's outbox for its client.
 */
final class ServiceReplies {
    private static final Logger log = LoggerFactory.getLogger(ServiceReplies.class);

    private ServiceReplies() {}

    static void accept(RIPVServer server, ServiceReference ref, OutgoingServiceMessage reply, PendingRequests pending) {
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
        f = store(server, f, folderOf(p.header().mailboxAddress()));
        f = server.cancels().judge(p, f);
        // Route by the header the server sent, never by what the service wrote back.
        OutgoingServerMessage out = new IncomingServerMessage(p.header()).reply(f.via(ServerReplies.SERVICE));
        if (!server.dataLoop().downloaded(out, sent, server::reply)) { // DBA files go to the database first
            server.reply(out);
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
    private static Footer store(RIPVServer server, Footer f, String folder) {
        Result r = f.result();
        List<FileData> files = r instanceof FileData d ? List.of(d) : r instanceof FileBundle b ? b.files() : List.of();
        try {
            if (r instanceof ImageResult img) {
                String as = server.files().storeDownload(folder, img.name(), img.jpeg());
                return f.withText(storedAs(f.replyText(), List.of(as)));
            }
            if (files.isEmpty()) {
                return f;
            }
            List<FileListing.Entry> stored = new ArrayList<>();
            List<String> names = new ArrayList<>();
            for (FileData d : files) {
                if (d.offset() != 0 || !d.isLast()) {
                    throw new IOException("a service sent part of '" + d.name() + "' where a whole file belongs");
                }
                String as = server.files().storeDownload(folder, d.name(), d.data());
                names.add(as);
                stored.add(new FileListing.Entry(as, d.data().length, System.currentTimeMillis()));
            }
            return f.withText(storedAs(f.replyText(), names)).withResult(new FileListing("download", stored));
        } catch (IOException | IllegalArgumentException e) {
            log.warn("could not store a file from a reply: {}", e.getMessage());
            return new Footer(f.serviceId(), org.ripv.messages.Status.ERROR, ErrorCode.TRANSFER_FAILED, f.route(),
                    (f.replyText().isEmpty() ? "" : f.replyText() + "\n") + "the server could not store the file: " + e.getMessage(),
                    null);
        }
    }

    private static String storedAs(String text, List<String> names) {
        return (text.isEmpty() ? "" : text + "\n") + "stored in the download directory as " + String.join(", ", names);
    }
}
