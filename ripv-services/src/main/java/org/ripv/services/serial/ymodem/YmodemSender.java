package org.ripv.services.serial.ymodem;

import static org.ripv.services.serial.ymodem.YmodemIo.ACK;
import static org.ripv.services.serial.ymodem.YmodemIo.CAN;
import static org.ripv.services.serial.ymodem.YmodemIo.CRC_REQUEST;
import static org.ripv.services.serial.ymodem.YmodemIo.EOT;
import static org.ripv.services.serial.ymodem.YmodemIo.NAK;
import static org.ripv.services.serial.ymodem.YmodemIo.SOH;
import static org.ripv.services.serial.ymodem.YmodemIo.STX;
import static org.ripv.services.serial.ymodem.YmodemIo.SUB;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;
import java.util.List;
import java.util.function.BooleanSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Sends a YMODEM batch as lrzsz's {@code sb --ymodem} does: waits for the receiver's 'C',
 * sends block 0 (name NUL length mtime mode), waits for ACK and a new 'C', sends the data in
 * 1024-byte blocks (128-byte blocks for a short tail, where they cost less), each padded with
 * 0x1A and resent on NAK, on 'C' (a receiver that missed a block asks again with 'C') or on
 * timeout; then EOT, accepting either an ACK or a NAK-then-ACK; finally the all-zero block 0,
 * whose ACK may be lost without harm. CAN CAN from the receiver aborts.
 *
 * <p>Not thread-safe; one sender per transfer.
 */
public final class YmodemSender {
    private static final Logger log = LoggerFactory.getLogger(YmodemSender.class);

    private final YmodemIo io;
    private final YmodemConfig config;
    private final TransferListener listener;
    private final byte[] frame = new byte[3 + 1024 + 2];

    public YmodemSender(ByteLink link, YmodemConfig config, TransferListener listener) {
        this.io = new YmodemIo(link);
        this.config = config;
        this.listener = listener == null ? TransferListener.NONE : listener;
    }

    private BooleanSupplier cancelled = () -> false;

    /**
     * Lets the transfer be cancelled from another thread: checked before every block, it aborts
     * with CAN CAN as any other abort does.
     */
    public YmodemSender cancelWhen(BooleanSupplier cancel) {
        this.cancelled = cancel;
        return this;
    }

    /** Sends the files as one batch. */
    public void sendBatch(List<SendFile> files) throws IOException {
        sendBatch(files, false);
    }

    /**
     * Sends the files as one batch; {@code requestSeen} says the caller has already read the
     * receiver's first 'C' (it watched the line to tell a receiver from a shell's error text).
     */
    public void sendBatch(List<SendFile> files, boolean requestSeen) throws IOException {
        if (!requestSeen) {
            awaitRequest(config.startTimeout().toMillis(), "the receiver to start");
        }
        for (SendFile file : files) {
            if (!sendFile(file)) {
                awaitRequest(config.blockTimeout().toMillis() * config.maxRetries(), "the receiver to ask for the next file",
                        true);
            }
        }
        endBatch();
    }

    /** Sends one file; true when the receiver's 'C' for the next file has been read already. */
    private boolean sendFile(SendFile file) throws IOException {
        FileHeader header = new FileHeader(file.name(), file.length(), file.mtimeSeconds(), file.mode());
        byte[] info = (file.name() + '\0' + file.length() + ' ' + Long.toOctalString(file.mtimeSeconds()) + ' '
                + Integer.toOctalString(file.mode())).getBytes(StandardCharsets.UTF_8);
        if (info.length > 1024) {
            throw new YmodemException("file name '" + file.name() + "' does not fit in block 0");
        }
        byte[] block0 = new byte[info.length < 128 ? 128 : 1024];
        System.arraycopy(info, 0, block0, 0, info.length);
        sendBlock(0, block0, block0.length, "block 0 of '" + file.name() + "'");
        // after ACKing block 0 the receiver asks for the data with 'C'
        awaitRequest(config.blockTimeout().toMillis() * config.maxRetries(), "the receiver to ask for '" + file.name() + "'");
        listener.started(header);

        byte[] data = new byte[1024];
        long sent = 0;
        int seq = 1;
        try (InputStream in = file.source().open()) {
            while (sent < file.length()) {
                if (cancelled.getAsBoolean()) {
                    throw abort("cancelled sending '" + file.name() + "' at byte " + sent);
                }
                long remaining = file.length() - sent;
                // 1024-byte blocks unless 128-byte ones carry the tail in fewer bytes on the line
                int size = remaining > 7 * 128 ? 1024 : 128;
                int n = in.readNBytes(data, 0, (int) Math.min(size, remaining));
                if (n <= 0) {
                    throw abort("'" + file.name() + "' ended at byte " + sent + " of " + file.length() + " while sending");
                }
                Arrays.fill(data, n, size, (byte) SUB);
                sendBlock(seq & 0xFF, data, size, "block " + seq + " of '" + file.name() + "'");
                seq++;
                sent += n;
                listener.progress(header, sent);
            }
        }
        boolean asked = sendEot(file.name());
        listener.finished(header);
        return asked;
    }

    private void sendBlock(int seq, byte[] data, int size, String what) throws IOException {
        frame[0] = (byte) (size == 128 ? SOH : STX);
        frame[1] = (byte) seq;
        frame[2] = (byte) ~seq;
        System.arraycopy(data, 0, frame, 3, size);
        int crc = CRC16CCITT.compute(data, 0, size);
        frame[3 + size] = (byte) (crc >>> 8);
        frame[4 + size] = (byte) crc;
        byte[] out = Arrays.copyOf(frame, size + 5);
        for (int attempt = 0; attempt <= config.maxRetries(); attempt++) {
            // an answer that came in with the previous ACK (a duplicate's ACK) is stale
            io.discardBuffered();
            io.write(out);
            int answer = awaitAnswer(config.blockTimeout().toMillis());
            if (answer == ACK) {
                return;
            }
            // NAK, 'C' (after block 1 'C' means "again"), or no answer: send the block again
            log.debug("{}: {} , resending", what, answer < 0 ? "no answer" : "got 0x" + Integer.toHexString(answer));
        }
        throw abort("no ACK for " + what + " after " + config.maxRetries() + " retries");
    }

    /**
     * Ends a file with EOT. Both receiver styles work: ACK at once, or NAK then ACK. Returns true
     * when a 'C' came instead of the ACK (the ACK was lost and the receiver asks for more).
     */
    private boolean sendEot(String name) throws IOException {
        io.discardBuffered();
        io.write(EOT);
        int errors = 0;
        while (true) {
            int answer = awaitAnswer(config.blockTimeout().toMillis());
            if (answer == ACK) {
                return false;
            }
            if (answer == CRC_REQUEST) {
                io.purge(1);
                return true;
            }
            // NAK (a receiver confirming EOT) or silence: send it again
            if (++errors > config.maxRetries()) {
                throw abort("no ACK for the end of '" + name + "'");
            }
            io.write(EOT);
        }
    }

    private void endBatch() throws IOException {
        byte[] empty = new byte[128];
        frame[0] = SOH;
        frame[1] = 0;
        frame[2] = (byte) 0xFF;
        System.arraycopy(empty, 0, frame, 3, 128);
        frame[131] = 0;
        frame[132] = 0;
        byte[] out = Arrays.copyOf(frame, 133);
        for (int attempt = 0; attempt < 3; attempt++) {
            io.write(out);
            int answer = awaitAnswer(config.finalAckTimeout().toMillis());
            if (answer == ACK) {
                return;
            }
            if (answer < 0) {
                // lrzsz does the same: the batch is complete, only its last ACK went missing
                log.debug("no ACK for the end-of-batch block; the batch is complete");
                return;
            }
        }
        log.debug("end-of-batch block not acknowledged; the batch is complete");
    }

    /** Waits for ACK, NAK or 'C'; -1 on timeout. CAN CAN aborts. Other bytes are noise. */
    private int awaitAnswer(long timeoutMillis) throws IOException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000;
        while (true) {
            long left = (deadline - System.nanoTime()) / 1_000_000;
            if (left <= 0) {
                return -1;
            }
            int c = io.read(left);
            switch (c) {
                case -1:
                    return -1;
                case ACK:
                case NAK:
                case CRC_REQUEST:
                    return c;
                case CAN:
                    if (io.read(config.charTimeout().toMillis()) == CAN) {
                        throw new YmodemException("receiver cancelled the transfer (CAN CAN)", true);
                    }
                    continue;
                default:
                    continue;
            }
        }
    }

    /** Waits for the receiver's 'C'; ACKs and NAKs that arrive meanwhile are stale. */
    private void awaitRequest(long timeoutMillis, String what) throws IOException {
        awaitRequest(timeoutMillis, what, false);
    }

    private void awaitRequest(long timeoutMillis, String what, boolean afterEot) throws IOException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000;
        while (true) {
            long left = (deadline - System.nanoTime()) / 1_000_000;
            int c = left <= 0 ? -1 : awaitAnswer(left);
            if (c == NAK && afterEot) {
                // a receiver that confirms EOT took an earlier ACK for ours: confirm it
                io.write(EOT);
                continue;
            }
            if (c == CRC_REQUEST) {
                // a receiver that waited repeats its 'C'; stale repeats would read as answers later
                io.purge(1);
                return;
            }
            if (c < 0) {
                throw abort("timed out waiting for " + what);
            }
        }
    }

    private YmodemException abort(String why) {
        io.cancel();
        log.warn("YMODEM send cancelled: {}", why);
        return new YmodemException(why);
    }
}
