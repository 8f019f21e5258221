package org.ripv.post;

import java.time.Instant;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Locks a {@link MailBox} while a command runs in it, so one conversation with a device happens
 * at a time (thesis 5.2.6). The inbox assistant takes it before handing a message to the
 * TaskManager and gives it back when the command has finished.
 */
public final class MailBoxKey {
    /** Who holds the key and since when. */
    public record Holder(String who, String command, Instant since) {}

    private final AtomicReference<Holder> holder = new AtomicReference<>();

    void take(String who, String command) {
        if (!holder.compareAndSet(null, new Holder(who, command, Instant.now()))) {
            throw new IllegalStateException("key already held by " + holder.get());
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
        return Optional.ofNullable(holder.get());
    }
}
