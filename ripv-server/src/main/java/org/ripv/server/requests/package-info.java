/**
 * What the server remembers about a request it forwarded to a service until that service
 * answers: the pending table with its deadlines, and how a request ends when no answer comes
 * (never delivered, timed out, or lost with its service). Kept apart so that the rule "every
 * forwarded request ends with exactly one reply" has one home, which the RIPV Post Office and
 * the service side both use but neither owns. {@link org.ripv.server.requests.ServerReplies}
 * says how the server words its own replies.
 */
package org.ripv.server.requests;
