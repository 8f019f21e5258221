/**
 * The SocketHandler: one per connected client, the frames it parses (fed by the selector threads of
 * org.ripv.server.transport) and the client's own bounded reply queue; the WriterPool's few
 * threads write every client's socket.
 */
package org.ripv.server.handlers;
