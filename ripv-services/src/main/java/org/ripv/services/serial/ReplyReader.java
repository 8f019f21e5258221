package org.ripv.services.serial;

import java.io.EOFException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

/** Reads a vehicle's answer to a command: until its prompt, a pause, or a deadline. */
final class ReplyReader {
    /**
     * A reply longer than this is cut in the middle, "[... N bytes cut]" (the console saw it all,
     * rate permitting): a reply that never ends costs a command this much memory and no more.
     */
    static final int MAX_REPLY = 1024 * 1024;

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
        Tail tail = new Tail();
        try {
            return collect(l, text, tail, maxMillis, command, cancel);
        } finally {
            tail.appendTo(text);
        }
    }

    private boolean collect(Link l, StringBuilder text, Tail tail, long maxMillis, String command, CommandCancel cancel)
            throws IOException {
        byte[] buf = new byte[4096];
        long deadline = System.nanoTime() + maxMillis * 1_000_000;
        long idle = settings.idleTimeout().toMillis();
        long wait = idle;
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
            int kept = Math.max(0, Math.min(n, MAX_REPLY - text.length()));
            text.append(new String(buf, 0, kept, StandardCharsets.ISO_8859_1));
            tail.add(buf, kept, n - kept);
            // past the cap only the tail is looked at: the prompt still ends an endless reply's command
            if (tail.past > 0 ? vehicleText.endsWithPrompt(tail.text) : vehicleText.endsWithPrompt(text)) {
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

    /**
     * What came after {@link #MAX_REPLY}: only its last {@link #KEEP} characters are kept (where
     * the prompt is), the rest is counted, and the reply says "[... N bytes cut]" in its place.
     */
    private static final class Tail {
        static final int KEEP = 512;
        final StringBuilder text = new StringBuilder();
        long past;

        void add(byte[] bytes, int offset, int length) {
            if (length <= 0) {
                return;
            }
            past += length;
            int from = Math.max(offset, offset + length - KEEP);
            text.append(new String(bytes, from, offset + length - from, StandardCharsets.ISO_8859_1));
            if (text.length() > KEEP) {
                text.delete(0, text.length() - KEEP);
            }
        }

        long cut() {
            return past - text.length();
        }

        void appendTo(StringBuilder reply) {
            if (cut() > 0) {
                reply.append("\n[... ").append(cut()).append(" bytes cut]\n");
            }
            reply.append(text);
        }
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
