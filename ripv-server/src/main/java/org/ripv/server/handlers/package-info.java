/**
 * The SocketHandler: one per connected client, a reader thread and the client's own bounded reply
 * queue; the WriterPool's few threads write every client's socket.
 */
package org.ripv.server.handlers;
