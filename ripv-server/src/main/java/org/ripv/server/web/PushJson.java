package org.ripv.server.web;

import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.atomic.AtomicReferenceArray;
import org.eclipse.jetty.websocket.core.Frame;
import org.eclipse.jetty.websocket.core.OpCode;
import org.ripv.messages.OutgoingServerMessage;

/**
 * A console push as JSON in UTF-8, written once for all the pages it goes to: the console hub
 * hands every up-to-date watcher the same message object (encoded once for socket clients), so a
 * line for 10,000 watching pages is one buffer that every page's frame shares (each sends a slice:
 * its own position, the same bytes), not 10,000 copies — neither the CPU of encoding it per page
 * nor, when pages fall behind, the heap of each page's queued copy (docs/performance.md). Keyed by
 * identity in a few slots; messages are immutable records, so a hit is always right and a miss
 * only costs writing it again.
 *
 * <p>The frame around the bytes is shared too (issue 38: a frame and a slice per page were a fifth
 * of what the fan-out allocated per delivery). Jetty only reads a frame it sends on a page with
 * no extension — its flusher and its fragmenting write slices of the payload, never moving the
 * buffer — so pages without permessage-deflate send this very frame; a page with it gets a frame
 * of its own over a slice ({@link ConsoleSocket}): Jetty 12.0's deflater reads a slice too, but
 * nothing in its API promises it, and a deflater that consumed the shared bytes would empty them
 * for every page after it ({@code SharedPushFrameTest} mixes both kinds of page).
 */
final class PushJson {
    private record Entry(OutgoingServerMessage message, Frame frame) {}

    private static final int SLOTS = 16;
    private final AtomicReferenceArray<Entry> slots = new AtomicReferenceArray<>(SLOTS);
    private final WebReplies replies = new WebReplies();

    /**
     * The push as one text frame of UTF-8 JSON, shared: callers send it as it is, or a frame of
     * their own over a slice of its payload, and never write into it. The payload is a direct
     * buffer, so each page's write hands the kernel these bytes as they are (issue 38).
     */
    Frame of(OutgoingServerMessage m) {
        int i = System.identityHashCode(m) & (SLOTS - 1);
        Entry e = slots.get(i);
        if (e != null && e.message() == m) {
            return e.frame();
        }
        byte[] bytes = replies.toJson(m).getBytes(StandardCharsets.UTF_8);
        // Direct: the JDK writes a heap buffer by copying it into a direct one first, once per page.
        ByteBuffer utf8 = ByteBuffer.allocateDirect(bytes.length).put(bytes).flip();
        Frame frame = new Frame(OpCode.TEXT, utf8);
        slots.set(i, new Entry(m, frame));
        return frame;
    }

    /** A reply, asked by one page only: written for it alone. */
    String reply(OutgoingServerMessage m) {
        return replies.toJson(m);
    }
}
