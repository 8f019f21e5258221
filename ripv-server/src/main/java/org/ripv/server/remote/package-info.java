/**
 * The server's side of {@link org.ripv.rmi.GenericRMIInterface}, which services call: over RMI
 * ({@link org.ripv.server.remote.ServerRemote}: registration by challenge–response, replies,
 * heartbeats, console entries) and, for services behind NAT, over one outbound TCP connection
 * ({@link org.ripv.server.remote.OutboundListener}). Both hand registrations to
 * {@link org.ripv.server.services.ServiceAdmission} and replies to
 * {@link org.ripv.server.requests.ServiceReplies}.
 */
package org.ripv.server.remote;
