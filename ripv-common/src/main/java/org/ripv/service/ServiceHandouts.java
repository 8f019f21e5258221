package org.ripv.service;

import java.rmi.RemoteException;
import java.util.List;
import java.util.function.BooleanSupplier;
import org.ripv.exceptions.ServiceException;
import org.ripv.handout.HandoutCollector;
import org.ripv.handout.HandoutRefused;
import org.ripv.handout.Handouts;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.Result;
import org.ripv.rmi.RmiSupport;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A service's part in handing files from service to service ({@link org.ripv.handout}): as a
 * holder, it keeps the files its replies send ({@link RIPVService#handsOutFiles}) and hands them
 * out by ticket; as an ingester, it reads the files a request's tickets name before the request's
 * handler runs, so that the handler sees an ordinary attachment.
 */
final class ServiceHandouts {
    private static final Logger log = LoggerFactory.getLogger(ServiceHandouts.class);

    private final String self;
    private final BooleanSupplier holds;
    private volatile Handouts held;
    private volatile HandoutCollector.Peers peers = s -> {
        throw new RemoteException("not connected to a server");
    };

    ServiceHandouts(String self, BooleanSupplier holds) {
        this.self = self;
        this.holds = holds;
    }

    void peersVia(HandoutCollector.Peers p) {
        this.peers = p;
    }

    /** Keeps the whole files of an OK reply's result, when this service hands files out. */
    void keep(Result r) {
        List<FileData> files = r instanceof FileData d ? List.of(d) : r instanceof FileBundle b ? b.files() : List.of();
        if (files.isEmpty() || !holds.getAsBoolean()) {
            return;
        }
        Handouts h = store();
        for (FileData f : files) {
            if (f.offset() == 0 && f.isLast()) {
                h.hold(f.data());
            }
        }
    }

    /** The next chunk of a held file, for another service; a refusal as a {@link SecurityException} (it crosses RMI). */
    byte[] read(String ticket, long offset, int max, String token) {
        Handouts h = held;
        try {
            if (h == null) {
                throw new HandoutRefused(self + " holds no files to hand out");
            }
            return h.read(ticket, offset, max, self, token);
        } catch (HandoutRefused e) {
            log.info("refused a handout: {}", e.getMessage());
            throw new SecurityException(e.getMessage());
        }
    }

    /**
     * The request with its tickets replaced by the files they name.
     *
     * @throws ServiceException {@code TRANSFER_FAILED}, text starting {@link HandoutCollector#REFUSED}
     */
    IncomingServiceMessage collect(IncomingServiceMessage request) throws ServiceException {
        Attachment a = request.header().attachment();
        // Only the server's own requests carry tickets: a user's upload that happens to be named like them stays a file.
        if (!HandoutCollector.carriesTickets(a) || !IdBadge.SERVER.clientId().equals(request.header().origin().clientId())) {
            return request;
        }
        long t0 = System.nanoTime();
        try {
            Attachment files = HandoutCollector.collect(a, peers, self, RmiSupport.MAX_RMI_BYTES);
            log.info("read {} ({} bytes) from the services that fetched it, in {} ms", files.name(), files.data().length,
                    (System.nanoTime() - t0) / 1_000_000);
            return new IncomingServiceMessage(request.header().withAttachment(files));
        } catch (HandoutRefused e) {
            log.warn("{}{}", HandoutCollector.REFUSED, e.getMessage());
            throw new ServiceException(ErrorCode.TRANSFER_FAILED, HandoutCollector.REFUSED + e.getMessage());
        }
    }

    private Handouts store() {
        Handouts h = held;
        if (h == null) {
            synchronized (this) {
                if (held == null) {
                    held = Handouts.defaults();
                }
                h = held;
            }
        }
        return h;
    }
}
