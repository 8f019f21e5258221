package org.ripv.services.serial.ymodem;

import java.io.IOException;

/** A YMODEM transfer failed: too many errors, a timeout, or the far end cancelled (CAN CAN). */
public class YmodemException extends IOException {
    private static final long serialVersionUID = 1L;
    private final boolean cancelledByPeer;

    public YmodemException(String message) {
        this(message, false);
    }

    public YmodemException(String message, boolean cancelledByPeer) {
        super(message);
        this.cancelledByPeer = cancelledByPeer;
    }

    /** True when the other end aborted with CAN CAN. */
    public boolean cancelledByPeer() {
        return cancelledByPeer;
    }
}
