package org.ripv.server.session;

import java.io.IOException;
import java.util.ArrayDeque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.json.Json;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.messages.SessionState.State;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.BatchWriter;
import org.ripv.server.store.StateStore;
import org.ripv.surfacing.SurfaceDialogParser;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Each vehicle MailBox's call state, derived from the console entries: SURFACED puts it on call
 * (and counts the call), DIVED marks it dived, LINK_LOST lost; lines, transfers and vehicle
 * events are contact; a position that comes with any entry is the last position. The state is
 * saved in the server's {@link StateStore} on every event (embedded: {@code state.json} beside the
 * MailBox's transcript; PostgreSQL: a document), so it survives a server restart and a standby
 * that takes over starts from it.
 */
final class VehicleStates {
    private static final Logger log = LoggerFactory.getLogger(VehicleStates.class);
    /** Lines kept per MailBox for a watcher joining late and for e-mails. */
    static final int RECENT = 50;

    private final StateStore store;
    /** Saves on a thread of their own: a database that is slow or failing over never holds the hub's lock. */
    private final BatchWriter<Saved> saves;

    private record Saved(String mailbox, String json) {}
    private final Map<String, Vehicle> vehicles = new ConcurrentHashMap<>();
    /** The run of MailBoxes a service listed before they published anything (at most as many as services may list). */
    private final Map<String, Long> runs = new ConcurrentHashMap<>();

    /** One MailBox's state; guarded by the hub's lock. */
    static final class Vehicle {
        State state = State.UNKNOWN;
        long lastContact;
        Double lat;
        Double lon;
        int calls;
        /** When the instance of the service whose calls {@link #calls} counts started (epoch ms; 0: unknown). */
        long run;
        VehicleEvent lastEvent;
        /** When the dive countdown ends (epoch ms), or 0; not saved: it means nothing after the call. */
        long diveAt;
        /** The sequence number of the last entry taken (not saved: numbers from before a restart are lower). */
        long lastSeq;
        final ArrayDeque<ConsoleEntry> recent = new ArrayDeque<>();

        synchronized SessionState snapshot() {
            return new SessionState(state, lastContact, lat, lon, calls, lastEvent, lastSeq, diveAt);
        }

        synchronized List<ConsoleEntry> recent(int n) {
            List<ConsoleEntry> all = List.copyOf(recent);
            return all.subList(Math.max(0, all.size() - n), all.size());
        }
    }

    VehicleStates(StateStore store) {
        this.store = store;
        this.saves = new BatchWriter<>("ripv-vehicle-state-writer", 10_000, 1000, (batch, dropped) -> {
            if (dropped > 0) {
                log.warn("{} vehicle state saves dropped: the state store could not keep up", dropped);
            }
            Map<String, String> newest = new LinkedHashMap<>();
            batch.forEach(x -> newest.put(x.mailbox(), x.json())); // only each MailBox's last state matters
            newest.forEach((mailbox, json) -> {
                try {
                    store.saveVehicleState(mailbox, json);
                } catch (IOException | RuntimeException e) {
                    log.warn("could not save the state of {}: {}", mailbox, e.toString());
                }
            });
        });
    }

    /** Waits (briefly) until the states changed so far are saved. */
    void sync() {
        saves.sync();
    }

    /** Saves what waits, then stops. */
    void close() {
        saves.close();
    }

    /**
     * A new run of the MailBox's service (an instance that started at {@code started}, epoch ms):
     * calls count from 0 again, as the service's own "call N" does, so that no line says two
     * counts. The same instance registering again (a server restart) keeps its count.
     */
    void runStarted(String mailbox, long started) {
        Vehicle v = vehicles.get(mailbox);
        if (v == null) {
            v = load(mailbox);
        }
        if (v == null) {
            runs.merge(mailbox, started, Math::max); // nothing heard from it yet: its first entry takes the run
            return;
        }
        synchronized (v) {
            if (started <= v.run) {
                return;
            }
            v.run = started;
            // The server hears of the new instance in the background: calls it already took count.
            v.calls = (int) v.recent.stream().filter(e -> e.event() == VehicleEvent.SURFACED && e.time() >= started).count();
        }
        save(mailbox, v);
    }

    /** Takes one entry into its MailBox's state; true when the state changed in a way worth saving. */
    boolean apply(ConsoleEntry e) {
        Vehicle v = vehicle(e.mailbox());
        boolean save = false;
        synchronized (v) {
            v.recent.addLast(e);
            v.lastSeq = Math.max(v.lastSeq, e.seq());
            if (v.recent.size() > RECENT) {
                v.recent.removeFirst();
            }
            if (e.isContact()) {
                v.lastContact = Math.max(v.lastContact, e.time());
            }
            if (e.kind() == ConsoleEntry.Kind.LINE) {
                long seconds = SurfaceDialogParser.countdownSeconds(e.text());
                if (seconds >= 0 && seconds <= 86_400) {
                    v.diveAt = e.time() + seconds * 1000; // "dives in N s" on every page from the state
                }
            }
            if (e.lat() != null && e.lon() != null && Double.isFinite(e.lat()) && Double.isFinite(e.lon())
                    && Math.abs(e.lat()) <= 90 && Math.abs(e.lon()) <= 180) {
                v.lat = e.lat();
                v.lon = e.lon();
            }
            if (e.kind() == ConsoleEntry.Kind.EVENT) {
                v.lastEvent = e.event();
                if (e.event().callState() != null) {
                    v.state = e.event().callState();
                    v.diveAt = 0; // a new call, its end or the link lost: no countdown runs
                }
                if (e.event().startsCall()) {
                    v.calls++;
                }
                save = true;
            }
        }
        if (save) {
            save(e.mailbox(), v);
        }
        return save;
    }

    /** The MailBoxes of a service (by address prefix) that are on call now. */
    List<String> onCall(String servicePrefix) {
        return vehicles.entrySet().stream()
                .filter(x -> x.getKey().startsWith(servicePrefix) && x.getValue().snapshot().state() == State.ON_CALL)
                .map(Map.Entry::getKey).sorted().toList();
    }

    /** True when the MailBox is on a call last heard from before {@code millis} (epoch ms), here or before a restart. */
    boolean onCallBefore(String mailbox, long millis) {
        SessionState s = state(mailbox);
        return s != null && s.state() == State.ON_CALL && s.lastContact() < millis;
    }

    /** The state, or null when the MailBox never published an event or line (here or before a restart). */
    SessionState state(String mailbox) {
        Vehicle v = vehicles.get(mailbox);
        if (v == null) {
            v = load(mailbox);
            if (v == null) {
                return null;
            }
        }
        return v.snapshot();
    }

    List<ConsoleEntry> recent(String mailbox, int n) {
        Vehicle v = vehicles.get(mailbox);
        return v == null ? List.of() : v.recent(n);
    }

    private Vehicle vehicle(String mailbox) {
        Vehicle v = vehicles.get(mailbox);
        if (v != null) {
            return v;
        }
        Vehicle loaded = load(mailbox);
        return loaded != null ? loaded : vehicles.computeIfAbsent(mailbox, k -> {
            Vehicle fresh = new Vehicle();
            Long run = runs.remove(k);
            fresh.run = run == null ? 0 : run;
            return fresh;
        });
    }

    /** Reads the saved state of a MailBox not seen since the server started. */
    private Vehicle load(String mailbox) {
        try {
            Optional<String> saved = store.loadVehicleState(mailbox);
            if (saved.isEmpty()) {
                return null;
            }
            Map<String, Object> m = Json.parse(saved.get().strip());
            Vehicle v = new Vehicle();
            v.state = State.valueOf(String.valueOf(m.get("state")));
            v.lastContact = m.get("lastContact") instanceof Number n ? n.longValue() : 0;
            v.lat = m.get("lat") instanceof Number n ? n.doubleValue() : null;
            v.lon = m.get("lon") instanceof Number n ? n.doubleValue() : null;
            v.calls = m.get("calls") instanceof Number n ? (int) Math.min(Integer.MAX_VALUE, n.longValue()) : 0;
            v.run = m.get("run") instanceof Number n ? n.longValue() : 0;
            v.lastEvent = m.get("lastEvent") instanceof String s ? VehicleEvent.valueOf(s) : null;
            Vehicle raced = vehicles.putIfAbsent(mailbox, v);
            return raced != null ? raced : v;
        } catch (IOException | RuntimeException e) {
            log.warn("ignoring the unreadable state of {}: {}", mailbox, e.toString());
            return null;
        }
    }

    private void save(String mailbox, Vehicle v) {
        Map<String, Object> m = new LinkedHashMap<>();
        SessionState s = v.snapshot();
        m.put("mailbox", mailbox);
        m.put("state", s.state().name());
        m.put("lastContact", s.lastContact());
        m.put("lat", s.lat());
        m.put("lon", s.lon());
        m.put("calls", s.calls());
        synchronized (v) {
            m.put("run", v.run);
        }
        m.put("lastEvent", s.lastEvent() == null ? null : s.lastEvent().name());
        saves.offer(new Saved(mailbox, Json.write(m) + "\n"));
    }
}
