package org.ripv.server.session;

import org.ripv.messages.OutgoingServerMessage;

/** Where a watcher's messages go: one client connection. */
public interface Outlet {
    /**
     * Queues a push without blocking; {@code written} runs once it has gone out. {@code frame} is
     * the message already encoded, or null. False when the connection is closed or too far behind.
     */
    boolean push(OutgoingServerMessage message, byte[] frame, Runnable written);

    /** Queues an ordinary reply. */
    void send(OutgoingServerMessage reply);

    /** False once the connection has closed (its watches are then being removed, or must be). */
    boolean isOpen();
}
