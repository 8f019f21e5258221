/**
 * What listens on a port, for errors that say what to do: a client pointed at the server's RMI
 * registry or its landing page, or a service pointed at the client port, is told which port it
 * reached instead of a TLS or JRMP failure that misleads ({@link org.ripv.probe.PortProbe}).
 * And which ports are free for a process about to be launched, outside the range the kernel
 * hands out to everyone else ({@link org.ripv.probe.FreePorts}).
 */
package org.ripv.probe;
