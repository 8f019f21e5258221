package org.ripv.messages;

/** A request from a client to the server (the client's side of the socket). */
public final class IncomingServerMessage extends Message {
    private static final long serialVersionUID = 1L;

    public IncomingServerMessage(Header header) {
        super(header, Footer.unanswered());
    }

    /** The request as the server forwards it to a service. */
    public IncomingServiceMessage toService(Header stamped) {
        return new IncomingServiceMessage(stamped);
    }

    /** A reply to this request, as the server sends it back to the client. */
    public OutgoingServerMessage reply(Footer footer) {
        return new OutgoingServerMessage(header().withAttachment(null), footer);
    }
}
