/**
 * The Fleet view: every vehicle with its last position, the time since that fix and a small
 * track, from the database's {@code positions} view (through the DatabaseServer) and the server's
 * vehicle state in {@code ?mailboxes}. {@link org.ripv.client.fleet.FleetModel} is plain code,
 * tested headless; {@link org.ripv.client.fleet.FleetView} is the window.
 */
package org.ripv.client.fleet;
