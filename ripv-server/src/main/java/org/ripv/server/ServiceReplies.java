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
        f = store(server, f);
        // Route by the header the server sent, never by what the service wrote back.
        OutgoingServerMessage out = new IncomingServerMessage(p.header()).reply(f.via(RIPVServer.SERVER_SERVICE));
        if (!server.dataLoop().downloaded(out, sent, server::reply)) { // DBA files go to the database first
            server.reply(out);
        }
    }

    /** Writes files from a reply into the download directory and replaces their bytes with a listing. */
    private static Footer store(RIPVServer server, Footer f) {
        Result r = f.result();
        List<FileData> files = r instanceof FileData d ? List.of(d) : r instanceof FileBundle b ? b.files() : List.of();
        try {
            if (r instanceof ImageResult img) {
                server.files().storeDownload(img.name(), img.jpeg());
                return f;
            }
            if (files.isEmpty()) {
                return f;
            }
            List<FileListing.Entry> stored = new ArrayList<>();
            for (FileData d : files) {
                if (d.offset() != 0 || !d.isLast()) {
                    throw new IOException("a service sent part of '" + d.name() + "' where a whole file belongs");
                }
                server.files().storeDownload(d.name(), d.data());
                stored.add(new FileListing.Entry(d.name(), d.data().length, System.currentTimeMillis()));
            }
            return f.withResult(new FileListing(server.files().downloadDir().toString(), stored));
        } catch (IOException | IllegalArgumentException e) {
            log.warn("could not store a file from a reply: {}", e.getMessage());
            return new Footer(f.serviceId(), org.ripv.messages.Status.ERROR, ErrorCode.TRANSFER_FAILED, f.route(),
                    (f.replyText().isEmpty() ? "" : f.replyText() + "\n") + "the server could not store the file: " + e.getMessage(),
                    null);
        }
    }
}
