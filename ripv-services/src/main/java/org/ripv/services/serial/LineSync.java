package org.ripv.services.serial;

import java.io.IOException;
import java.nio.charset.StandardCharsets;

/**
 * A clean line after a transfer — finished, failed or cancelled — before the next command.
 *
 * <p>Why: a YMODEM receiver asks for blocks with 'C's. One sent just as the vehicle's sender
 * finished (a loaded machine answers late, so the receiver asks again) reaches the vehicle's
 * shell, not the sender: the next command then arrives as {@code Cyr} and is refused. So after a
 * transfer the link is drained to the vehicle's prompt, left to go quiet (stray bytes in flight
 * land), and then sent one line ending, which ends whatever sits in the shell's line (at worst
 * one "Bad command" for a lone {@code C}); the fresh prompt after it says the line is clean.
 */
final class LineSync {
    /** Silence that says no more stray bytes are on their way. */
    static final long QUIET_MILLIS = 150;

    private final LinkSettings settings;
    private final ReplyReader replies;

    LineSync(LinkSettings settings, ReplyReader replies) {
        this.settings = settings;
        this.replies = replies;
    }

    /**
     * Drains to the prompt, waits for quiet, ends the shell's line and waits for its prompt.
     *
     * @return true when the vehicle answered the line ending with its prompt
     */
    boolean resync(Link l) throws IOException {
        replies.drain(l);
        quiet(l);
        byte[] end = settings.lineEnding().getBytes(StandardCharsets.ISO_8859_1);
        l.write(end, 0, end.length);
        l.flush();
        StringBuilder text = new StringBuilder();
        replies.read(l, text, 2 * settings.idleTimeout().toMillis(), null);
        return replies.endsWithPrompt(text);
    }

    /** Reads and forgets until the line has been silent {@link #QUIET_MILLIS} (at most twice the idle timeout). */
    private void quiet(Link l) throws IOException {
        byte[] buf = new byte[1024];
        long end = System.nanoTime() + 2 * settings.idleTimeout().toNanos();
        while (System.nanoTime() - end < 0 && l.read(buf, 0, buf.length, QUIET_MILLIS) > 0) {
            // forget it: the vehicle's tail after a transfer, or our own stray bytes echoed
        }
    }
}
