package org.ripv.client.cli;

import org.ripv.client.handlers.ClientSocketHandler;

/**
 * Logs in again after the connection was lost: the same server restarted, or the next of a
 * {@code --server} list (a standby that took over). Used by {@code --follow} and the interactive CLI.
 */
@FunctionalInterface
public interface Reconnect {
    /** A new connection, logged in as before; throws when no server of the list took it. */
    ClientSocketHandler connect() throws Exception;
}
