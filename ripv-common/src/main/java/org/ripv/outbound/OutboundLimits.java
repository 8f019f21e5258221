package org.ripv.outbound;

/** Limits both ends of an outbound connection agree on. */
public final class OutboundLimits {
    /** The largest call or answer (a whole file travels in one reply, as over RMI). */
    public static final int MAX_FRAME = 256 * 1024 * 1024;
    /** How long the handshake may take. */
    public static final int HANDSHAKE_MILLIS = 10_000;

    private OutboundLimits() {}
}
