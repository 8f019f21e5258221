package org.ripv.post;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentSkipListMap;
import java.util.concurrent.TimeUnit;
import org.ripv.assistants.InboxAssistantThread;
import org.ripv.assistants.OutboxAssistantThread;
import org.ripv.managers.TaskManager;
import org.ripv.messages.Message;

/**
 * The MailBoxes of a server or service, each with its pair of assistants (thesis 5.2.6).
 * {@link #scan} files an incoming message in the MailBox its header names.
 */
public final class PostOffice<I extends Message, O extends Message> {

    /** What {@link #scan} did with a message. */
    public enum Delivery { DELIVERED, UNKNOWN_MAILBOX, FULL }

    private record Station<I extends Message, O extends Message>(
            MailBox<I, O> box, InboxAssistantThread<I, O> inbox, OutboxAssistantThread<I, O> outbox) {}

    private final Map<String, Station<I, O>> stations = new ConcurrentSkipListMap<>();
    private final int capacity;

    /** @param capacity how many requests each MailBox may hold waiting */
    public PostOffice(int capacity) {
        this.capacity = capacity;
    }

    /** Creates a MailBox, starts its assistants, and returns it. */
    public MailBox<I, O> open(String address, TaskManager<I, O> manager) {
        MailBox<I, O> box = new MailBox<>(address, capacity);
        Station<I, O> s = new Station<>(box, new InboxAssistantThread<>(box, manager),
                new OutboxAssistantThread<>(box, manager));
        if (stations.putIfAbsent(address, s) != null) {
            throw new IllegalStateException("a MailBox '" + address + "' is open already");
        }
        s.inbox().start();
        s.outbox().start();
        return box;
    }

    /** Files the message in the MailBox named by its header's mailbox address. */
    public Delivery scan(I message) {
        Station<I, O> s = stations.get(message.header().mailboxAddress());
        if (s == null) {
            return Delivery.UNKNOWN_MAILBOX;
        }
        return s.box().deliver(message) ? Delivery.DELIVERED : Delivery.FULL;
    }

    public Optional<MailBox<I, O>> mailbox(String address) {
        return Optional.ofNullable(stations.get(address)).map(Station::box);
    }

    /** The MailBoxes, in address order. */
    public List<MailBox<I, O>> mailboxes() {
        return stations.values().stream().map(Station::box).toList();
    }

    /** Stops a MailBox's assistants and removes it; waiting requests are returned unrun. */
    public List<I> close(String address) {
        Station<I, O> s = stations.remove(address);
        if (s == null) {
            return List.of();
        }
        s.inbox().shutdown(2000);
        s.outbox().shutdown(2000);
        List<I> left = new ArrayList<>();
        I m;
        try {
            while ((m = s.box().pollNext(0, TimeUnit.MILLISECONDS)) != null) {
                left.add(m);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return left;
    }

    /** Closes every MailBox. */
    public void stop() {
        for (String address : List.copyOf(stations.keySet())) {
            close(address);
        }
    }
}
