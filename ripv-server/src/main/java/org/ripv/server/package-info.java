/**
 * The RIPVServer broker (thesis figure 5.3): the RIPV Post Office and its TaskManager, service references over RMI, pending requests and timeouts, the {@code ?} commands, the launcher. Package-private except what launchers and tests need.
 */
package org.ripv.server;
