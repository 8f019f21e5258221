/**
 * Slocum glider files, recognised the same way by the server (which sends a fetched file to the
 * database) and the DatabaseServer (which decodes it): {@link org.ripv.slocum.SlocumFiles}.
 */
package org.ripv.slocum;
