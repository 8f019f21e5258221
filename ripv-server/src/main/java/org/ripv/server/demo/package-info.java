/**
 * What {@code ./ripv demo} starts besides the product's own parts, so that a new user can try
 * every part on one machine: {@link org.ripv.server.demo.WebhookSink}, a receiver for the
 * server's webhooks on loopback (docs/operations.md#the-demo). Nothing here runs in a real
 * deployment.
 */
package org.ripv.server.demo;
