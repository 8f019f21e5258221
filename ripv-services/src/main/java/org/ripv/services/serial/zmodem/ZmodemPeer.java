package org.ripv.services.serial.zmodem;

import java.io.IOException;
import java.util.Objects;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;
import org.ripv.services.serial.ymodem.ByteLink;
import org.ripv.services.serial.ymodem.TransferListener;

/**
 * What both ends of a ZMODEM transfer hold: the frame reader and writer on one link, the
 * listener, the deadlines, and how a transfer is cancelled or refused by the far side's shell.
 *
 * @param <T> the end itself, so the settings chain
 */
abstract class ZmodemPeer<T extends ZmodemPeer<T>> {
    final ZFrameReader in;
    final ZFrameWriter out;
    final TransferListener listener;
    final long timeoutMillis;
    long startTimeoutMillis;
    BooleanSupplier cancel = () -> false;
    Predicate<String> refusal;
    final byte[] buf = new byte[Zmodem.MAX_SUBPACKET];

    ZmodemPeer(ByteLink link, long timeoutMillis, TransferListener listener) {
        this.in = new ZFrameReader(link);
        this.out = new ZFrameWriter(link);
        this.listener = listener == null ? TransferListener.NONE : listener;
        this.timeoutMillis = timeoutMillis;
        this.startTimeoutMillis = 3 * timeoutMillis;
    }

    abstract T self();

    /** Stops (with the abort sequence) when this turns true. */
    public T cancelWhen(BooleanSupplier c) {
        this.cancel = Objects.requireNonNull(c);
        return self();
    }

    /** Gives up waiting for the other end when the text before its first frame passes this test (a shell's refusal). */
    public T refusedWhen(Predicate<String> r) {
        this.refusal = r;
        return self();
    }

    /** How long to wait for the other end's first frame (the vehicle's command has to start it). */
    public T startTimeout(long millis) {
        this.startTimeoutMillis = millis;
        return self();
    }

    void checkCancel() throws IOException {
        if (cancel.getAsBoolean()) {
            abort();
            throw new ZmodemException(ZmodemException.Kind.LINE, "cancelled");
        }
    }

    void abort() throws IOException {
        out.raw(Zmodem.ABORT);
    }
}
