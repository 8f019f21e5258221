package org.ripv.server.plans;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Optional;

import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.plans.SensorLine;
import org.ripv.plans.SurfacingFacts;

/**
 * A stand-in surface-dialog reader: from a MailBox's SURFACED to the end of its call, every
 * {@code sensor:NAME(UNITS)=VALUE} line the vehicle printed; the call's end makes them one
 * {@link SurfacingFacts}. A full dialog parser can feed {@link Plans#surfacing} instead. Bounded:
 * at most {@value #MAX_SENSORS} sensors a call.
 */
final class DialogWindow {
    static final int MAX_SENSORS = 500;

    private record Open(long since, Map<String, Double> sensors) {}

    private final Map<String, Open> open = new HashMap<>();
    /** Sensor lines seen while no surfacing is open: a dialog's lines may come just before its SURFACED. */
    private final Map<String, Map<String, Double>> early = new HashMap<>();

    /** Takes one console entry; the facts of a surfacing when this entry ended it. */
    Optional<SurfacingFacts> take(ConsoleEntry e) {
        if (e.kind() == ConsoleEntry.Kind.EVENT) {
            if (e.event() == VehicleEvent.SURFACED) {
                Map<String, Double> first = early.remove(e.mailbox());
                Open was = open.put(e.mailbox(), new Open(e.time(), first == null ? new LinkedHashMap<>() : first));
                return was == null ? Optional.empty() : Optional.of(SurfacingFacts.of(e.mailbox(), was.since(), was.sensors()));
            }
            if (e.event() == VehicleEvent.DIVED || e.event() == VehicleEvent.LINK_LOST) {
                Open was = open.remove(e.mailbox());
                early.remove(e.mailbox());
                return was == null ? Optional.empty() : Optional.of(SurfacingFacts.of(e.mailbox(), was.since(), was.sensors()));
            }
            return Optional.empty();
        }
        if (e.kind() != ConsoleEntry.Kind.LINE) {
            return Optional.empty();
        }
        Open o = open.get(e.mailbox());
        Map<String, Double> into = o != null ? o.sensors()
                : early.size() < 10_000 ? early.computeIfAbsent(e.mailbox(), k -> new LinkedHashMap<>()) : null;
        if (into != null && into.size() < MAX_SENSORS) {
            SensorLine.parse(e.text()).ifPresent(s -> into.putIfAbsent(s.name(), s.value()));
        }
        return Optional.empty();
    }
}
