package org.ripv.client.managers;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;

/**
 * Brings a vehicle's call state ({@code ?mailboxes}, {@code ?status}) up to date with the console
 * entries pushed since, the way the server derives it (docs/sessions.md "State"): SURFACED → on
 * call (one more call), DIVED → dived, LINK_LOST → lost; every entry from the vehicle (not
 * commands, locks, workflows or LINK_LOST) is a contact. So badges change the moment an event
 * arrives, not at the next refresh.
 */
public final class SessionStates {
    private SessionStates() {
    }

    /**
     * The state after {@code e}; {@code s} itself when {@code e} is not newer than what {@code s}
     * already counts (a replay repeating known entries). {@code s} may be null (nothing known yet).
     */
    public static SessionState apply(SessionState s, ConsoleEntry e) {
        if (e == null || s != null && e.time() <= s.lastContact()) {
            return s;
        }
        SessionState.State st = s == null ? SessionState.State.UNKNOWN : s.state();
        long contact = s == null ? 0 : s.lastContact();
        int calls = s == null ? 0 : s.calls();
        boolean fromVehicle = e.kind() != ConsoleEntry.Kind.COMMAND;
        if (e.kind() == ConsoleEntry.Kind.EVENT) {
            switch (e.event()) {
                case SURFACED -> {
                    st = SessionState.State.ON_CALL;
                    calls++;
                }
                case DIVED -> st = SessionState.State.DIVED;
                case LINK_LOST -> {
                    st = SessionState.State.LOST;
                    fromVehicle = false;
                }
                case LOCK_TAKEN, LOCK_RELEASED, WORKFLOW_DONE, WORKFLOW_FAILED, WORKFLOW_DONE_WITH_ERRORS, INGEST_WAITING,
                        INGEST_RELEASED -> fromVehicle = false;
                default -> { }
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
        return new SessionState(st, contact, lat, lon, calls, e.event() != null ? e.event() : s == null ? null : s.lastEvent());
    }
}
