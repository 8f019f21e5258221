package org.ripv.server.web;

import java.util.concurrent.atomic.AtomicReferenceArray;
import org.ripv.messages.OutgoingServerMessage;

/**
 * A console push as JSON, written once for all the pages it goes to: the console hub hands every
 * up-to-date watcher the same message object (encoded once for socket clients), so a line for
 * 10,000 watching pages is one JSON text, not 10,000 (Jetty still makes each page's frame its
 * own UTF-8 copy: docs/performance.md). Keyed by
 * identity in a few slots; messages are immutable records, so a hit is always right and a miss
 * only costs writing it again.
 */
final class PushJson {
    private record Entry(OutgoingServerMessage message, String json) {}

    private static final int SLOTS = 16;
    private final AtomicReferenceArray<Entry> slots = new AtomicReferenceArray<>(SLOTS);
    private final WebReplies replies = new WebReplies();

    String of(OutgoingServerMessage m) {
        int i = System.identityHashCode(m) & (SLOTS - 1);
        Entry e = slots.get(i);
        if (e != null && e.message() == m) {
            return e.json();
        }
        String json = replies.toJson(m);
        slots.set(i, new Entry(m, json));
        return json;
    }

    /** A reply, asked by one page only: written for it alone. */
    String reply(OutgoingServerMessage m) {
        return replies.toJson(m);
    }
}
