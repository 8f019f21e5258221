/**
 * Notifications of vehicle events (docs/sessions.md): users subscribe with {@code ?notify} to
 * webhooks (one JSON POST per event) or e-mail (through the SMTP server given with
 * {@code --smtp}); deliveries retry with back-off on executors of their own, so a hung or failing
 * receiver never holds up the broker; subscriptions and their last result persist in the data
 * directory.
 */
package org.ripv.server.notify;
