package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

/** Reads a vehicle's answer to a command: until its prompt, a pause, or a deadline. */
final class ReplyReader {
    /** A reply longer than this is cut (the requester is told); the console saw it all, rate permitting. */
    static final int MAX_REPLY = 4 * 1024 * 1024;

    private final LinkSettings settings;
    private final VehicleText vehicleText;

    ReplyReader(LinkSettings settings, VehicleText vehicleText) {
        this.settings = settings;
        this.vehicleText = vehicleText;
    }

    /**
     * Reads into {@code text} until the prompt ends it, the line is idle, or {@code maxMillis}
     * pass. Returns true when the link closed meanwhile. A prompt before the echo of
     * {@code command} (a fresh connection's banner) only ends the reply if nothing follows it.
     */
    boolean read(Link l, StringBuilder text, long maxMillis, String command) throws IOException {
        return read(l, text, maxMillis, command, null);
    }

    /**
     * As {@link #read(Link, StringBuilder, long, String)}; once {@code cancel} has been asked, the
     * vehicle has {@link #settleMillis} from then to come back to its prompt.
     */
    boolean read(Link l, StringBuilder text, long maxMillis, String command, CommandCancel cancel) throws IOException {
        byte[] buf = new byte[4096];
        long deadline = System.nanoTime() + maxMillis * 1_000_000;
        long idle = settings.idleTimeout().toMillis();
        long wait = idle;
        boolean cut = false;
        while (System.nanoTime() - deadline < 0) {
            int n;
            try {
                long asked = cancel == null ? 0 : cancel.askedAt();
                if (asked != 0 && deadline - (asked + settleMillis() * 1_000_000) > 0) {
                    deadline = asked + settleMillis() * 1_000_000;
                }
                n = l.read(buf, 0, buf.length, Math.max(1, Math.min(wait, (deadline - System.nanoTime()) / 1_000_000)));
            } catch (EOFException e) {
                return true;
            }
            if (n == 0) {
                return false;
            }
            if (text.length() < MAX_REPLY) {
                text.append(new String(buf, 0, Math.min(n, MAX_REPLY - text.length()), StandardCharsets.ISO_8859_1));
            } else if (!cut) {
                cut = true;
                text.append("\n[reply cut at ").append(MAX_REPLY).append(" characters]\n");
            }
            if (vehicleText.endsWithPrompt(text)) {
                if (command == null || VehicleText.echoEnd(text, command) >= 0) {
                    return false;
                }
                wait = Math.min(idle, 200); // a banner's prompt, or a vehicle that does not echo
            } else {
                wait = idle;
            }
        }
        return false;
    }

    /** Whether {@code text} ends with the vehicle's prompt. */
    boolean endsWithPrompt(CharSequence text) {
        return vehicleText.endsWithPrompt(text);
    }

    /** How long a cancelled command's vehicle has to be back at its prompt: twice the idle timeout, at least 3 s. */
    long settleMillis() {
        return Math.max(3000, 2 * settings.idleTimeout().toMillis());
    }

    /** Reads and forgets until the vehicle is back at its prompt or quiet (after a transfer). */
    boolean drain(Link l) throws IOException {
        return read(l, new StringBuilder(), settings.idleTimeout().toMillis() * 2, null);
    }
}
