package org.ripv.post;

import java.time.Instant;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import org.ripv.messages.Header;
import org.ripv.messages.Message;

/**
 * Locks a {@link MailBox} while a command runs in it, so one conversation with a device happens
 * at a time (thesis 5.2.6). The inbox assistant takes it before handing a message to the
 * TaskManager and gives it back when the command has finished.
 */
public final class MailBoxKey {
    /** Who holds the key and since when. */
    public record Holder(String who, String command, Instant since) {}

    /**
     * The request holding the key and when it took it. Kept as the request itself: who and what
     * are only put in words when someone asks ({@link #holder}), not for every command run.
     */
    private record Taken(Message request, long sinceMillis) {
        Holder describe() {
            Header h = request.header();
            return new Holder(h.origin().user() + "@" + h.origin().clientId(), Header.abbreviate(h.body()),
                    Instant.ofEpochMilli(sinceMillis));
        }
    }

    private final AtomicReference<Taken> holder = new AtomicReference<>();

    void take(Message request) {
        if (!holder.compareAndSet(null, new Taken(request, System.currentTimeMillis()))) {
            throw new IllegalStateException("key already held by " + holder().orElse(null));
        }
    }

    void giveBack() {
        holder.set(null);
    }

    /** True while a command runs in the MailBox. */
    public boolean isHeld() {
        return holder.get() != null;
    }

    public Optional<Holder> holder() {
        return Optional.ofNullable(holder.get()).map(Taken::describe);
    }
}
