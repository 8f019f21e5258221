package org.ripv.server.requests;

import java.util.function.Consumer;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.services.ServiceReference;

/**
 * Hands a checked request to its service (thesis figure 5.3: "ServiceReference.serviceRequest"):
 * from here on it is pending, with a deadline, until exactly one final reply ends it.
 */
public final class RequestForwarder {
    private final PendingRequests pending;
    private final Consumer<OutgoingServerMessage> outbox;

    /** @param outbox where a refusal goes (the Post Office's outbox) */
    public RequestForwarder(PendingRequests pending, Consumer<OutgoingServerMessage> outbox) {
        this.pending = pending;
        this.outbox = outbox;
    }

    /** Forwards a checked request to its service; the request is now pending. */
    public void forward(ServiceReference ref, IncomingServiceMessage request) {
        if (!pending.add(request.header(), ref.descriptor().name())) {
            outbox.accept(new IncomingServerMessage(request.header()).reply(Footer.error(ref.descriptor().sid(),
                    ErrorCode.BAD_REQUEST, "message id " + request.header().messageId() + " is already in use by a pending request")));
            return;
        }
        ref.forward(request);
    }
}
