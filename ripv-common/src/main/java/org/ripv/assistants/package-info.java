/**
 * The pair of threads each MailBox has (thesis 5.2.6): the InboxAssistantThread runs requests one at a time, highest priority first; the OutboxAssistantThread delivers replies.
 */
package org.ripv.assistants;
