/**
 * The RIPV clients' entry point: the Swing RIPVClient and the command-line client.
 */
package org.ripv.client;
