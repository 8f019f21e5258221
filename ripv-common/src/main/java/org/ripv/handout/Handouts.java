package org.ripv.handout;

import java.time.Duration;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.function.LongSupplier;

/**
 * What a service that fetches files keeps of them for a while, so that the service that ingests
 * them can read them here instead of through the server: the files of its last replies, in memory,
 * at most {@code maxBytes} of them (the oldest let go first) and each for {@code holdFor}.
 *
 * <p>The rules a reader is held to, in {@link #read}: the ticket must name this service as its
 * holder and carry the server's MAC for this service's session (so a forged ticket, or one from
 * before a re-registration, is refused); it must not have expired; it is read once, from offset 0
 * to its end, in order, in chunks of at most {@link #MAX_CHUNK} bytes — a second read from 0 or
 * a read at any other offset than the next is refused as a replay; and the file must still be
 * held here, with the SHA-256 the server signed.
 */
public final class Handouts {
    /** The largest chunk one {@code handout} call returns. */
    public static final int MAX_CHUNK = 1 << 20;
    /** Tickets being read or read already, remembered until they expire (replays refused). */
    static final int MAX_READINGS = 4096;

    private final long maxBytes;
    private final long holdMillis;
    private final LongSupplier clock;
    /** By SHA-256, oldest first. */
    private final LinkedHashMap<String, Held> held = new LinkedHashMap<>();
    private final Map<String, Reading> readings = new HashMap<>();
    private long heldBytes;

    private record Held(byte[] data, long until) {}

    private static final class Reading {
        final long expires;
        long next;
        boolean done;

        Reading(long expires) {
            this.expires = expires;
        }
    }

    public Handouts(long maxBytes, Duration holdFor) {
        this(maxBytes, holdFor, System::currentTimeMillis);
    }

    Handouts(long maxBytes, Duration holdFor, LongSupplier clock) {
        this.maxBytes = maxBytes;
        this.holdMillis = holdFor.toMillis();
        this.clock = clock;
    }

    /**
     * The holder's default: 64 MiB, or a quarter of the heap when that is less, or what the system
     * property {@value #MAX_BYTES_PROPERTY} says (0: hold nothing, every file goes through the
     * server); each file for 15 minutes.
     */
    public static Handouts defaults() {
        long max = Long.getLong(MAX_BYTES_PROPERTY, Math.min(64L << 20, Runtime.getRuntime().maxMemory() / 4));
        return new Handouts(Math.max(0, max), Duration.ofMinutes(15));
    }

    /** The system property that bounds what a service holds for handouts, in bytes. */
    public static final String MAX_BYTES_PROPERTY = "ripv.handout.maxBytes";

    /** Keeps a file this service just sent; a file larger than the whole store is not kept (the server relays it). */
    public synchronized void hold(byte[] data) {
        long now = clock.getAsLong();
        prune(now);
        if (data.length > maxBytes) {
            return;
        }
        String sha = HandoutTicket.sha256(data);
        Held old = held.remove(sha);
        if (old != null) {
            heldBytes -= old.data().length;
        }
        for (Iterator<Held> it = held.values().iterator(); heldBytes + data.length > maxBytes && it.hasNext(); ) {
            heldBytes -= it.next().data().length;
            it.remove();
        }
        held.put(sha, new Held(data, now + holdMillis));
        heldBytes += data.length;
    }

    /** How many bytes are held now. */
    public synchronized long heldBytes() {
        prune(clock.getAsLong());
        return heldBytes;
    }

    /**
     * The next chunk of the file a ticket names.
     *
     * @param self         this service's full name: the holder the ticket must name
     * @param sessionToken this service's session token now (null when not registered)
     * @throws HandoutRefused when a rule above is broken; nothing is returned then
     */
    public synchronized byte[] read(String ticketText, long offset, int max, String self, String sessionToken)
            throws HandoutRefused {
        long now = clock.getAsLong();
        prune(now);
        HandoutTicket t = HandoutTicket.parse(ticketText);
        if (!t.source().equals(self)) {
            throw new HandoutRefused("the handout ticket names " + t.source() + " as the holder, not " + self);
        }
        t.verify(sessionToken, now);
        if (max <= 0 || max > MAX_CHUNK) {
            throw new HandoutRefused("a handout is read in chunks of 1 to " + MAX_CHUNK + " bytes, not " + max);
        }
        Reading r = readings.get(t.nonce());
        if (r == null && offset == 0) {
            if (readings.size() >= MAX_READINGS) {
                throw new HandoutRefused("too many handouts under way here; try again later");
            }
            r = new Reading(t.expiresAt());
            readings.put(t.nonce(), r);
        } else if (r == null || r.done || offset != r.next) {
            throw new HandoutRefused("the handout ticket was used already (read once, in order, from offset 0)");
        }
        Held h = held.get(t.sha256());
        if (h == null || h.data().length != t.size()) {
            r.done = true;
            throw new HandoutRefused(self + " no longer holds the file (let go after " + holdMillis / 60_000
                    + " min or to make room)");
        }
        int n = (int) Math.min(max, t.size() - offset);
        byte[] chunk = new byte[n];
        System.arraycopy(h.data(), (int) offset, chunk, 0, n);
        r.next += n;
        r.done = r.next == t.size();
        return chunk;
    }

    private void prune(long now) {
        for (Iterator<Held> it = held.values().iterator(); it.hasNext(); ) {
            Held h = it.next();
            if (h.until() < now) {
                heldBytes -= h.data().length;
                it.remove();
            }
        }
        readings.values().removeIf(r -> r.expires < now);
    }
}
