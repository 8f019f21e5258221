/**
 * The RIPVServer broker's lobby (thesis figure 5.3): {@link org.ripv.server.RIPVServer} opens the
 * parts, gives each the collaborators it uses and closes them; {@link org.ripv.server.ServerMain}
 * launches it from the command line with {@link org.ripv.server.ServerConfig} and
 * {@link org.ripv.server.SessionOptions} (public: tests and embedders build them);
 * {@code ServerState} opens the state store first and closes it last; {@code Threads} names the
 * server's threads. Everything else lives by concern: the RIPV Post Office's TaskManager and the
 * admission of requests in {@link org.ripv.server.routing}, the {@code ?} commands in
 * {@link org.ripv.server.commands}, requests awaiting a service in
 * {@link org.ripv.server.requests}, the services in {@link org.ripv.server.services}, the RMI
 * side services call in {@link org.ripv.server.remote}, the clients in
 * {@link org.ripv.server.clients}. No part takes RIPVServer.
 */
package org.ripv.server;
