package org.ripv.services.serial.zmodem;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.function.Predicate;
import java.util.zip.CRC32;
import org.ripv.services.serial.ymodem.ByteLink;
import org.ripv.services.serial.ymodem.CRC16CCITT;

/**
 * Decodes ZMODEM frames from a link: headers (hex, 16- and 32-bit binary) and ZDLE-escaped data
 * subpackets with their CRCs. Whatever comes between frames is skipped, up to a limit: a line
 * that carries only garbage is an error, not an endless wait. Five CANs in a row are the peer's
 * abort.
 */
public final class ZFrameReader {
    /** A read found no byte in time. */
    static final class Timeout extends IOException {
        private static final long serialVersionUID = 1L;

        Timeout(String what) {
            super(what);
        }
    }

    /** How a data subpacket ended. */
    public record Subpacket(int length, int end, boolean crcOk) {
    }

    private static final int FRAME_END = 0x100;
    private final ByteLink link;
    private final byte[] buf = new byte[8192];
    private int pos;
    private int len;
    /** The bytes skipped while looking for a header, for an error message (and a refusal check). */
    private final StringBuilder skipped = new StringBuilder();
    private int garbageLimit = 8192;

    public ZFrameReader(ByteLink link) {
        this.link = link;
    }

    /** How many bytes between frames are tolerated before the line is declared garbage. */
    public ZFrameReader garbageLimit(int bytes) {
        this.garbageLimit = bytes;
        return this;
    }

    private int raw(long timeoutMillis) throws IOException {
        if (pos == len) {
            int n = link.read(buf, 0, buf.length, timeoutMillis);
            if (n <= 0) {
                throw new Timeout("nothing arrived for " + timeoutMillis + " ms");
            }
            pos = 0;
            len = n;
        }
        return buf[pos++] & 0xFF;
    }

    /** True when bytes are waiting (or arrive within a millisecond): the sender's look for a ZRPOS. */
    boolean ready() throws IOException {
        if (pos < len) {
            return true;
        }
        int n = link.read(buf, 0, buf.length, 1);
        pos = 0;
        len = Math.max(0, n);
        return n > 0;
    }

    /**
     * Reads the next header, skipping anything before it.
     *
     * @param timeoutMillis the longest silence allowed
     * @param refusal       asked with the text skipped so far; true stops the wait (the vehicle's
     *                      shell answered instead of its ZMODEM program), or null
     */
    public ZHeader header(long timeoutMillis, Predicate<String> refusal) throws IOException {
        skipped.setLength(0);
        int cans = 0;
        while (true) {
            int c = raw(timeoutMillis);
            if (c == Zmodem.ZDLE) {
                cans = oneMoreCan(cans);
                continue;
            }
            cans = 0;
            if (c == Zmodem.ZPAD) {
                ZHeader h = afterPad(timeoutMillis);
                if (h != null) {
                    garbage = 0;
                    return h;
                }
                continue;
            }
            skip(c, refusal);
        }
    }

    private void skip(int c, Predicate<String> refusal) throws ZmodemException {
        if (skipped.length() < 256) {
            skipped.append((char) c);
        }
        if (refusal != null && refusal.test(skipped.toString())) {
            throw new ZmodemException(ZmodemException.Kind.REFUSED, skippedText());
        }
        if (++garbage > garbageLimit) {
            throw new ZmodemException(ZmodemException.Kind.PROTOCOL, garbage + " bytes of garbage where ZMODEM frames"
                    + " were expected, starting '" + skippedText() + "'; is the vehicle running a ZMODEM program?");
        }
    }

    private int garbage;

    /** Clears the garbage count: the caller saw a sound frame. */
    void sound() {
        garbage = 0;
    }

    /** What was skipped, printable. */
    String skippedText() {
        return skipped.toString().replaceAll("[\\x00-\\x1f\\x7f-\\xff]", ".");
    }

    /** After a ZPAD: more pads, ZDLE, then the format letter; null when it was no header after all. */
    private ZHeader afterPad(long timeoutMillis) throws IOException {
        int c = raw(timeoutMillis);
        while (c == Zmodem.ZPAD) {
            c = raw(timeoutMillis);
        }
        if (c != Zmodem.ZDLE) {
            skip(c, null);
            return null;
        }
        int format = raw(timeoutMillis);
        return switch (format) {
            case Zmodem.ZHEX -> hex(timeoutMillis);
            case Zmodem.ZBIN -> binary(timeoutMillis, false);
            case Zmodem.ZBIN32 -> binary(timeoutMillis, true);
            default -> {
                skip(format, null);
                yield null;
            }
        };
    }

    private ZHeader hex(long timeoutMillis) throws IOException {
        byte[] b = new byte[7];
        for (int i = 0; i < b.length; i++) {
            int hi = hexDigit(raw(timeoutMillis));
            int lo = hexDigit(raw(timeoutMillis));
            if (hi < 0 || lo < 0) {
                return bad("a hex header with a character that is not a hex digit");
            }
            b[i] = (byte) (hi << 4 | lo);
        }
        int crc = CRC16CCITT.compute(b, 0, 5);
        if (crc != ((b[5] & 0xFF) << 8 | (b[6] & 0xFF))) {
            return bad("a hex header with a bad CRC");
        }
        return header(b, false);
    }

    private ZHeader binary(long timeoutMillis, boolean crc32) throws IOException {
        byte[] b = new byte[crc32 ? 9 : 7];
        for (int i = 0; i < b.length; i++) {
            int c = zdl(timeoutMillis);
            if (c < 0 || (c & FRAME_END) != 0) {
                return bad("a binary header cut by a frame end");
            }
            b[i] = (byte) c;
        }
        boolean ok;
        if (crc32) {
            CRC32 crc = new CRC32();
            crc.update(b, 0, 5);
            long sent = (b[5] & 0xFFL) | (b[6] & 0xFFL) << 8 | (b[7] & 0xFFL) << 16 | (b[8] & 0xFFL) << 24;
            ok = crc.getValue() == sent;
        } else {
            ok = CRC16CCITT.compute(b, 0, 5) == ((b[5] & 0xFF) << 8 | (b[6] & 0xFF));
        }
        return ok ? header(b, crc32) : bad("a binary header with a bad CRC");
    }

    private ZHeader bad(String what) throws ZmodemException {
        // a damaged header is skipped like garbage: the peer repeats it after a timeout or a ZRPOS
        for (char c : what.toCharArray()) {
            skip(c, null);
        }
        return null;
    }

    private ZHeader header(byte[] b, boolean crc32) throws ZmodemException {
        int type = b[0] & 0xFF;
        if (type > Zmodem.ZSTDERR) {
            return bad("an unknown header type " + type);
        }
        return new ZHeader(type, new byte[] {b[1], b[2], b[3], b[4]}, crc32);
    }

    private static int hexDigit(int c) {
        if (c >= '0' && c <= '9') {
            return c - '0';
        }
        if (c >= 'a' && c <= 'f') {
            return c - 'a' + 10;
        }
        return -1; // lrzsz sends lower case only
    }

    /**
     * One byte, unescaped: a data byte, FRAME_END|end for ZDLE+ZCRCx, -1 for a bad escape.
     * Unescaped XON/XOFF are flow control and skipped, as lrzsz does.
     */
    private int zdl(long timeoutMillis) throws IOException {
        while (true) {
            int c = raw(timeoutMillis);
            if (c == Zmodem.ZDLE) {
                break;
            }
            if ((c & 0x7F) == 0x11 || (c & 0x7F) == 0x13) {
                continue;
            }
            return c;
        }
        int cans = 1;
        while (true) {
            int c = raw(timeoutMillis);
            if (c == Zmodem.ZDLE) {
                cans = oneMoreCan(cans);
                continue;
            }
            if ((c & 0x7F) == 0x11 || (c & 0x7F) == 0x13) {
                continue;
            }
            if (c >= Zmodem.ZCRCE && c <= Zmodem.ZCRCW) {
                return FRAME_END | c;
            }
            if (c == Zmodem.ZRUB0) {
                return 0x7F;
            }
            if (c == Zmodem.ZRUB1) {
                return 0xFF;
            }
            if ((c & 0x60) == 0x40) {
                return c ^ 0x40;
            }
            return -1;
        }
    }

    /**
     * Reads one data subpacket into {@code into}: its length and end, and whether its CRC held.
     * A subpacket longer than {@code into}, or with a bad escape, reads as a CRC failure: the
     * caller answers it as a damaged one (ZRPOS), and the garbage limit ends a line that does
     * nothing else.
     */
    public Subpacket data(byte[] into, boolean crc32, long timeoutMillis) throws IOException {
        int n = 0;
        while (true) {
            int c = zdl(timeoutMillis);
            if (c < 0) {
                return new Subpacket(n, 0, false);
            }
            if ((c & FRAME_END) != 0) {
                int end = c & 0xFF;
                return new Subpacket(n, end, crcHolds(into, n, end, crc32, timeoutMillis));
            }
            if (n == into.length) {
                garbage += n;
                if (garbage > garbageLimit) {
                    throw new ZmodemException(ZmodemException.Kind.PROTOCOL, "a data subpacket longer than "
                            + into.length + " bytes: garbage, not ZMODEM");
                }
                return new Subpacket(n, 0, false);
            }
            into[n++] = (byte) c;
        }
    }

    private boolean crcHolds(byte[] data, int n, int end, boolean crc32, long timeoutMillis) throws IOException {
        byte[] sent = new byte[crc32 ? 4 : 2];
        for (int i = 0; i < sent.length; i++) {
            int c = zdl(timeoutMillis);
            if (c < 0 || (c & FRAME_END) != 0) {
                return false;
            }
            sent[i] = (byte) c;
        }
        if (crc32) {
            CRC32 crc = new CRC32();
            crc.update(data, 0, n);
            crc.update(end);
            long got = (sent[0] & 0xFFL) | (sent[1] & 0xFFL) << 8 | (sent[2] & 0xFFL) << 16 | (sent[3] & 0xFFL) << 24;
            return crc.getValue() == got;
        }
        int crc = CRC16CCITT.update(CRC16CCITT.compute(data, 0, n), new byte[] {(byte) end}, 0, 1);
        return crc == ((sent[0] & 0xFF) << 8 | (sent[1] & 0xFF));
    }

    /** Reads what follows ZFIN from a sender ("OO"), without waiting long for it. */
    void overAndOut(long timeoutMillis) throws IOException {
        for (int i = 0; i < 2; i++) {
            try {
                raw(timeoutMillis);
            } catch (Timeout e) {
                return;
            }
        }
    }

    static String text(byte[] b, int n) {
        return new String(b, 0, n, StandardCharsets.ISO_8859_1);
    }

    /** One more CAN (ZDLE) in a row; the fifth is the other end's abort. */
    private static int oneMoreCan(int cans) throws ZmodemException {
        if (cans + 1 >= 5) {
            throw new ZmodemException(ZmodemException.Kind.ABORTED, "the other end aborted the transfer (CAN CAN CAN CAN CAN)");
        }
        return cans + 1;
    }
}
