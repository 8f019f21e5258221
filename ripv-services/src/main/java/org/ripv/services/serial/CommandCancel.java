package org.ripv.services.serial;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Cancelling the plain vehicle command that runs now ({@code ?cancel}): the link's interrupt
 * ({@link LinkSettings#interrupt}) is written once the command line has gone out — at once when
 * the cancel comes while the vehicle runs it, or right after the line when it comes earlier —
 * and the command's reader then waits, for a bounded time, for the vehicle's prompt.
 *
 * <p>Writing the command line and the interrupt share this object's lock, so the interrupt never
 * lands inside the line. {@link #ask} comes from another thread (RMI); the rest from the command's.
 */
final class CommandCancel {
    private static final Logger log = LoggerFactory.getLogger(CommandCancel.class);

    private final String keys;
    private Link link;
    private boolean active;
    private volatile long askedAt;

    /** @param keys the link's interrupt; empty when it has none (then nothing can be cancelled) */
    CommandCancel(String keys) {
        this.keys = keys;
    }

    /** A plain command starts; cancels of earlier ones are forgotten. */
    synchronized void begin() {
        active = true;
        link = null;
        askedAt = 0;
    }

    /** The command is over: later cancels find nothing to stop. */
    synchronized void end() {
        active = false;
        link = null;
    }

    /** Writes the command line; from now on a cancel interrupts it (and one that came first does so now). */
    synchronized void send(Link l, byte[] line) throws IOException {
        l.write(line, 0, line.length);
        l.flush();
        link = l;
        if (askedAt != 0) {
            interrupt(l);
        }
    }

    /** From ?cancel: true when a plain command runs and the link has an interrupt. */
    synchronized boolean ask() {
        if (!active || keys.isEmpty()) {
            return false;
        }
        if (askedAt == 0) {
            askedAt = System.nanoTime();
            if (link != null) {
                try {
                    interrupt(link);
                } catch (IOException e) {
                    log.info("could not write the interrupt to {}: {}", link.describe(), e.toString()); // the command's read fails too
                }
            }
        }
        return true;
    }

    /** Whether a cancel was asked for during this command. */
    boolean asked() {
        return askedAt != 0;
    }

    /** When the cancel was asked for ({@link System#nanoTime}), or 0. */
    long askedAt() {
        return askedAt;
    }

    /** The interrupt as an operator reads it ({@code ^C}). */
    String describe() {
        return Interrupt.describe(keys);
    }

    private void interrupt(Link l) throws IOException {
        byte[] b = keys.getBytes(StandardCharsets.ISO_8859_1);
        l.write(b, 0, b.length);
        l.flush();
    }
}
