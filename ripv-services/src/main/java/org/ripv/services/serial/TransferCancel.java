package org.ripv.services.serial;

/**
 * {@code ?cancel} for a link's YMODEM or ZMODEM transfer: asked from another thread, seen by the
 * transfer where it answers or sends a block (then it aborts with CANs). A cancel that comes while
 * no transfer runs asks nothing of the next one.
 */
final class TransferCancel {
    private volatile boolean transferring;
    private volatile boolean requested;

    /** A transfer starts, with no cancel asked yet. */
    void started() {
        requested = false;
        transferring = true;
    }

    void ended() {
        transferring = false;
    }

    /**
     * Asks the running transfer to stop.
     *
     * @return false when no transfer is running
     */
    boolean request() {
        if (!transferring) {
            return false;
        }
        requested = true;
        return true;
    }

    /** Whether {@code ?cancel} asked the running transfer to stop: what the protocol ends poll. */
    boolean requested() {
        return requested;
    }
}
