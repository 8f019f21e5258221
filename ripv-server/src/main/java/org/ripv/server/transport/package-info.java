/**
 * The client port without a thread per client (issue 26): a few selector threads read every
 * connection, TLS through the JDK's {@link javax.net.ssl.SSLEngine} (or plain TCP with
 * {@code --plain}), and hand the bytes to the connection's
 * {@link org.ripv.server.handlers.SocketHandler}, which parses the frames (docs/concurrency.md).
 */
package org.ripv.server.transport;
