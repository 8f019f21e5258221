/**
 * The SocketHandler: one per connected client, a reader thread and a writer thread with the client's own bounded reply queue.
 */
package org.ripv.server.handlers;
