package org.ripv.client.handlers;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;

/** The server answered a request with ERROR. The message is the server's own text. */
public class RipvErrorException extends Exception {
    private static final long serialVersionUID = 1L;
    private final transient OutgoingServerMessage reply;

    public RipvErrorException(OutgoingServerMessage reply) {
        super(reply.footer().replyText());
        this.reply = reply;
    }

    public ErrorCode code() {
        return reply.footer().errorCode();
    }

    public OutgoingServerMessage reply() {
        return reply;
    }
}
