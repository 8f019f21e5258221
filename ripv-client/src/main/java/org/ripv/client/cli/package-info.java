/**
 * {@code ripv cli}: the COM panel's command language for terminals and scripts, with aligned tables and --json.
 */
package org.ripv.client.cli;
