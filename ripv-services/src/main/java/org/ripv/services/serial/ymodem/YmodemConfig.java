package org.ripv.services.serial.ymodem;

import java.time.Duration;

/**
 * Timeouts and retry limits of a transfer. {@link #lrzsz()} follows lrzsz: 10 s for a block or
 * an answer, 10 retries, a minute for the other end to start.
 *
 * @param startTimeout     how long a sender waits for the receiver's first 'C', and a receiver
 *                         for the first block 0
 * @param startInterval    how often a waiting receiver repeats its 'C'
 * @param blockTimeout     how long to wait for a block (receiver) or its answer (sender)
 * @param charTimeout      the longest gap allowed between the bytes of one block
 * @param maxRetries       consecutive errors on one block before the transfer is cancelled
 * @param eotNakFirst      receiver: NAK the first EOT and ACK the repeated one (guards
 *                         against a noise byte that looks like EOT); false ACKs the first
 * @param finalAckTimeout  sender: how long to wait for the ACK of the end-of-batch block
 *                         (a lost final ACK is tolerated)
 */
public record YmodemConfig(Duration startTimeout, Duration startInterval, Duration blockTimeout,
                           Duration charTimeout, int maxRetries, boolean eotNakFirst,
                           Duration finalAckTimeout) {

    public YmodemConfig {
        if (maxRetries < 1) {
            throw new IllegalArgumentException("maxRetries must be at least 1, got " + maxRetries);
        }
    }

    /** lrzsz's limits. */
    public static YmodemConfig lrzsz() {
        return new YmodemConfig(Duration.ofSeconds(60), Duration.ofSeconds(3), Duration.ofSeconds(10),
                Duration.ofSeconds(2), 10, true, Duration.ofSeconds(3));
    }

    public YmodemConfig withEotNakFirst(boolean nakFirst) {
        return new YmodemConfig(startTimeout, startInterval, blockTimeout, charTimeout, maxRetries, nakFirst,
                finalAckTimeout);
    }

    /** Scales every timeout (tests use short ones). */
    public YmodemConfig withTimeouts(Duration start, Duration interval, Duration block, Duration chr) {
        return new YmodemConfig(start, interval, block, chr, maxRetries, eotNakFirst, block);
    }
}
