package org.ripv.services.serial.zmodem;

import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.zip.CRC32;
import org.ripv.services.serial.ymodem.ByteLink;
import org.ripv.services.serial.ymodem.FileHeader;
import org.ripv.services.serial.ymodem.SendFile;
import org.ripv.services.serial.ymodem.TransferListener;

/**
 * Sends one file by ZMODEM (the vehicle runs {@code rz}): waits for its ZRINIT, offers the file
 * (ZFILE), streams it from where the receiver asks (ZRPOS; an {@code rz} that kept a part asks
 * from its length), goes back to any position it asks again, and ends with ZEOF, ZFIN and "OO".
 * A receiver asking for a position beyond the file is refused, not humoured.
 *
 * <p>Longer than 400 lines for one job: ZMODEM's sending side, whose states (offer, stream, reposition,
 * end) answer the same receiver headers and share the position in the file.
 */
public final class ZmodemSender extends ZmodemPeer<ZmodemSender> {
    /** The data subpacket size: lrzsz's, a good fit for 2,400 baud and 115,200 alike. */
    static final int SUBPACKET = 1024;
    /** How long a header on the back channel may take to complete once its first byte is here. */
    static final long BACK_CHANNEL_MILLIS = 200;
    /**
     * How often the stream stops to look for a ZRPOS. Each look waits a moment for a byte, and on
     * a loaded machine that moment stretches: looking after every subpacket left the line idle
     * one time in ten at 115,200 baud.
     */
    static final long LOOK_EVERY_NANOS = 200_000_000L;
    /** How long a header that may follow a repeated ZRINIT is waited for before the ZFILE goes again (sz: 5 s). */
    static final long OFFER_DRAIN_MILLIS = 5000;
    /** How long a receiver's repeated ZFIN is waited for after "OO". */
    static final long OO_REPEAT_MILLIS = 500;

    /**
     * The window on a link that buffers deeply ({@link ByteLink#buffersDeeply}): at most this many
     * bytes ahead of the receiver's last ZACK, asked for every quarter of it (ZCRCQ), as {@code sz -w}
     * does. A quarter, 1 KiB, takes 4.3 s at 2,400 baud: well inside the 10 s a frame may take.
     */
    public static final int DEEP_LINK_WINDOW = 4096;
    /** How many times a silent receiver is asked where it is before the transfer gives up. */
    static final int ACK_TRIES = 4;

    private boolean crc32 = true;
    private int receiverBuffer;
    private int window;
    private long acked;

    public ZmodemSender(ByteLink link, long timeoutMillis, TransferListener listener) {
        super(link, timeoutMillis, listener);
        this.window = link.buffersDeeply() ? DEEP_LINK_WINDOW : 0;
    }

    /**
     * Keeps the stream at most {@code bytes} ahead of the receiver's acknowledgements (0: stream
     * without them, as over a serial line). The default follows the link: {@value #DEEP_LINK_WINDOW}
     * on one that buffers deeply, none on others.
     */
    public ZmodemSender window(int bytes) {
        if (bytes != 0 && bytes < 4 * 64) {
            throw new IllegalArgumentException("a ZMODEM window is 0 (none) or at least 256 bytes, not " + bytes);
        }
        this.window = bytes;
        return this;
    }

    @Override
    ZmodemSender self() {
        return this;
    }

    /**
     * Sends {@code file}.
     *
     * @return the position the receiver started from (0, or the length of the part it kept)
     */
    public long send(SendFile file) throws IOException {
        ZHeader h = awaitZrinit();
        FileHeader header = new FileHeader(file.name(), file.length(), file.mtimeSeconds(), file.mode());
        long start = offer(file, h);
        if (start < 0) {
            endAfterSkip();
            throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle skipped " + file.name()
                    + " (ZSKIP: it may have it already, or may not write it)");
        }
        listener.started(header);
        if (start > 0) {
            listener.resumed(header, start);
        }
        long pos = start;
        int rounds = 0;
        while (true) {
            ZHeader answer = stream(file, header, pos);
            switch (answer.type()) {
                case Zmodem.ZRINIT -> {
                    finishSession();
                    listener.finished(header);
                    return start;
                }
                case Zmodem.ZRPOS -> {
                    pos = checkedPosition(file, answer);
                    if (++rounds > ZmodemReceiver.MAX_ERRORS) {
                        abort();
                        throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle asked for " + file.name()
                                + " again " + rounds + " times (a bad line); stopped at byte " + pos);
                    }
                }
                case Zmodem.ZSKIP -> {
                    endAfterSkip();
                    throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle stopped taking " + file.name() + " (ZSKIP)");
                }
                case Zmodem.ZFERR, Zmodem.ZABORT, Zmodem.ZCAN -> throw new ZmodemException(
                        ZmodemException.Kind.LINE, "the vehicle stopped taking " + file.name() + " ("
                        + Zmodem.name(answer.type()) + ")");
                default -> throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "unexpected " + answer
                        + " after the data of " + file.name());
            }
        }
    }

    private ZHeader awaitZrinit() throws IOException {
        long deadline = System.nanoTime() + startTimeoutMillis * 1_000_000L;
        while (true) {
            checkCancel();
            try {
                ZHeader h = in.header(Math.min(timeoutMillis, 1000), refusal);
                if (h.type() == Zmodem.ZRINIT) {
                    crc32 = (h.zf0() & Zmodem.CANFC32) != 0;
                    out.escapeControls((h.zf0() & Zmodem.ESCCTL) != 0);
                    receiverBuffer = (h.p()[0] & 0xFF) | (h.p()[1] & 0xFF) << 8;
                    return h;
                }
                if (h.type() == Zmodem.ZCHALLENGE) {
                    out.hex(ZHeader.position(Zmodem.ZACK, h.position()));
                }
            } catch (ZFrameReader.Timeout e) {
                if (System.nanoTime() - deadline > 0) {
                    throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle did not start receiving within "
                            + startTimeoutMillis / 1000 + " s");
                }
                out.hex(ZHeader.position(Zmodem.ZRQINIT, 0));
            }
        }
    }

    /** ZFILE and its subpacket, until the receiver says where to start (or -1: ZSKIP). */
    private long offer(SendFile file, ZHeader zrinit) throws IOException {
        String info = file.name() + "\0" + file.length() + " " + Long.toOctalString(file.mtimeSeconds()) + " "
                + Integer.toOctalString(file.mode()) + " 0 1 " + file.length() + "\0";
        byte[] b = info.getBytes(StandardCharsets.ISO_8859_1);
        ZHeader pending = null;
        for (int tries = 0; tries < ZmodemReceiver.MAX_ERRORS; tries++) {
            checkCancel();
            ZHeader h;
            if (pending != null) {
                h = pending;
                pending = null;
            } else {
                out.binary(ZHeader.flags(Zmodem.ZFILE, Zmodem.ZCBIN, 0, 0, 0).as32(crc32));
                out.data(b, 0, b.length, Zmodem.ZCRCW, crc32);
                try {
                    h = in.header(timeoutMillis, null);
                } catch (ZFrameReader.Timeout e) {
                    continue;
                }
            }
            if (h.type() == Zmodem.ZRINIT) {
                // a receiver that repeated its ZRINIT before our ZFILE reached it: its answer to
                // the ZFILE may be on its way, and a second ZFILE would get a second ZRPOS that
                // sends the stream back mid-file (sz waits for it too)
                pending = backChannel(OFFER_DRAIN_MILLIS);
                if (pending != null) {
                    continue;
                }
            }
            switch (h.type()) {
                case Zmodem.ZRPOS -> {
                    return checkedPosition(file, h);
                }
                case Zmodem.ZSKIP -> {
                    return -1;
                }
                case Zmodem.ZCRC -> {
                    // rz -r asks for the CRC of the part it has before it resumes
                    out.hex(ZHeader.position(Zmodem.ZCRC, crcOf(file, h.position())));
                    h = in.header(timeoutMillis, null);
                    if (h.type() == Zmodem.ZRPOS) {
                        return checkedPosition(file, h);
                    }
                    if (h.type() == Zmodem.ZSKIP) {
                        return -1;
                    }
                }
                default -> { } // ZRINIT again, ZNAK: offer again
            }
        }
        throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle never accepted the offer of " + file.name());
    }

    private long checkedPosition(SendFile file, ZHeader h) throws IOException {
        long p = h.position();
        if (p > file.length()) {
            abort();
            throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "the vehicle asked to resume " + file.name()
                    + " at byte " + p + ", beyond its " + file.length() + " bytes; stopped (delete its part on the vehicle"
                    + " and send again)");
        }
        return p;
    }

    private static long crcOf(SendFile file, long length) throws IOException {
        CRC32 crc = new CRC32();
        long left = length <= 0 ? file.length() : Math.min(length, file.length());
        try (InputStream s = file.source().open()) {
            byte[] b = new byte[8192];
            int n;
            while (left > 0 && (n = s.read(b, 0, (int) Math.min(b.length, left))) > 0) {
                crc.update(b, 0, n);
                left -= n;
            }
        }
        return crc.getValue();
    }

    /**
     * ZDATA from {@code pos} to the end, then ZEOF; returns the receiver's answer (ZRINIT when it
     * has the file, ZRPOS to go back). A ZRPOS that arrives while streaming stops it at once.
     */
    private ZHeader stream(SendFile file, FileHeader header, long pos) throws IOException {
        try (InputStream s = file.source().open()) {
            s.skipNBytes(pos);
            out.binary(ZHeader.position(Zmodem.ZDATA, pos).as32(crc32));
            long p = pos;
            long sinceAck = 0;
            long sinceQuery = 0;
            acked = pos;
            long lastLook = System.nanoTime();
            while (p < file.length()) {
                checkCancel();
                int n = s.readNBytes(buf, 0, (int) Math.min(SUBPACKET, file.length() - p));
                if (n <= 0) {
                    throw new ZmodemException(ZmodemException.Kind.PROTOCOL, file.name() + " is shorter than its "
                            + file.length() + " bytes");
                }
                p += n;
                sinceAck += n;
                sinceQuery += n;
                boolean last = p == file.length();
                boolean waitAck = receiverBuffer > 0 && sinceAck + SUBPACKET > receiverBuffer;
                boolean query = window > 0 && sinceQuery >= window / 4;
                out.data(buf, 0, n, last ? Zmodem.ZCRCE : waitAck ? Zmodem.ZCRCW : query ? Zmodem.ZCRCQ : Zmodem.ZCRCG, crc32);
                if (query) {
                    sinceQuery = 0;
                }
                listener.progress(header, p);
                if (waitAck && !last) {
                    ZHeader h = in.header(timeoutMillis, null);
                    if (h.type() != Zmodem.ZACK) {
                        return h;
                    }
                    sinceAck = 0;
                    out.binary(ZHeader.position(Zmodem.ZDATA, p).as32(crc32));
                } else if (window > 0 && !last && p - acked >= window) {
                    ZHeader h = inStep(file, p);
                    if (h != null) {
                        return h;
                    }
                } else if (System.nanoTime() - lastLook > LOOK_EVERY_NANOS && in.ready()) {
                    lastLook = System.nanoTime();
                    ZHeader h = whileStreaming();
                    if (h != null) {
                        return h;
                    }
                }
            }
            if (file.length() == 0) {
                out.data(buf, 0, 0, Zmodem.ZCRCE, crc32);
            }
        }
        for (int tries = 0; tries < ZmodemReceiver.MAX_ERRORS / 4; tries++) {
            out.hex(ZHeader.position(Zmodem.ZEOF, file.length()));
            try {
                while (true) {
                    ZHeader h = in.header(timeoutMillis, null);
                    if (h.type() != Zmodem.ZACK) {
                        return h;
                    }
                }
            } catch (ZFrameReader.Timeout e) {
                // ZEOF lost: send it again
            }
        }
        throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle did not answer the end of " + file.name());
    }

    /**
     * What the receiver sent while we stream: a ZRPOS, or only the tail of an earlier hex header
     * (CR, LF, XON), which must not stop the stream for a full timeout.
     */
    private ZHeader backChannel() throws IOException {
        return backChannel(BACK_CHANNEL_MILLIS);
    }

    /** Everything the receiver has sent while we stream: ZACKs move the window on; a ZRPOS stops the stream. */
    private ZHeader whileStreaming() throws IOException {
        do {
            ZHeader h = backChannel();
            if (h == null) {
                return null;
            }
            if (h.type() == Zmodem.ZACK) {
                acked = Math.max(acked, h.position());
            } else if (h.type() == Zmodem.ZRPOS) {
                return h;
            }
        } while (in.ready());
        return null;
    }

    /**
     * Waits, with a full window out, for the receiver's ZACKs to show it has caught up. A receiver
     * silent for a frame timeout is asked where it is (an empty ZCRCQ) up to {@value #ACK_TRIES}
     * times. Returns a header that stops the stream (a ZRPOS), or null to go on.
     */
    private ZHeader inStep(SendFile file, long p) throws IOException {
        int silences = 0;
        while (p - acked >= window) {
            checkCancel();
            ZHeader h;
            try {
                h = in.header(timeoutMillis, null);
            } catch (ZFrameReader.Timeout e) {
                if (++silences >= ACK_TRIES) {
                    throw new ZmodemException(ZmodemException.Kind.LINE, "the vehicle stopped acknowledging " + file.name()
                            + " at byte " + acked + " of " + file.length());
                }
                out.data(buf, 0, 0, Zmodem.ZCRCQ, crc32);
                continue;
            }
            if (h.type() == Zmodem.ZACK) {
                acked = Math.max(acked, h.position());
            } else if (h.type() != Zmodem.ZRINIT) {
                return h;
            }
        }
        return null;
    }

    private ZHeader backChannel(long millis) throws IOException {
        try {
            return in.header(millis, null);
        } catch (ZFrameReader.Timeout e) {
            return null;
        }
    }

    /**
     * A receiver that skipped the file waits for the next one: ZFIN tells it there is none, so its
     * rz ends now and the shell is back, instead of after rz's own timeouts (minutes of a call at
     * the surface). Failing that, the skip is still what is reported.
     */
    private void endAfterSkip() {
        try {
            finishSession();
        } catch (IOException e) {
            // the line is gone or garbled: the receiver times out on its own
        }
    }

    /** ZFIN, the receiver's ZFIN, then "OO": the session is over and the vehicle's shell is back. */
    private void finishSession() throws IOException {
        for (int tries = 0; tries < 5; tries++) {
            out.hex(ZHeader.position(Zmodem.ZFIN, 0));
            try {
                ZHeader h = in.header(timeoutMillis, null);
                if (h.type() == Zmodem.ZFIN) {
                    overAndOut();
                    return;
                }
            } catch (ZFrameReader.Timeout e) {
                // ZFIN lost: again
            } catch (EOFException e) {
                return; // the receiver has the file (its ZRINIT said so) and hung up before its ZFIN arrived
            }
        }
        // the file is there (ZRINIT said so); an rz that never answers ZFIN times out on its own
    }

    /**
     * "OO". An rz that read the tail of our ZFIN (CR, LF) where it waited for 'O' purges its
     * input and sends ZFIN again: each repeat gets its "OO" again, so rz ends now, not after its
     * three ten-second waits.
     */
    private void overAndOut() throws IOException {
        for (int i = 0; i < 3; i++) {
            ZHeader again;
            try {
                out.raw("OO".getBytes(StandardCharsets.ISO_8859_1));
                again = backChannel(OO_REPEAT_MILLIS);
            } catch (IOException e) {
                if (i == 0 && !(e instanceof EOFException)) {
                    throw e;
                }
                return; // rz took the "OO" and ended, and with it a link that was only rz
            }
            if (again == null || again.type() != Zmodem.ZFIN) {
                return;
            }
        }
    }
}
