package org.ripv.services.serial;

import java.util.function.Consumer;

/**
 * Cuts a vehicle's byte stream into console lines. CR, LF and CR LF end a line; a backspace
 * takes back the character before it (a shell's echo of an edited line); NULs are dropped; tabs
 * become spaces; every other byte outside printable ASCII becomes U+FFFD, so binary junk never
 * reaches a watcher as binary. A line longer than the limit is published cut, with a note, and
 * the rest of it is only counted: a megabyte without a line end costs no more memory than one line.
 *
 * <p>Not thread-safe: one reader feeds it.
 */
final class LineAssembler {
    static final char REPLACEMENT = '\uFFFD';

    private final int max;
    private final StringBuilder line;
    private long dropped;
    private boolean lastWasCr;

    LineAssembler(int maxLength) {
        this.max = maxLength;
        this.line = new StringBuilder(Math.min(maxLength, 256));
    }

    /** Feeds bytes; each completed line goes to {@code out}, blank ones are skipped. */
    void feed(byte[] bytes, int offset, int length, Consumer<String> out) {
        for (int i = offset; i < offset + length; i++) {
            int c = bytes[i] & 0xFF;
            if (c == '\n' && lastWasCr) {
                lastWasCr = false;
                continue;
            }
            lastWasCr = c == '\r';
            if (c == '\r' || c == '\n') {
                end(out);
            } else if (c == 8) {
                if (dropped == 0 && !line.isEmpty()) {
                    line.setLength(line.length() - 1);
                }
            } else if (c != 0) {
                append(c >= 0x20 && c < 0x7F ? (char) c : c == '\t' ? ' ' : REPLACEMENT, out);
            }
        }
    }

    private void append(char ch, Consumer<String> out) {
        if (dropped > 0) {
            dropped++;
        } else if (line.length() < max) {
            line.append(ch);
        } else {
            out.accept(line + " [line cut at " + max + " characters]");
            line.setLength(0);
            dropped = 1;
        }
    }

    /** Publishes a partial line (a prompt, a question waiting for an answer). */
    void flush(Consumer<String> out) {
        end(out);
    }

    boolean hasPartial() {
        return !line.isEmpty() || dropped > 0;
    }

    private void end(Consumer<String> out) {
        if (dropped > 0) {
            out.accept("[" + dropped + " more characters of that line dropped]");
            dropped = 0;
        } else if (!line.toString().isBlank()) {
            out.accept(line.toString());
        }
        line.setLength(0);
    }
}
