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
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Receives a YMODEM batch (CRC-16, 128- and 1024-byte blocks mixed freely) as lrzsz's
 * {@code rb --ymodem} does: asks with 'C', reads block 0 (name NUL length [mtime mode]),
 * ACKs and asks again, takes the data blocks, truncates the last one to the declared length,
 * and ends at the all-zero block 0. Duplicated blocks are ACKed and dropped, damaged ones
 * NAKed, CAN CAN from the sender aborts, and too many errors cancel the transfer with CANs.
 * A file that does not arrive whole is discarded from the {@link FileSink}.
 *
 * <p>Not thread-safe; one receiver per transfer.
 */
public final class YmodemReceiver {
    private static final Logger log = LoggerFactory.getLogger(YmodemReceiver.class);

    private final YmodemIo io;
    private final YmodemConfig config;
    private final TransferListener listener;
    private final byte[] packet = new byte[1024 + 4];
    private final StringBuilder noise = new StringBuilder();
    private Predicate<CharSequence> gaveUp = text -> false;
    private boolean waitingForFirst;

    public YmodemReceiver(ByteLink link, YmodemConfig config, TransferListener listener) {
        this.io = new YmodemIo(link);
        this.config = config;
        this.listener = listener == null ? TransferListener.NONE : listener;
    }

    /**
     * Lets the receiver stop waiting early when what the other end prints instead of starting
     * shows it will not send (a shell back at its prompt after "File not found").
     */
    public YmodemReceiver stopWaitingWhen(Predicate<CharSequence> shellIsBack) {
        this.gaveUp = shellIsBack;
        return this;
    }

    private BooleanSupplier cancelled = () -> false;

    /**
     * Lets the transfer be cancelled from another thread: checked where a block would be
     * answered, it aborts with CAN CAN as any other abort does.
     */
    public YmodemReceiver cancelWhen(BooleanSupplier cancel) {
        this.cancelled = cancel;
        return this;
    }

    /** What a packet read produced. */
    private enum Kind { DATA, TIMEOUT, BAD, EOT, CANCEL }

    private int packetSeq;
    private int packetSize;

    /**
     * Receives every file of one batch into {@code sink}.
     *
     * @return the headers of the files received whole, in order
     * @throws YmodemException when the transfer fails or is cancelled; files completed before
     *                         the failure stay in the sink, the broken one is discarded
     */
    public List<FileHeader> receiveBatch(FileSink sink) throws IOException {
        List<FileHeader> done = new ArrayList<>();
        boolean first = true;
        while (true) {
            FileHeader header = receiveHeader(first);
            first = false;
            if (header == null) {
                return done;
            }
            receiveFile(header, sink);
            done.add(header);
        }
    }

    /** Asks for and reads block 0; null at the end of the batch. */
    private FileHeader receiveHeader(boolean first) throws IOException {
        long deadline = System.nanoTime() + (first ? config.startTimeout() : config.blockTimeout()).toNanos()
                * (first ? 1 : config.maxRetries());
        int errors = 0;
        io.write(CRC_REQUEST);
        waitingForFirst = first;
        while (true) {
            Kind kind = readPacket(config.startInterval().toMillis());
            if (waitingForFirst && gaveUp.test(noise)) {
                String said = noise.toString().replaceAll("[\\p{Cntrl}&&[^\\n]]", "").strip();
                throw new YmodemRefusedException("the other end did not start sending; it said: " + said);
            }
            switch (kind) {
                case CANCEL -> throw new YmodemException("sender cancelled the transfer (CAN CAN)", true);
                case EOT -> io.write(ACK); // our ACK of the previous file's EOT was lost: ACK again
                case TIMEOUT, BAD -> {
                    if (kind == Kind.BAD && ++errors > config.maxRetries()) {
                        throw abort("too many damaged blocks while waiting for a file header");
                    }
                    if (System.nanoTime() - deadline > 0) {
                        throw abort("no YMODEM sender answered within " + (first ? config.startTimeout()
                                : config.blockTimeout().multipliedBy(config.maxRetries())).toSeconds() + " s");
                    }
                    if (kind == Kind.BAD) {
                        io.purge(100);
                    }
                    io.write(CRC_REQUEST);
                }
                case DATA -> {
                    if (packetSeq != 0) {
                        // a stray data block (its sender missed our ACK); not a header, ask again
                        io.write(ACK);
                        continue;
                    }
                    waitingForFirst = false;
                    io.write(ACK);
                    FileHeader header = parseHeader();
                    if (header == null) {
                        log.debug("end of YMODEM batch");
                        return null;
                    }
                    return header;
                }
                default -> throw new IllegalStateException(kind.toString());
            }
        }
    }

    private FileHeader parseHeader() throws YmodemException {
        int nul = 0;
        while (nul < packetSize && packet[2 + nul] != 0) {
            nul++;
        }
        if (nul == 0) {
            return null;
        }
        String sent = new String(packet, 2, nul, StandardCharsets.UTF_8);
        String name;
        try {
            name = FileNames.requirePlain(FileNames.baseName(sent));
        } catch (IllegalArgumentException e) {
            throw abort("refused file name from sender: " + e.getMessage());
        }
        // The fields after the name run to the next NUL; lrzsz fills the rest (even the last two
        // bytes of the block) with other data, so nothing past that NUL is read.
        int start = 2 + nul + 1;
        int end = start;
        while (end < 2 + packetSize && packet[end] != 0) {
            end++;
        }
        String[] fields = new String(packet, start, end - start, StandardCharsets.US_ASCII).trim().split("\\s+");
        long length = parse(fields, 0, 10);
        long mtime = parse(fields, 1, 8);
        long mode = parse(fields, 2, 8);
        return new FileHeader(name, length, Math.max(0, mtime), (int) Math.max(0, mode));
    }

    private static long parse(String[] fields, int index, int radix) {
        if (index >= fields.length || fields[index].isEmpty()) {
            return -1;
        }
        try {
            return Long.parseLong(fields[index], radix);
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    private void receiveFile(FileHeader header, FileSink sink) throws IOException {
        OutputStream out;
        try {
            out = sink.begin(header);
        } catch (IOException | RuntimeException e) {
            io.cancel();
            throw new YmodemException("cannot store '" + header.name() + "': " + e.getMessage());
        }
        boolean ok = false;
        try {
            listener.started(header);
            receiveData(header, out);
            out.close();
            sink.complete(header);
            ok = true;
            listener.finished(header);
        } finally {
            if (!ok) {
                try {
                    out.close();
                } catch (IOException ignored) {
                    // discarding it anyway
                }
                sink.discard(header);
            }
        }
    }

    private void receiveData(FileHeader header, OutputStream out) throws IOException {
        io.write(CRC_REQUEST);
        int expected = 1;
        int errors = 0;
        long received = 0;
        boolean eotSeen = false;
        boolean anyData = false;
        // With no declared length the last block's 0x1A padding can only be cut at EOT, so the
        // newest block is held back until the next one (or EOT) arrives.
        byte[] held = null;
        while (true) {
            Kind kind = readPacket(config.blockTimeout().toMillis());
            switch (kind) {
                case CANCEL -> throw new YmodemException("sender cancelled '" + header.name() + "' at byte "
                        + received + " (CAN CAN)", true);
                case TIMEOUT, BAD -> {
                    if (cancelled.getAsBoolean()) {
                        throw abort("cancelled receiving '" + header.name() + "' at byte " + received);
                    }
                    if (++errors > config.maxRetries()) {
                        throw abort((kind == Kind.TIMEOUT ? "timed out" : "too many damaged blocks")
                                + " receiving '" + header.name() + "' at byte " + received);
                    }
                    if (kind == Kind.BAD) {
                        io.purge(Math.min(200, config.charTimeout().toMillis()));
                    }
                    // before the first data block the sender may have missed our 'C'
                    io.write(anyData ? NAK : CRC_REQUEST);
                }
                case EOT -> {
                    if (config.eotNakFirst() && !eotSeen) {
                        eotSeen = true;
                        io.write(NAK);
                        continue;
                    }
                    if (held != null) {
                        int n = held.length;
                        while (n > 0 && held[n - 1] == SUB) {
                            n--;
                        }
                        out.write(held, 0, n);
                        received += n;
                    }
                    if (header.length() >= 0 && received != header.length()) {
                        io.write(ACK);
                        throw new YmodemException("sender ended '" + header.name() + "' after " + received
                                + " of " + header.length() + " bytes");
                    }
                    io.write(ACK);
                    return;
                }
                case DATA -> {
                    if (packetSeq == (expected & 0xFF)) {
                        eotSeen = false;
                        errors = 0;
                        anyData = true;
                        expected++;
                        if (header.length() >= 0) {
                            int n = (int) Math.min(packetSize, header.length() - received);
                            if (n > 0) {
                                out.write(packet, 2, n);
                                received += n;
                            }
                        } else {
                            if (held != null) {
                                out.write(held);
                                received += held.length;
                            }
                            held = Arrays.copyOfRange(packet, 2, 2 + packetSize);
                        }
                        if (cancelled.getAsBoolean()) {
                            // CAN CAN in place of the ACK: the sender is waiting for an answer, so it hears
                            // it (a CAN sent after an ACK may be discarded with the stale input before
                            // the next block)
                            throw abort("cancelled receiving '" + header.name() + "' at byte " + received);
                        }
                        io.write(ACK);
                        listener.progress(header, received);
                    } else if (packetSeq == ((expected - 1) & 0xFF)) {
                        io.write(ACK); // a repeat of the block we have: our ACK was lost
                        if (!anyData) {
                            io.write(CRC_REQUEST); // it was block 0: the sender waits for 'C' again
                        }
                    } else {
                        throw abort("block " + packetSeq + " out of sequence (expected " + (expected & 0xFF)
                                + ") in '" + header.name() + "'");
                    }
                }
                default -> throw new IllegalStateException(kind.toString());
            }
        }
    }

    /**
     * Reads one packet. Noise before a packet start is skipped until {@code timeoutMillis} has
     * passed. On DATA, {@link #packetSeq} and {@link #packetSize} describe {@link #packet}
     * (sequence, complement, then the data at offset 2).
     */
    private Kind readPacket(long timeoutMillis) throws IOException {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000;
        while (true) {
            long left = (deadline - System.nanoTime()) / 1_000_000;
            if (left <= 0) {
                return Kind.TIMEOUT;
            }
            int c = io.read(left);
            switch (c) {
                case -1:
                    return Kind.TIMEOUT;
                case SOH:
                    packetSize = 128;
                    break;
                case STX:
                    packetSize = 1024;
                    break;
                case EOT:
                    return Kind.EOT;
                case CAN:
                    if (io.read(config.charTimeout().toMillis()) == CAN) {
                        return Kind.CANCEL;
                    }
                    continue;
                default:
                    // line noise, or the echo of the command that started the sender
                    if (waitingForFirst && noise.length() < 4096) {
                        noise.append((char) c);
                        if (gaveUp.test(noise)) {
                            return Kind.TIMEOUT;
                        }
                    }
                    continue;
            }
            if (!io.readFully(packet, 0, packetSize + 4, config.charTimeout().toMillis())) {
                log.debug("short block");
                return Kind.BAD;
            }
            int seq = packet[0] & 0xFF;
            if (((packet[1] & 0xFF) ^ 0xFF) != seq) {
                log.debug("block number {} does not match its complement {}", seq, packet[1] & 0xFF);
                return Kind.BAD;
            }
            int crc = ((packet[packetSize + 2] & 0xFF) << 8) | (packet[packetSize + 3] & 0xFF);
            if (CRC16CCITT.compute(packet, 2, packetSize) != crc) {
                log.debug("CRC error in block {}", seq);
                return Kind.BAD;
            }
            packetSeq = seq;
            return Kind.DATA;
        }
    }

    private YmodemException abort(String why) {
        io.cancel();
        log.warn("YMODEM receive cancelled: {}", why);
        return new YmodemException(why);
    }
}
