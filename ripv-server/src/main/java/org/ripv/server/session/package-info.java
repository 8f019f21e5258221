/**
 * Vehicle sessions on the server (docs/sessions.md): the live console's watchers and their
 * bounded, self-paced backlogs ({@link org.ripv.server.session.ConsoleHub}), each vehicle
 * MailBox's call state derived from the events, the per-vehicle transcript files and
 * {@code ?history}, and the read right that watching and history need.
 */
package org.ripv.server.session;
