/**
 * The ClientSocketHandler (thesis figure 5.5): requests out, replies matched to them and passed to listeners; file transfers in chunks; TLS.
 */
package org.ripv.client.handlers;
