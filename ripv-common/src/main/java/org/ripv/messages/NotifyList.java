package org.ripv.messages;

import java.io.Serializable;
import java.util.List;

/** A user's notification subscriptions ({@code ?notify list}), each with how its last delivery went. */
public record NotifyList(List<Subscription> subscriptions) implements Result {
    public NotifyList {
        subscriptions = List.copyOf(subscriptions);
    }

    /**
     * One subscription.
     *
     * @param id         what {@code ?notify remove ID} takes
     * @param user       whose it is
     * @param channel    {@code webhook} or {@code email}
     * @param target     the URL or the address
     * @param events     the event names, or {@code all}
     * @param mailboxes  a glob over MailBox addresses ({@code *}: every MailBox the user may read)
     * @param lastResult how the last delivery went ({@code never used}, {@code ok 200 at ...}, {@code failed ...})
     */
    public record Subscription(String id, String user, String channel, String target, String events, String mailboxes,
                               String lastResult) implements Serializable {}
}
