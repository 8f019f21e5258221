package org.ripv.messages;

/** A reply from a service to the server ({@code serviceReply}). */
public final class OutgoingServiceMessage extends Message {
    private static final long serialVersionUID = 1L;

    public OutgoingServiceMessage(Header header, Footer footer) {
        super(header, footer);
    }

    /** The reply as the server passes it on to the client. */
    public OutgoingServerMessage toClient(Footer footer) {
        return new OutgoingServerMessage(header(), footer);
    }
}
