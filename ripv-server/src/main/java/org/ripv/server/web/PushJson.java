package org.ripv.server.web;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.atomic.AtomicReferenceArray;
import org.ripv.messages.OutgoingServerMessage;

/**
 * A console push as JSON, written once for all the pages it goes to: the console hub hands every
 * up-to-date watcher the same message object (encoded once for socket clients), so a line for
 * 10,000 watching pages is one JSON text and one UTF-8 buffer that every page's frame shares
 * (each page gets a duplicate: its own position, the same bytes), not 10,000 copies. Keyed by
 * identity in a few slots; messages are immutable records, so a hit is always right and a miss
 * only costs writing it again.
 */
final class PushJson {
    private record Entry(OutgoingServerMessage message, ByteBuffer utf8) {}

    private static final int SLOTS = 16;
    private final AtomicReferenceArray<Entry> slots = new AtomicReferenceArray<>(SLOTS);
    private final WebReplies replies = new WebReplies();

    /** The push's JSON as UTF-8, read-only; callers send a {@link ByteBuffer#duplicate()}. */
    ByteBuffer of(OutgoingServerMessage m) {
        int i = System.identityHashCode(m) & (SLOTS - 1);
        Entry e = slots.get(i);
        if (e != null && e.message() == m) {
            return e.utf8();
        }
        ByteBuffer utf8 = ByteBuffer.wrap(replies.toJson(m).getBytes(StandardCharsets.UTF_8)).asReadOnlyBuffer();
        slots.set(i, new Entry(m, utf8));
        return utf8;
    }

    /** A reply, asked by one page only: written for it alone. */
    String reply(OutgoingServerMessage m) {
        return replies.toJson(m);
    }
}
