package org.ripv.services.serial;

import java.util.function.Consumer;
import java.util.regex.Pattern;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.surfacing.SurfaceDialogParser;

/**
 * One vehicle MailBox's live console: turns what the link's reader hands it into console entries
 * (lines, cut and made printable, at most the link's rate, with "N lines skipped" in place of the
 * excess), and adds the commands sent, transfers, ALERTs and the call's events. The echo of a
 * command and lone prompts are left out: the COMMAND entry already says it.
 *
 * <p>Thread-safe: the reader, the command thread and the call listener all report here.
 */
final class VehicleConsole {
    /** How a link's calls are recognised. */
    enum Calls {
        /** listen://: a caller connects and hangs up. */
        CALLER,
        /** A serial link with carrier=require: DCD rises and falls. */
        CARRIER,
        /** Anything else: the surface pattern over the output starts a call, silence ends it. */
        DIALOG
    }

    private static final long PARTIAL_NANOS = 300_000_000L;
    private static final long SECOND = 1_000_000_000L;

    private final String mailbox;
    private final Consumer<ConsoleEntry> out;
    private final CallSettings settings;
    private final Pattern prompt;
    private final Calls calls;
    private final LineAssembler lines;
    private final LineRate rate;
    private final CallState call;
    private long lastInput = System.nanoTime();
    private long lastText;
    private boolean spoken;
    private long lastSkipReport = System.nanoTime();
    private long linesSinceReport;
    private String echo;
    private int echoLines;
    private long lastAlert = System.nanoTime() - 2 * SECOND;
    private int alertsHeld;
    /** Follows the surface dialog only to know whether a caller hung up in the middle of it. */
    private final SurfaceDialogParser dialog = new SurfaceDialogParser(s -> { });

    VehicleConsole(String mailbox, CallSettings settings, Pattern prompt, Calls calls, Consumer<ConsoleEntry> out) {
        this.mailbox = mailbox;
        this.out = out;
        this.settings = settings;
        this.prompt = prompt;
        this.calls = calls;
        this.lines = new LineAssembler(settings.lineLength());
        this.rate = new LineRate(settings.linesPerSecond(), System.nanoTime());
        this.call = new CallState(mailbox, out, settings.overdue());
    }

    Calls calls() {
        return calls;
    }

    /** Text from the vehicle. */
    synchronized void text(byte[] bytes, int offset, int length) {
        lastInput = System.nanoTime();
        lastText = lastInput;
        spoken = true;
        call.heard(lastInput);
        lines.feed(bytes, offset, length, this::line);
    }

    /** Bytes that are no text (a transfer): the vehicle is there. */
    synchronized void alive() {
        lastInput = System.nanoTime();
    }

    /** The clock: partial lines after a pause, the skipped count, SURFACED's wait, and quiet. */
    synchronized void tick() {
        long now = System.nanoTime();
        if (lines.hasPartial() && now - lastInput > PARTIAL_NANOS) {
            lines.flush(this::line);
        }
        if (now - lastSkipReport > SECOND) {
            reportSkipped(now);
        }
        call.tick(now);
        if (calls == Calls.DIALOG && call.onCall() && now - lastInput > settings.quiet().toNanos()) {
            call.ended(VehicleEvent.DIVED, "quiet for " + settings.quiet().toSeconds() + " s");
        }
    }

    private void line(String text) {
        long now = System.nanoTime();
        dialog.line(text);
        if (prompt.matcher(text.strip()).matches()) {
            return;
        }
        if (echo != null) {
            if (isEcho(text)) {
                echo = null;
                return;
            }
            if (--echoLines <= 0) {
                echo = null;
            }
        }
        linesSinceReport++;
        if (rate.admit(now)) {
            if (now - lastSkipReport > SECOND) {
                reportSkipped(now);
            }
            out.accept(ConsoleEntry.line(mailbox, text));
        }
        if (calls == Calls.DIALOG && !call.onCall() && settings.surface().matcher(text).find()) {
            call.started("surface dialog: " + text, now);
            call.heard(now);
        }
        GpsFix.parse(text).ifPresent(call::position);
        if (settings.alert().matcher(text).find()) {
            alert(text, now);
        }
    }

    private boolean isEcho(String text) {
        if (!text.endsWith(echo)) {
            return false;
        }
        String before = text.substring(0, text.length() - echo.length()).strip();
        return before.isEmpty() || prompt.matcher(before).matches();
    }

    /** The "N lines skipped" marker, with the rate the vehicle printed at since the last one. */
    private void reportSkipped(long now) {
        long skipped = rate.takeSkipped();
        if (skipped > 0) {
            double seconds = Math.max(1e-3, (now - lastSkipReport) / 1e9);
            long printed = Math.round(linesSinceReport / seconds);
            out.accept(ConsoleEntry.line(mailbox, "[" + skipped + " lines skipped: the vehicle printed " + printed
                    + " lines/s, more than the link's " + rate.perSecond() + "]"));
        }
        if (skipped > 0 || now - lastSkipReport > SECOND) {
            lastSkipReport = now;
            linesSinceReport = 0;
        }
    }

    /** At most one ALERT a second; the lines held back are counted in the next. */
    private void alert(String text, long now) {
        if (now - lastAlert < SECOND) {
            alertsHeld++;
            return;
        }
        String more = alertsHeld > 0 ? " (and " + alertsHeld + " more alert lines before it)" : "";
        alertsHeld = 0;
        lastAlert = now;
        GpsFix p = call.position();
        out.accept(ConsoleEntry.event(mailbox, VehicleEvent.ALERT, text + more, p == null ? null : p.lat(),
                p == null ? null : p.lon()));
    }

    /** A command about to be written, with the user who sent it. */
    synchronized void command(String user, String command) {
        call.settle();
        out.accept(ConsoleEntry.command(mailbox, user, command));
        echo = command;
        echoLines = 3;
    }

    /** A transfer's start, progress or end. */
    synchronized void transfer(String user, String text) {
        out.accept(ConsoleEntry.transfer(mailbox, user, text));
    }

    /** TRANSFER_DONE or TRANSFER_FAILED. */
    synchronized void event(VehicleEvent event, String detail) {
        out.accept(ConsoleEntry.event(mailbox, event, detail, null, null));
    }

    /** A call began: a caller connected or carrier rose. */
    synchronized void callStarted(String how) {
        dialog.end(); // whatever came before this call is not its dialog
        lastInput = System.nanoTime();
        call.started(how, lastInput);
        if (spoken && lastInput - lastText < CallState.SURFACE_WAIT_NANOS) {
            call.heard(lastText); // the carrier is polled: the dialog may have come in just before it rose
        }
    }

    /**
     * Why a call whose caller hung up now was dropped rather than ended, or null when it ended
     * normally: a command or transfer was running, or the surface dialog had begun and not ended
     * (no countdown, no prompt yet).
     */
    synchronized String droppedMidway(boolean commandRunning) {
        if (lines.hasPartial()) {
            lines.flush(this::line);
        }
        if (commandRunning) {
            return "the caller hung up while a command or transfer ran: the call dropped";
        }
        return dialog.inDialog() ? "the caller hung up in the middle of its surface dialog: the call dropped" : null;
    }

    /** The call ended normally (DIVED) or the link failed (LINK_LOST). */
    synchronized void callEnded(VehicleEvent event, String why) {
        if (lines.hasPartial()) {
            lines.flush(this::line);
        }
        reportSkipped(System.nanoTime());
        call.ended(event, why);
    }

    /** True when a call is on and the vehicle has said nothing for the link's quiet time. */
    synchronized boolean quietTooLong() {
        return call.onCall() && System.nanoTime() - lastInput > settings.quiet().toNanos();
    }

    /** The link's quiet time in seconds, for messages. */
    long quietSeconds() {
        return settings.quiet().toSeconds();
    }

    synchronized boolean onCall() {
        return call.onCall();
    }

    synchronized CallState.State state() {
        return call.state();
    }

    /** For ?status. */
    synchronized String describe() {
        return call.describe();
    }
}
