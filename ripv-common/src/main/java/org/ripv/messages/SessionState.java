package org.ripv.messages;

import java.io.Serializable;
import java.util.Locale;

/**
 * What the server knows of a vehicle MailBox's calls, derived from the events its service
 * publishes (docs/sessions.md). Carried in {@link MailboxStatus#session()}.
 *
 * @param state       on call, dived, lost, or unknown (no event seen yet)
 * @param lastContact epoch milliseconds of the last console entry from the vehicle, or 0
 * @param lat         the last position's latitude (decimal degrees), or null
 * @param lon         the last position's longitude, or null
 * @param calls       how many calls (SURFACED events) the server has seen
 * @param lastEvent   the last event, or null
 * @param lastSeq     the {@link ConsoleEntry#seq()} of the last console entry this state counts, or 0
 *                    when unknown: an entry with a higher number is news, one with a lower or equal
 *                    number is already counted, whatever the millisecond it was made in
 * @param diveAt      epoch milliseconds when the surface dialog's countdown ("Hit Control-C within N
 *                    seconds to abort the mission") ends and the vehicle dives, or 0 when no
 *                    countdown runs (docs/surfacings.md)
 */
public record SessionState(State state, long lastContact, Double lat, Double lon, int calls, VehicleEvent lastEvent,
                           long lastSeq, long diveAt) implements Serializable {

    /** A vehicle MailBox's call state. */
    public enum State {
        UNKNOWN, ON_CALL, DIVED, LOST;

        /** Lower case with a space, for people: {@code on call}. */
        public String words() {
            return name().toLowerCase(Locale.ROOT).replace('_', ' ');
        }
    }

    public SessionState {
        state = state == null ? State.UNKNOWN : state;
    }

    /** A state with no dive countdown running. */
    public SessionState(State state, long lastContact, Double lat, Double lon, int calls, VehicleEvent lastEvent, long lastSeq) {
        this(state, lastContact, lat, lon, calls, lastEvent, lastSeq, 0);
    }

    /** A state that does not say which console entries it counts. */
    public SessionState(State state, long lastContact, Double lat, Double lon, int calls, VehicleEvent lastEvent) {
        this(state, lastContact, lat, lon, calls, lastEvent, 0);
    }

    /** True when a position is known. */
    public boolean hasPosition() {
        return lat != null && lon != null;
    }
}
