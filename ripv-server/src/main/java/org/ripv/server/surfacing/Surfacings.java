package org.ripv.server.surfacing;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.type.TypeReference;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.time.Duration;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.naming.MailboxAddress;
import org.ripv.server.store.StateStore;
import org.ripv.surfacing.CallInterval;
import org.ripv.surfacing.CallOutlook;
import org.ripv.surfacing.SurfaceDialogParser;
import org.ripv.surfacing.Surfacing;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Reads every vehicle's surface dialogs from the console entries the server takes, keeps a call
 * record per surfacing in the state store, and publishes ALERT (rate-limited per vehicle and cause)
 * and OVERDUE events. The console hub hands it entries without waiting ({@link #accept}: a bounded
 * queue; what does not fit is counted and logged); one thread, {@code ripv-surfacings}, parses,
 * stores and checks, so a slow store or a flood delays only this.
 */
public final class Surfacings implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Surfacings.class);
    /** Call records kept per vehicle. */
    public static final int KEEP = 1000;
    static final int QUEUE = 50_000;
    /** Vehicles followed at once (the hub allows 1,000 MailBoxes per service). */
    static final int MAX_VEHICLES = 10_000;
    private static final TypeReference<LinkedHashMap<String, Object>> MAP = new TypeReference<>() {};

    /** A parsed surface dialog, for a part that reads dialogs (the plans' change follower). */
    @FunctionalInterface
    public interface Reader {
        /** Called on {@code ripv-surfacings}; {@code time} is when the dialog began (epoch ms). Must not block. */
        void surfacing(String mailbox, long time, Surfacing dialog);
    }

    private volatile Reader reader = (m, t, s) -> { };
    private final StateStore store;
    private final AlertRules rules;
    private final Consumer<ConsoleEntry> events;
    private final ObjectMapper json = new ObjectMapper();
    private final BlockingQueue<ConsoleEntry> queue = new ArrayBlockingQueue<>(QUEUE);
    private final AtomicLong dropped = new AtomicLong();
    private final Map<String, Vehicle> vehicles = new HashMap<>();
    private final Overdue overdue;
    private final Thread worker;
    private volatile boolean closed;
    /** Entries taken off the queue and done with; for {@link #sync}. */
    private final AtomicLong done = new AtomicLong();
    private final AtomicLong offered = new AtomicLong();

    /** One vehicle's dialog under way and what earlier calls said; the worker's only. */
    private final class Vehicle implements SurfaceDialogParser.Listener {
        final String mailbox;
        final String name;
        final SurfaceDialogParser parser = new SurfaceDialogParser(this);
        long start;
        long now;
        boolean ended;
        Map<String, Object> previous;
        boolean previousLoaded;
        final Map<String, Long> lastAlert = new HashMap<>();
        final Map<String, Integer> held = new HashMap<>();

        Vehicle(String mailbox) {
            this.mailbox = mailbox;
            String handle;
            try {
                handle = MailboxAddress.parse(mailbox).handle();
            } catch (IllegalArgumentException e) {
                handle = mailbox;
            }
            this.name = handle;
        }

        void line(ConsoleEntry e) {
            now = e.time();
            boolean before = parser.inDialog();
            ended = false;
            parser.line(e.text());
            if (parser.inDialog() && (!before || ended)) { // a dialog began on this line
                start = e.time();
            }
        }

        @Override
        public void surfacing(Surfacing s) {
            ended = true;
            recorded(this, s);
        }
    }

    /**
     * @param store  where call records are kept
     * @param rules  the alert rules file ({@code DATA/surfacing-alerts.conf}; need not exist)
     * @param events publishes an event entry as the server's own (the console hub's {@code serverEntry})
     */
    public Surfacings(StateStore store, Path rules, Consumer<ConsoleEntry> events) {
        this.store = store;
        this.rules = new AlertRules(rules);
        this.events = events;
        this.overdue = new Overdue(this::thresholds);
        this.worker = new Thread(this::work, "ripv-surfacings");
        worker.setDaemon(true);
        worker.start();
    }

    private AlertRules.Thresholds thresholds(String mailbox) {
        String name;
        try {
            name = MailboxAddress.parse(mailbox).handle();
        } catch (IllegalArgumentException e) {
            name = mailbox;
        }
        return rules.of(mailbox, name);
    }

    /** Where each parsed dialog goes besides its call record. */
    public void onSurfacing(Reader r) {
        this.reader = r;
    }

    /** Entries the server took; never waits. */
    public void accept(List<ConsoleEntry> taken) {
        for (ConsoleEntry e : taken) {
            if (!relevant(e)) {
                continue;
            }
            if (queue.offer(e)) {
                offered.incrementAndGet();
            } else if (dropped.incrementAndGet() % 10_000 == 1) {
                log.warn("surface dialogs: {} console entries not read so far; this server's vehicles print more than it parses",
                        dropped.get());
            }
        }
    }

    private static boolean relevant(ConsoleEntry e) {
        return e.kind() == ConsoleEntry.Kind.LINE || (e.kind() == ConsoleEntry.Kind.EVENT
                && (e.event() == VehicleEvent.SURFACED || e.event() == VehicleEvent.DIVED || e.event() == VehicleEvent.LINK_LOST));
    }

    private void work() {
        seedAll();
        while (!closed) {
            try {
                ConsoleEntry e = queue.poll(overdue.waitMillis(System.currentTimeMillis()), TimeUnit.MILLISECONDS);
                if (e != null) {
                    take(e);
                    done.incrementAndGet();
                }
                for (Overdue.Late late : overdue.check(System.currentTimeMillis())) {
                    publish(late.mailbox(), VehicleEvent.OVERDUE, late.text(), null, null);
                }
            } catch (InterruptedException x) {
                Thread.currentThread().interrupt();
                return;
            } catch (RuntimeException x) {
                log.warn("surface dialogs: {}", x.toString(), x);
            }
        }
    }

    private void take(ConsoleEntry e) {
        Vehicle v = vehicles.get(e.mailbox());
        if (v == null) {
            if (vehicles.size() >= MAX_VEHICLES) {
                return;
            }
            v = new Vehicle(e.mailbox());
            vehicles.put(e.mailbox(), v);
        }
        if (e.kind() == ConsoleEntry.Kind.LINE) {
            v.line(e);
            return;
        }
        v.now = e.time();
        if (e.event() != VehicleEvent.SURFACED) {
            v.parser.end(); // the call's end ends a dialog under way (SURFACED comes in the middle of one, after its fix)
        }
        if (e.event() == VehicleEvent.SURFACED) {
            if (!overdue.knows(e.mailbox())) {
                overdue.seed(e.mailbox(), callTimes(e.mailbox()), e.time()); // its calls before this server started
            }
            String back = overdue.called(e.mailbox(), e.time(),
                    CallInterval.announced(e.text()).orElse(null));
            if (back != null) {
                publish(e.mailbox(), VehicleEvent.OVERDUE, back, e.lat(), e.lon());
            }
        } else {
            overdue.ended(e.mailbox());
        }
    }

    private void recorded(Vehicle v, Surfacing s) {
        if (!v.previousLoaded) {
            v.previousLoaded = true;
            v.previous = last(v.mailbox, 1).stream().findFirst().orElse(null);
        }
        AlertRules.Thresholds t = thresholds(v.mailbox);
        long time = v.start == 0 ? v.now : v.start;
        Map<String, Object> rec = CallRecord.of(s, time, v.previous, t.leakMin());
        try {
            store.appendSurfacing(v.mailbox, time, json.writeValueAsString(rec), KEEP);
        } catch (IOException | RuntimeException x) {
            log.warn("could not keep the call record of {}: {}", v.mailbox, x.toString());
        }
        try {
            reader.surfacing(v.mailbox, time, s);
        } catch (RuntimeException x) {
            log.warn("a reader of {}'s surface dialog failed: {}", v.mailbox, x.toString());
        }
        Double lat = s.gps() == null ? null : s.gps().lat();
        Double lon = s.gps() == null ? null : s.gps().lon();
        for (Alerts.Alert a : Alerts.check(s, rec, v.previous, t)) {
            alert(v, a, t, lat, lon);
        }
        v.previous = rec;
    }

    /** At most one ALERT per vehicle and cause per {@code alert.every}; those held back are counted in the next. */
    private void alert(Vehicle v, Alerts.Alert a, AlertRules.Thresholds t, Double lat, Double lon) {
        long now = System.currentTimeMillis();
        Long last = v.lastAlert.get(a.cause());
        if (last != null && now - last < t.every().toMillis()) {
            v.held.merge(a.cause(), 1, Integer::sum);
            return;
        }
        Integer held = v.held.remove(a.cause());
        v.lastAlert.put(a.cause(), now);
        publish(v.mailbox, VehicleEvent.ALERT, a.text() + (held == null ? "" : " (and " + held + " more " + a.cause()
                + " alerts held back since the last)"), lat, lon);
    }

    private void publish(String mailbox, VehicleEvent event, String text, Double lat, Double lon) {
        try {
            events.accept(ConsoleEntry.event(mailbox, event, text, lat, lon));
        } catch (RuntimeException x) {
            log.warn("could not publish {} of {}: {}", event, mailbox, x.toString());
        }
    }

    /** The MailBox's last {@code n} call records, oldest first; unreadable ones are skipped. */
    public List<Map<String, Object>> last(String mailbox, int n) {
        List<Map<String, Object>> out = new ArrayList<>();
        try {
            for (String line : store.lastSurfacings(mailbox, n)) {
                try {
                    out.add(json.readValue(line, MAP));
                } catch (JsonProcessingException x) {
                    log.debug("skipping an unreadable call record of {}: {}", mailbox, x.getMessage());
                }
            }
        } catch (IOException x) {
            throw new UncheckedIOException(x);
        }
        return out;
    }

    /**
     * Every vehicle whose call records the store keeps: its calls' times, so its learned interval
     * and OVERDUE survive a restart (a vehicle already due before now was told by the server then).
     */
    private void seedAll() {
        long now = System.currentTimeMillis();
        try {
            List<String> mailboxes = store.surfacingMailboxes();
            for (String m : mailboxes.subList(0, Math.min(mailboxes.size(), MAX_VEHICLES))) {
                overdue.seed(m, callTimes(m), now);
            }
        } catch (IOException | RuntimeException x) {
            log.warn("could not read which vehicles called before: {}; their call intervals are learned afresh", x.toString());
        }
    }

    /** The start times of the vehicle's last stored calls, oldest first. */
    private List<Long> callTimes(String mailbox) {
        try {
            List<Long> out = new ArrayList<>();
            for (Map<String, Object> r : last(mailbox, Overdue.LEARN_FROM + 1)) {
                Long t = time(r);
                if (t != null) {
                    out.add(t);
                }
            }
            return out;
        } catch (RuntimeException x) {
            log.warn("could not read the calls of {}: {}", mailbox, x.toString());
            return List.of();
        }
    }

    private static Long time(Map<String, Object> r) {
        try {
            return r.get("time_utc") instanceof String t ? java.time.Instant.parse(t).toEpochMilli() : null;
        } catch (DateTimeParseException x) {
            return null;
        }
    }

    /**
     * What the vehicle's call records say comes next ({@link CallOutlook}): the records given
     * (oldest first) with the interval it is expected to call at — its link's, its rule's, or
     * learned from its calls (here, or from the records when it has not called since the start).
     */
    public Map<String, Object> outlook(String mailbox, List<Map<String, Object>> records) {
        Overdue.Expected e = overdue.expected(mailbox);
        if (e == null) {
            List<Long> times = new ArrayList<>();
            records.forEach(r -> {
                Long t = time(r);
                if (t != null) {
                    times.add(t);
                }
            });
            Duration learned = CallOutlook.learned(times);
            int n = Math.min(times.size(), Overdue.LEARN_FROM + 1) - 1;
            e = learned == null ? null : new Overdue.Expected(learned, "learned from its last " + n + " intervals");
        }
        return CallOutlook.of(records, e == null ? null : e.every(), e == null ? null : e.from());
    }

    /** Waits (at most 5 s) until what was accepted so far has been read (tests). */
    public void sync() {
        long target = offered.get();
        long end = System.nanoTime() + 5_000_000_000L;
        while (done.get() < target && System.nanoTime() < end) {
            try {
                Thread.sleep(5);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    @Override
    public void close() {
        closed = true;
        worker.interrupt();
        try {
            worker.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
