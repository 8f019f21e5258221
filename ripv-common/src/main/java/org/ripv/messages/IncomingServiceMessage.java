package org.ripv.messages;

/** A request the server forwards to a service over RMI. */
public final class IncomingServiceMessage extends Message {
    private static final long serialVersionUID = 1L;

    public IncomingServiceMessage(Header header) {
        super(header, Footer.unanswered());
    }

    /** A reply from the service, to be sent back to the server. */
    public OutgoingServiceMessage reply(Footer footer) {
        return new OutgoingServiceMessage(header().withAttachment(null), footer);
    }
}
