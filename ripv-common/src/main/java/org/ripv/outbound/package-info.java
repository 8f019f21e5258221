/**
 * Outbound-only mode for services behind NAT or a firewall: the service opens one TCP connection
 * to the server, both sides prove they know the service secret by HMAC without sending it
 * ({@link org.ripv.outbound.OutboundHandshake}), and then the calls of
 * {@link org.ripv.rmi.GenericRMIInterface} travel both ways over that connection
 * ({@link org.ripv.outbound.CallChannel}): length-prefixed frames, each one filtered object
 * stream, with call ids so that calls in both directions share the line.
 */
package org.ripv.outbound;
