/**
 * What both ends of a RIPV connection compute alike: certificate fingerprints for trust on
 * first use, and the HMAC challenge–response with which a service and the server prove to each
 * other that they hold the service secret without sending it (docs/security.md).
 */
package org.ripv.security;
