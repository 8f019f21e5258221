/**
 * The PostOffice and its MailBoxes (thesis figure 5.2): three FIFO inboxes by priority, an outbox, and the MailBoxKey that holds a MailBox while a command runs.
 */
package org.ripv.post;
