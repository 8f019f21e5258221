/**
 * The permit file: users with PBKDF2 hashes and roles, and allow/deny rules per service, mailbox and command pattern (docs/permit.md).
 */
package org.ripv.server.permit;
