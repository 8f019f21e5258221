/**
 * A hot standby (issue 15, docs/operations.md "A hot standby"): RIPVServers that share a
 * PostgreSQL state database take turns through one session-level advisory lock. The server that
 * holds it ({@link org.ripv.server.standby.Leadership}) serves; every other one listens on
 * nothing — no client port, no registry, no landing page — and asks for the lock once a second.
 * The holder checks its lock every second; when it loses its database connection it stops
 * serving at once and stands by again ({@link org.ripv.server.standby.StandbyLoop}), before the
 * database has dropped its session and let another server take the lead.
 *
 * <p>Threads: {@code ripv-lead} (one per server: the checks on the lock's connection); the
 * launcher's main thread waits in {@link org.ripv.server.standby.StandbyLoop#run}.
 */
package org.ripv.server.standby;
