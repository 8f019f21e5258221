/**
 * The server's side of its services (thesis: ServiceReference, figure 5.3): the handle on each
 * registered service with its own sender thread, the liveness checks that drop a service that no
 * longer answers, the shared secret a service proves it knows, and the RMI socket factory that
 * binds the registry and the server's remote object to the configured address. They live apart
 * from the client side because they fail differently: a service is a remote peer on RMI that
 * may hang or vanish, and nothing here may hold up a client or another service. Registration
 * itself ({@code ServiceAdmission}) and the remote object ({@code ServerRemote}) stay with
 * RIPVServer, as they reach into its service table and secret, which it keeps to itself.
 */
package org.ripv.server.services;
