package org.ripv.server.plans;

import java.util.List;
import java.util.Locale;

/**
 * One change sent to a vehicle: a behaviour file ({@code FILE}: {@code target} is the name on the
 * vehicle) or a parameter ({@code SET}: {@code target} the sensor, {@code value} its new value),
 * and how far it got. Times are epoch ms (0 until reached). {@code waypoints} are a goto file's
 * (lat, lon) pairs in degrees, which its "in effect" is judged by.
 */
record Change(long id, String mailbox, Kind kind, String target, String value, String source, String sha256, long bytes,
              String user, State state, long queuedAt, long sentAt, long receivedAt, long settledAt, int surfacings,
              String staged, long workflowId, String detail, List<double[]> waypoints) {

    enum Kind { FILE, SET }

    enum State {
        QUEUED, SENT, RECEIVED, IN_EFFECT, NOT_IN_EFFECT,
        /** A file whose staged copy was deleted or replaced before a call took it: nothing of it reaches the vehicle. */
        CANCELLED;

        String word() {
            return name().toLowerCase(Locale.ROOT).replace('_', ' ');
        }

        boolean settled() {
            return this == IN_EFFECT || this == NOT_IN_EFFECT || this == CANCELLED;
        }
    }

    Change {
        waypoints = List.copyOf(waypoints);
    }

    /** What it is, for people: {@code goto_l10.ma (from goto_l11.ma)} or {@code put c_dive_target_depth 30}. */
    String what() {
        return kind == Kind.SET ? "put " + target + " " + value
                : target + (source.equals(target) ? "" : " (from " + source + ")");
    }

    Change moved(State to, long at, String why) {
        return new Change(id, mailbox, kind, target, value, source, sha256, bytes, user, to, queuedAt,
                to == State.SENT ? at : sentAt, to == State.RECEIVED ? at : receivedAt, to.settled() ? at : settledAt,
                surfacings, staged, workflowId, why, waypoints);
    }

    Change withSurfacings(int n, String why) {
        return new Change(id, mailbox, kind, target, value, source, sha256, bytes, user, state, queuedAt, sentAt, receivedAt,
                settledAt, n, staged, workflowId, why, waypoints);
    }

    Change withDetail(String why) {
        return withSurfacings(surfacings, why);
    }
}
