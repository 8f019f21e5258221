package org.ripv.handout;

import java.io.IOException;

/** A handout that cannot be had: a forged, used or expired ticket, a file let go, a peer out of reach. */
public final class HandoutRefused extends IOException {
    public HandoutRefused(String message) {
        super(message);
    }

    public HandoutRefused(String message, Throwable cause) {
        super(message, cause);
    }
}
