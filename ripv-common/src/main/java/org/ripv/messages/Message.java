package org.ripv.messages;

import java.io.IOException;
import java.io.InvalidObjectException;
import java.io.ObjectInputStream;
import java.io.Serializable;
import java.util.Objects;

/**
 * What travels between the parts of RIPV: a {@link Header} saying who asks what of whom, and a
 * {@link Footer} with the answer. The four concrete types are named for the part of the system
 * the message travels to or from (thesis 5.2.5):
 * <ul>
 *   <li>{@link IncomingServerMessage}: client to server, a request</li>
 *   <li>{@link IncomingServiceMessage}: server to service, the same request, checked and stamped</li>
 *   <li>{@link OutgoingServiceMessage}: service to server, a reply</li>
 *   <li>{@link OutgoingServerMessage}: server to client, the reply</li>
 * </ul>
 * Messages are immutable; each hop makes the next type from the last.
 */
public abstract sealed class Message implements Serializable
        permits IncomingServerMessage, OutgoingServerMessage, IncomingServiceMessage, OutgoingServiceMessage {

    private static final long serialVersionUID = 1L;

    private final Header header;
    private final Footer footer;

    Message(Header header, Footer footer) {
        this.header = Objects.requireNonNull(header, "header");
        this.footer = Objects.requireNonNull(footer, "footer");
    }

    public final Header header() {
        return header;
    }

    public final Footer footer() {
        return footer;
    }

    /** The reply's status, short for {@code footer().status()}. */
    public final Status status() {
        return footer.status();
    }

    /** Travels as a {@link PackedMessage}: a fraction of the cost of the records' default form. */
    protected final Object writeReplace() {
        return PackedMessage.pack(this);
    }

    private void readObject(ObjectInputStream in) throws IOException, ClassNotFoundException {
        in.defaultReadObject();
        if (header == null || footer == null) {
            throw new InvalidObjectException("a message needs a header and a footer");
        }
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "{" + header + ", " + footer + "}";
    }
}
