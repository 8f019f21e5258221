package org.ripv.services.serial;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Locale;
import java.util.function.Consumer;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.surfacing.CallInterval;

/**
 * A vehicle link's call: whether the vehicle is on a call, dived (the call ended normally) or
 * lost (the link failed), since when, how many calls, and the last position; and the events that
 * say so. SURFACED waits a moment for the surface dialog's GPS line so that it carries the
 * position: at most {@link #SURFACE_WAIT_NANOS} from the vehicle's first words on the call (or
 * {@link #SILENT_WAIT_NANOS} from the connect when it says nothing), or until the call ends or
 * someone sends a command. The wait counts from the first words, not the connect, because over a
 * modem or Iridium the dialog starts seconds after the carrier, and a stalled moment between the
 * connect and the dialog must not cost SURFACED its position.
 *
 * <p>Not thread-safe: {@link VehicleConsole} calls it under its lock.
 */
final class CallState {
    static final long SURFACE_WAIT_NANOS = 5_000_000_000L;
    static final long SILENT_WAIT_NANOS = 30_000_000_000L;
    private static final DateTimeFormatter TIME = DateTimeFormatter.ofPattern("HH:mm:ss 'UTC'", Locale.ROOT)
            .withZone(ZoneOffset.UTC);

    enum State { NEVER, ON_CALL, DIVED, LOST }

    private final String mailbox;
    private final Consumer<ConsoleEntry> out;
    private State state = State.NEVER;
    private long since = System.currentTimeMillis();
    private int calls;
    private GpsFix position;
    private String why = "";
    private String how = "";
    private boolean pending;
    private boolean heard;
    private long pendingSince;

    /** The link's {@code overdue=}, announced in SURFACED for the server's OVERDUE, or null. */
    private final Duration overdue;

    CallState(String mailbox, Consumer<ConsoleEntry> out) {
        this(mailbox, out, null);
    }

    CallState(String mailbox, Consumer<ConsoleEntry> out, Duration overdue) {
        this.mailbox = mailbox;
        this.out = out;
        this.overdue = overdue;
    }

    boolean onCall() {
        return state == State.ON_CALL;
    }

    State state() {
        return state;
    }

    GpsFix position() {
        return position;
    }

    /** A call began ({@code how}: "caller 10.0.0.7:40112", "carrier rose", "surface dialog"). */
    void started(String how, long nowNanos) {
        if (state == State.ON_CALL) {
            return;
        }
        state = State.ON_CALL;
        since = System.currentTimeMillis();
        calls++;
        this.how = how;
        this.why = "";
        pending = true;
        heard = false;
        pendingSince = nowNanos;
    }

    /** The vehicle said something: on a new call, SURFACED's wait for the GPS line starts now. */
    void heard(long nowNanos) {
        if (pending && !heard) {
            heard = true;
            pendingSince = nowNanos;
        }
    }

    /** A GPS line was seen; during the surface dialog it completes SURFACED. */
    void position(GpsFix fix) {
        position = fix;
        if (pending) {
            surfaced();
        }
    }

    /** SURFACED goes out without a position when no GPS line came in time. */
    void tick(long nowNanos) {
        if (pending && nowNanos - pendingSince > (heard ? SURFACE_WAIT_NANOS : SILENT_WAIT_NANOS)) {
            surfaced();
        }
    }

    /** Someone talks to the vehicle: the surface dialog is over. */
    void settle() {
        if (pending) {
            surfaced();
        }
    }

    private void surfaced() {
        pending = false;
        publish(VehicleEvent.SURFACED, "call " + calls + " (" + how + ")"
                + (overdue == null ? "" : " " + CallInterval.announce(overdue)));
    }

    /** The call ended: DIVED (normal) or LINK_LOST. A DIVED with no call on says nothing. */
    void ended(VehicleEvent event, String reason) {
        if (event == VehicleEvent.DIVED && state != State.ON_CALL) {
            return;
        }
        if (pending) {
            surfaced();
        }
        state = event == VehicleEvent.DIVED ? State.DIVED : State.LOST;
        since = System.currentTimeMillis();
        why = reason;
        publish(event, reason);
    }

    private void publish(VehicleEvent event, String detail) {
        GpsFix p = position;
        String where = p == null ? "" : String.format(Locale.ROOT, "; %s %.5f, %.5f",
                event == VehicleEvent.SURFACED ? "at" : "last position", p.lat(), p.lon());
        out.accept(ConsoleEntry.event(mailbox, event, detail + where, p == null ? null : p.lat(),
                p == null ? null : p.lon()));
    }

    /**
     * For ?status: "on call since 14:02:11 UTC (caller 10.0.0.7:40112)". No count of calls: the
     * server's vehicle state beside it counts them (per run of this service, as SURFACED's "call N"
     * does), and one line should not say it twice.
     */
    String describe() {
        String at = TIME.format(Instant.ofEpochMilli(since));
        return switch (state) {
            case NEVER -> "no call yet";
            case ON_CALL -> "on call since " + at + " (" + how + ")";
            case DIVED -> "dived at " + at + " (" + why + ")";
            case LOST -> "lost at " + at + " (" + why + ")";
        };
    }
}
