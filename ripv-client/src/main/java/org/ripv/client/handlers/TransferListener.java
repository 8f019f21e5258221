package org.ripv.client.handlers;

/** Progress of an upload or download, called from the transferring thread. */
@FunctionalInterface
public interface TransferListener {
    /** @return false to cancel the transfer */
    boolean progress(long done, long total);

    TransferListener NONE = (d, t) -> true;
}
