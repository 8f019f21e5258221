/**
 * Text that users and vehicles give RIPV — notify messages, workflow names, event text, vehicle
 * lines — is kept as data and printed escaped wherever it meets a terminal or a log: ESC, BEL,
 * the C1 controls and the other non-printing characters become visible ({@code ^[}, {@code ^G},
 * {@code \u009b}), so nobody's text can move another user's cursor, retitle their terminal, ring
 * its bell or forge a log line (issue 23, item 8). {@link org.ripv.text.Printable} does it;
 * {@link org.ripv.text.SafeMessageConverter} does it for every log line ({@code %safemsg}).
 */
package org.ripv.text;
