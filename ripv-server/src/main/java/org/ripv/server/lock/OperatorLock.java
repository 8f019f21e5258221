package org.ripv.server.lock;

/**
 * An operator's hold on a MailBox ({@code ?lock MAILBOX SECONDS}, or a workflow's while it runs):
 * nobody else may command the MailBox until {@code untilMillis}.
 */
public record OperatorLock(String user, String clientId, long untilMillis) {
    public boolean expired() {
        return System.currentTimeMillis() > untilMillis;
    }
}
