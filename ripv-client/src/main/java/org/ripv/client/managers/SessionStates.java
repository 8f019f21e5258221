package org.ripv.client.managers;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;

/**
 * Brings a vehicle's call state ({@code ?mailboxes}, {@code ?status}) up to date with the console
 * entries pushed since, the way the server derives it (docs/sessions.md "State"), by the rules
 * both share ({@link org.ripv.messages.VehicleEvent#callState}, {@link ConsoleEntry#isContact}):
 * SURFACED → on call (one more call), DIVED → dived, LINK_LOST → lost; every entry from the
 * vehicle (not commands, locks, workflows or LINK_LOST) is a contact. So badges change the moment an event
 * arrives, not at the next refresh.
 *
 * <p>What is news is decided by the console's order, not by the clock: the server numbers every
 * entry ({@link ConsoleEntry#seq()}) and says which number a state counts up to
 * ({@link SessionState#lastSeq()}), so SURFACED and DIVED made in the same millisecond are both
 * taken, and a replay of entries already counted is not counted twice. Only when either side has no
 * number (a transcript read back, an older server) does the time decide, as before.
 */
public final class SessionStates {
    private SessionStates() {
    }

    /**
     * The state after {@code e}; {@code s} itself when {@code e} is one {@code s} already counts (a
     * replay repeating known entries). {@code s} may be null (nothing known yet).
     */
    public static SessionState apply(SessionState s, ConsoleEntry e) {
        if (e == null || s != null && counted(s, e)) {
            return s;
        }
        SessionState.State st = s == null ? SessionState.State.UNKNOWN : s.state();
        long contact = s == null ? 0 : s.lastContact();
        int calls = s == null ? 0 : s.calls();
        boolean fromVehicle = e.isContact();
        if (e.kind() == ConsoleEntry.Kind.EVENT) {
            if (e.event().callState() != null) {
                st = e.event().callState();
            }
            if (e.event().startsCall()) {
                calls++;
            }
        }
        if (!fromVehicle && st == (s == null ? SessionState.State.UNKNOWN : s.state())) {
            return s; // a command, a lock or a workflow says nothing of the vehicle
        }
        if (fromVehicle) {
            contact = Math.max(contact, e.time());
        }
        Double lat = e.lat() != null && e.lon() != null ? e.lat() : s == null ? null : s.lat();
        Double lon = e.lat() != null && e.lon() != null ? e.lon() : s == null ? null : s.lon();
        return new SessionState(st, contact, lat, lon, calls, e.event() != null ? e.event() : s == null ? null : s.lastEvent(),
                Math.max(e.seq(), s == null ? 0 : s.lastSeq()));
    }

    /** True when {@code s} already counts {@code e}: by number when both have one, else by time. */
    private static boolean counted(SessionState s, ConsoleEntry e) {
        if (e.seq() > 0 && s.lastSeq() > 0) {
            return e.seq() <= s.lastSeq();
        }
        return e.time() <= s.lastContact();
    }
}
