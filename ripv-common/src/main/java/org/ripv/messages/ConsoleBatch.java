package org.ripv.messages;

import java.io.Serial;
import java.util.List;
import java.util.Objects;

/**
 * Console entries pushed to a client watching a MailBox ({@code ?watch}), or returned by
 * {@code ?history}. Pushes come unasked: message id 0, status PROGRESS, FID
 * {@link Ids#FID_CONSOLE}, so they never complete a request.
 *
 * @param mailbox the MailBox they belong to
 * @param entries in the order the service published them
 * @param skipped entries this watcher missed just before these because it read too slowly
 *                (a marker line among {@code entries} says so too); 0 normally
 * @param more    for {@code ?history}: true when older entries were left out to keep the reply bounded
 */
public record ConsoleBatch(String mailbox, List<ConsoleEntry> entries, long skipped, boolean more) implements Result {
    public ConsoleBatch {
        Objects.requireNonNull(mailbox, "mailbox");
        entries = List.copyOf(entries);
    }

    /** Travels as one packed array ({@link PackedConsole}), not an object per entry and field. */
    @Serial
    private Object writeReplace() {
        return new PackedConsole(this);
    }
}
