package org.ripv.naming;

import java.time.Instant;

/**
 * The refusal of a service whose name another running service holds: the server sends it, the
 * service's connector recognises it and stops (a second process of one name must not evict the
 * first, nor the first the second, every heartbeat). The text says who holds the name, from
 * where and since when, and what to do.
 */
public final class NameTaken {
    /** How the refusal's text starts, so the service can tell it from refusals a retry mends. */
    public static final String PREFIX = "the name is taken: ";

    private NameTaken() {
    }

    /**
     * @param name    the service name both want
     * @param address where the holder answers (HOST:PORT)
     * @param since   when the holder registered (epoch ms; 0 unknown)
     * @param started when the holder's process started (epoch ms; 0 unknown)
     */
    public static String refusal(String name, String address, long since, long started) {
        return PREFIX + name + " is registered by another running service at " + address
                + (since > 0 ? ", registered since " + Instant.ofEpochMilli(since) : "")
                + (started > 0 ? " (its process started " + Instant.ofEpochMilli(started) + ")" : "")
                + ", and it answers. Stop that one first, or run this one under another name (--host); a service"
                + " that stops answering is replaced by the next one that registers with its name";
    }

    /** True when a registration's refusal is {@link #refusal}. */
    public static boolean is(String message) {
        return message != null && message.startsWith(PREFIX);
    }
}
