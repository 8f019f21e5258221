package org.ripv.services.serial.zmodem;

import java.io.IOException;

/**
 * A ZMODEM transfer failed: a timeout, too many errors, a peer that broke the protocol (lied
 * about a size or an offset, sent garbage instead of frames) or aborted with CANs.
 */
public class ZmodemException extends IOException {
    private static final long serialVersionUID = 1L;

    /** Why a transfer ended, which decides what happens to a partial file. */
    public enum Kind {
        /** Time ran out or errors piled up: what arrived is sound and is kept for a resume. */
        LINE,
        /** The peer broke the protocol: nothing it sent in this file is trusted. */
        PROTOCOL,
        /** The peer aborted (five CANs). */
        ABORTED,
        /** The vehicle's shell answered with text instead of starting ZMODEM. */
        REFUSED
    }

    private final Kind kind;

    public ZmodemException(Kind kind, String message) {
        super(message);
        this.kind = kind;
    }

    public Kind kind() {
        return kind;
    }
}
