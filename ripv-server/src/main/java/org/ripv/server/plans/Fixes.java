package org.ripv.server.plans;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.plans.SurfacingFacts;

/**
 * What a forecast starts from, per MailBox: the GPS fixes of its last surfacings (SURFACED's
 * position) and the depth-averaged current its last dialog showed ({@code m_water_vx} east,
 * {@code m_water_vy} north, m/s) and the waypoint it steered for. Kept in memory: after a server restart the next calls bring them.
 */
final class Fixes {
    record Fix(long time, double lat, double lon) {}

    record Current(double east, double north) {}

    /** The waypoint a dialog steered for ({@code c_wpt_lat/lon}), degrees. */
    record Heading(long time, double lat, double lon) {}

    private static final int KEPT = 5;
    private final Map<String, Deque<Fix>> fixes = new HashMap<>();
    private final Map<String, Current> currents = new HashMap<>();
    private final Map<String, Heading> headings = new HashMap<>();

    synchronized void take(ConsoleEntry e) {
        if (e.kind() == ConsoleEntry.Kind.EVENT && e.event() == VehicleEvent.SURFACED && e.lat() != null && e.lon() != null
                && Math.abs(e.lat()) <= 90 && Math.abs(e.lon()) <= 180 && fixes.size() < 10_000) {
            Deque<Fix> d = fixes.computeIfAbsent(e.mailbox(), k -> new ArrayDeque<>());
            d.addLast(new Fix(e.time(), e.lat(), e.lon()));
            while (d.size() > KEPT) {
                d.removeFirst();
            }
        }
    }

    synchronized void take(SurfacingFacts f) {
        Double vx = f.sensors().get("m_water_vx");
        Double vy = f.sensors().get("m_water_vy");
        if (vx != null && vy != null && Math.abs(vx) < 10 && Math.abs(vy) < 10 && currents.size() < 10_000) {
            currents.put(f.mailbox(), new Current(vx, vy));
        }
        if (f.wptLat() != null && f.wptLon() != null && headings.size() < 10_000) {
            headings.put(f.mailbox(), new Heading(f.time(), f.wptLat(), f.wptLon()));
        }
    }

    synchronized Optional<Fix> last(String mailbox) {
        Deque<Fix> d = fixes.get(mailbox);
        return d == null || d.isEmpty() ? Optional.empty() : Optional.of(d.getLast());
    }

    /** The fix before the last, if any. */
    synchronized Optional<Fix> previous(String mailbox) {
        Deque<Fix> d = fixes.get(mailbox);
        if (d == null || d.size() < 2) {
            return Optional.empty();
        }
        Fix last = d.removeLast();
        Fix before = d.getLast();
        d.addLast(last);
        return Optional.of(before);
    }

    synchronized Optional<Heading> heading(String mailbox) {
        return Optional.ofNullable(headings.get(mailbox));
    }

    synchronized Optional<Current> current(String mailbox) {
        return Optional.ofNullable(currents.get(mailbox));
    }
}
