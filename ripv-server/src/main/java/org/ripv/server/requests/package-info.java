/**
 * What the server remembers about a request it forwarded to a service until that service
 * answers: the pending table with its deadlines, and how a request ends when no answer comes
 * (never delivered, timed out, or lost with its service). Kept apart so that the rule "every
 * forwarded request ends with exactly one reply" has one home, which the RIPV Post Office and
 * the service side both use but neither owns. Cancels ({@code RequestCancels}) stay with
 * RIPVServer because they check the permit file and publish on the server's console.
 */
package org.ripv.server.requests;
