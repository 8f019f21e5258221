package org.ripv.wire;

import java.io.IOException;

/** A peer broke the socket protocol: a bad greeting, frame or message. The connection is closed. */
public class ProtocolException extends IOException {
    private static final long serialVersionUID = 1L;

    public ProtocolException(String message) {
        super(message);
    }

    public ProtocolException(String message, Throwable cause) {
        super(message, cause);
    }
}
