package org.ripv.server.session;

import org.ripv.messages.OutgoingServerMessage;

/** Where a watcher's messages go: one client connection. */
public interface Outlet {
    /**
     * Queues a push without blocking; {@code written} runs once it has gone out. False when the
     * connection is closed or too far behind.
     */
    boolean push(OutgoingServerMessage message, Runnable written);

    /** Queues an ordinary reply. */
    void send(OutgoingServerMessage reply);
}
