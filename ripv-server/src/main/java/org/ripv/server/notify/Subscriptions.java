package org.ripv.server.notify;

import java.io.IOException;
import java.security.SecureRandom;
import java.util.Collection;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.StateStore;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The subscriptions in force, kept in the state store (embedded: an owner-only file, one JSON
 * object per line; it names addresses and URLs): added with a fresh id within the per-user cap,
 * removed by their owner, each with the result of its last delivery.
 */
final class Subscriptions {
    private static final Logger log = LoggerFactory.getLogger(Subscriptions.class);
    /** Subscriptions one user may hold. */
    static final int MAX_PER_USER = 50;

    private final StateStore store;
    private final Map<String, Subscription> subscriptions = new ConcurrentHashMap<>();
    private final SecureRandom random = new SecureRandom();

    Subscriptions(StateStore store) throws IOException {
        this.store = store;
        load();
    }

    /** Adds a checked subscription under a fresh id, within the user's cap. */
    synchronized Subscription add(String user, Subscription.Channel channel, String target, Set<VehicleEvent> wanted,
                                  boolean allEvents, String glob) throws IOException {
        if (subscriptions.values().stream().filter(s -> s.user.equals(user)).count() >= MAX_PER_USER) {
            throw new IllegalArgumentException("a user may hold at most " + MAX_PER_USER + " subscriptions; ?notify remove some");
        }
        String id;
        do {
            byte[] b = new byte[4];
            random.nextBytes(b);
            id = "n" + HexFormat.of().formatHex(b);
        } while (subscriptions.containsKey(id));
        Subscription s = new Subscription(id, user, channel, target, wanted, allEvents, glob);
        subscriptions.put(id, s);
        save();
        return s;
    }

    /** Removes a user's subscription; false when the user has none with that id. */
    synchronized boolean remove(String user, String id) throws IOException {
        Subscription s = subscriptions.get(id);
        if (s == null || !s.user.equals(user)) {
            return false;
        }
        subscriptions.remove(id);
        save();
        return true;
    }

    List<Subscription> of(String user) {
        return subscriptions.values().stream().filter(s -> s.user.equals(user)).sorted((a, b) -> a.id.compareTo(b.id)).toList();
    }

    private void load() throws IOException {
        Optional<StateStore.Stored> stored = store.loadSubscriptions();
        if (stored.isEmpty()) {
            return;
        }
        int n = 0;
        for (String line : stored.get().text().split("\n")) {
            n++;
            if (line.isBlank()) {
                continue;
            }
            try {
                Subscription s = Subscription.fromJson(line);
                subscriptions.put(s.id, s);
            } catch (IllegalArgumentException e) {
                log.warn("{}:{}: ignoring an unreadable subscription: {}", stored.get().where(), n, e.getMessage());
            }
        }
    }

    /** Replaces the stored subscriptions whole (embedded: an owner-only file; it names addresses and URLs). */
    private synchronized void save() throws IOException {
        StringBuilder b = new StringBuilder();
        subscriptions.values().stream().sorted((a, c) -> a.id.compareTo(c.id)).forEach(s -> b.append(s.toJson()).append('\n'));
        store.saveSubscriptions(b.toString());
    }

    /** Whether a subscription is still in force (not removed meanwhile). */
    boolean holds(Subscription s) {
        return subscriptions.containsKey(s.id);
    }

    Collection<Subscription> all() {
        return subscriptions.values();
    }

    /** Records a delivery's result and keeps it (a failure to save is logged: the delivery happened). */
    void result(Subscription s, String r) {
        s.lastResult(r);
        if (!holds(s)) {
            return;
        }
        try {
            save();
        } catch (IOException e) {
            log.warn("could not save the subscriptions: {}", e.toString());
        }
    }
}
