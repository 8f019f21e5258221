/**
 * The server's side of its services (thesis: ServiceReference, figure 5.3): the services
 * registered now ({@link org.ripv.server.services.ServiceRegistry}), the handle on each with its
 * own sender thread, admission (a service is called back before it is listed, and a late
 * registration never replaces a newer one), the liveness checks that drop a service that no
 * longer answers, the shared secret a service proves it knows, and the RMI socket factory that
 * binds the registry and the server's remote object to the configured address. They live apart
 * from the client side because they fail differently: a service is a remote peer on RMI that
 * may hang or vanish, and nothing here may hold up a client or another service.
 */
package org.ripv.server.services;
