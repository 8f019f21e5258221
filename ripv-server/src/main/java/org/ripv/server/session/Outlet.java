package org.ripv.server.session;

import java.util.function.Supplier;
import org.ripv.messages.OutgoingServerMessage;

/** Where a watcher's messages go: one client connection. */
public interface Outlet {
    /**
     * Queues a push without blocking; {@code written} runs once it has gone out. {@code frame}
     * gives the message encoded once for every socket client (or null): asked only by a
     * connection that writes the server's frames, so a line watched only by web pages is never
     * encoded in them. False when the connection is closed or too far behind.
     */
    boolean push(OutgoingServerMessage message, Supplier<byte[]> frame, Runnable written);

    /** Queues an ordinary reply. */
    void send(OutgoingServerMessage reply);

    /** False once the connection has closed (its watches are then being removed, or must be). */
    boolean isOpen();
}
