package org.ripv.messages;

import java.io.Serializable;
import java.util.Objects;

/**
 * One entry of a vehicle MailBox's live console and transcript: a line the vehicle printed, a
 * command someone sent, an event, or a transfer's start, progress or end. Services publish
 * entries with {@code RIPVService.publish}; the server fans them out to watchers, keeps them in
 * the transcript and derives the MailBox's state from the events.
 *
 * @param time    when it happened, epoch milliseconds
 * @param mailbox the full MailBox address
 * @param kind    what the entry is
 * @param user    who sent it (commands; the user a transfer runs for), or empty
 * @param text    the line, command, event detail or transfer summary; never binary, already cut
 *                to the link's line length
 * @param event   the event for {@link Kind#EVENT} entries, else null
 * @param lat     a position that came with it (decimal degrees, north positive), or null
 * @param lon     decimal degrees, east positive, or null
 * @param seq     the entry's place in the server's console, increasing across MailBoxes and server
 *                restarts (the server stamps it as it takes the entry); 0 when not stamped (a
 *                service's entry on its way, or one read back from a transcript). Two entries of a
 *                MailBox made in the same millisecond still have different numbers.
 */
public record ConsoleEntry(long time, String mailbox, Kind kind, String user, String text, VehicleEvent event,
                           Double lat, Double lon, long seq) implements Serializable {

    /** What a console entry is. */
    public enum Kind { LINE, COMMAND, EVENT, TRANSFER }

    /** True when this entry is a contact with the vehicle: its lines and transfers, and the events it caused ({@link VehicleEvent#fromVehicle}). */
    public boolean isContact() {
        return switch (kind) {
            case LINE, TRANSFER -> true;
            case COMMAND -> false;
            case EVENT -> event != null && event.fromVehicle();
        };
    }

    public ConsoleEntry {
        Objects.requireNonNull(mailbox, "mailbox");
        Objects.requireNonNull(kind, "kind");
        user = user == null ? "" : user;
        text = text == null ? "" : text;
        if (kind == Kind.EVENT) {
            Objects.requireNonNull(event, "event");
        }
    }

    /** An entry the server has not stamped yet. */
    public ConsoleEntry(long time, String mailbox, Kind kind, String user, String text, VehicleEvent event,
                        Double lat, Double lon) {
        this(time, mailbox, kind, user, text, event, lat, lon, 0);
    }

    /** This entry with its place in the server's console. */
    public ConsoleEntry withSeq(long number) {
        return new ConsoleEntry(time, mailbox, kind, user, text, event, lat, lon, number);
    }

    public static ConsoleEntry line(String mailbox, String text) {
        return new ConsoleEntry(System.currentTimeMillis(), mailbox, Kind.LINE, "", text, null, null, null);
    }

    public static ConsoleEntry command(String mailbox, String user, String command) {
        return new ConsoleEntry(System.currentTimeMillis(), mailbox, Kind.COMMAND, user, command, null, null, null);
    }

    public static ConsoleEntry transfer(String mailbox, String user, String text) {
        return new ConsoleEntry(System.currentTimeMillis(), mailbox, Kind.TRANSFER, user, text, null, null, null);
    }

    public static ConsoleEntry event(String mailbox, VehicleEvent event, String detail, Double lat, Double lon) {
        return new ConsoleEntry(System.currentTimeMillis(), mailbox, Kind.EVENT, "", detail, event, lat, lon);
    }
}
