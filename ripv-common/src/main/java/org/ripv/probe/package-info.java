/**
 * What listens on a port, for errors that say what to do: a client pointed at the server's RMI
 * registry or its landing page, or a service pointed at the client port, is told which port it
 * reached instead of a TLS or JRMP failure that misleads ({@link org.ripv.probe.PortProbe}).
 */
package org.ripv.probe;
