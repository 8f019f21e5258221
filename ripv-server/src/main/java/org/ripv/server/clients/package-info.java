/**
 * The server's side of its clients: the client port's accept loop and the table of connected
 * clients by id, the door through which the web console's pages become clients, and the vehicle
 * sessions those clients see (console hub, transcripts, notifications, operator locks that run
 * out). Kept apart from the services side because a client is an untrusted connection the server
 * must outlive, answered through its SocketHandler, while a service is a registered RMI peer.
 * What a client's frame does once parsed ({@code ClientDispatch}) stays with RIPVServer, as it
 * reaches into the server's locks, pending requests and security.
 */
package org.ripv.server.clients;
