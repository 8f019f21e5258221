package org.ripv.messages;

/** A reply from the server to a client. */
public final class OutgoingServerMessage extends Message {
    private static final long serialVersionUID = 1L;

    public OutgoingServerMessage(Header header, Footer footer) {
        super(header, footer);
    }
}
