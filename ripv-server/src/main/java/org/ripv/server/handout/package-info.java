/**
 * The server's part in handing a fetched file from the service that fetched it to the service that
 * ingests it ({@link org.ripv.handout}): it signs the one-use tickets, with the holder's session
 * token, for files whose rights it has decided and whose copy it has stored, and it tells a
 * registered service where another one is ({@code peer}). docs/security.md.
 *
 * <p>Threads: none of its own; called on the RMI threads that deliver replies and {@code peer} calls.
 */
package org.ripv.server.handout;
