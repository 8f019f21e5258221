package org.ripv.services.serial.zmodem;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.zip.CRC32;
import org.ripv.services.serial.ymodem.ByteLink;
import org.ripv.services.serial.ymodem.CRC16CCITT;

/**
 * Encodes ZMODEM frames: hex and binary headers, data subpackets with ZDLE escapes and their
 * CRC. Escapes ZDLE, and DLE, XON and XOFF with their high-bit twins, always, and every control
 * character when the receiver asked for it (ESCCTL), as lrzsz does.
 */
public final class ZFrameWriter {
    private static final byte[] HEX = "0123456789abcdef".getBytes(StandardCharsets.ISO_8859_1);
    private final ByteLink link;
    private final byte[] out = new byte[2 * Zmodem.MAX_SUBPACKET + 64];
    private int n;
    private boolean escapeControls;

    public ZFrameWriter(ByteLink link) {
        this.link = link;
    }

    /** The receiver wants every control character escaped (ZRINIT's ESCCTL). */
    void escapeControls(boolean on) {
        escapeControls = on;
    }

    /** A hex header: for the receiver's answers, readable on any line. */
    public void hex(ZHeader h) throws IOException {
        byte[] b = bytes(h);
        int crc = CRC16CCITT.compute(b, 0, 5);
        put(Zmodem.ZPAD);
        put(Zmodem.ZPAD);
        put(Zmodem.ZDLE);
        put(Zmodem.ZHEX);
        for (byte x : b) {
            putHex(x);
        }
        putHex((byte) (crc >>> 8));
        putHex((byte) crc);
        put('\r');
        put(0x8A);
        if (h.type() != Zmodem.ZFIN && h.type() != Zmodem.ZACK) {
            put(Zmodem.XON); // undoes an XOFF a noisy line may have left
        }
        flush();
    }

    /** A binary header, 32-bit CRC when {@code h.crc32()}; its data subpackets must match. */
    public void binary(ZHeader h) throws IOException {
        byte[] b = bytes(h);
        put(Zmodem.ZPAD);
        put(Zmodem.ZDLE);
        if (h.crc32()) {
            put(Zmodem.ZBIN32);
            CRC32 crc = new CRC32();
            crc.update(b, 0, 5);
            escaped(b, 0, 5);
            crc32(crc.getValue());
        } else {
            put(Zmodem.ZBIN);
            escaped(b, 0, 5);
            int crc = CRC16CCITT.compute(b, 0, 5);
            escaped(new byte[] {(byte) (crc >>> 8), (byte) crc}, 0, 2);
        }
        flush();
    }

    /** A data subpacket ending with {@code end} (ZCRCE, ZCRCG, ZCRCQ, ZCRCW). */
    public void data(byte[] data, int offset, int length, int end, boolean crc32) throws IOException {
        escaped(data, offset, length);
        put(Zmodem.ZDLE);
        put(end);
        if (crc32) {
            CRC32 crc = new CRC32();
            crc.update(data, offset, length);
            crc.update(end);
            crc32(crc.getValue());
        } else {
            int crc = CRC16CCITT.update(CRC16CCITT.compute(data, offset, length), new byte[] {(byte) end}, 0, 1);
            escaped(new byte[] {(byte) (crc >>> 8), (byte) crc}, 0, 2);
        }
        if (end == Zmodem.ZCRCW) {
            put(Zmodem.XON);
        }
        flush();
    }

    /** Raw bytes ("OO" after ZFIN, the abort sequence). */
    void raw(byte[] bytes) throws IOException {
        flush();
        link.write(bytes, 0, bytes.length);
        link.flush();
    }

    private void crc32(long crc) {
        escaped(new byte[] {(byte) crc, (byte) (crc >>> 8), (byte) (crc >>> 16), (byte) (crc >>> 24)}, 0, 4);
    }

    private static byte[] bytes(ZHeader h) {
        byte[] p = h.p();
        return new byte[] {(byte) h.type(), p[0], p[1], p[2], p[3]};
    }

    private void escaped(byte[] data, int offset, int length) {
        for (int i = offset; i < offset + length; i++) {
            int c = data[i] & 0xFF;
            if ((c & 0x60) == 0 && needsEscape(c)) {
                ensure(2);
                out[n++] = Zmodem.ZDLE;
                out[n++] = (byte) (c ^ 0x40);
            } else {
                ensure(1);
                out[n++] = (byte) c;
            }
        }
    }

    /**
     * The seven the protocol names (ZDLE, DLE, XON, XOFF, and the last three with the high bit:
     * 0x18, 0x10, 0x90, 0x11, 0x91, 0x13, 0x93), as lrzsz's sz escapes them. Not 0x98: no
     * receiver takes it for ZDLE, and escaping it cost 0.17 % of the line on a glider's files.
     */
    private boolean needsEscape(int c) {
        if (c == Zmodem.ZDLE) {
            return true;
        }
        return switch (c & 0x7F) {
            case 0x10, 0x11, 0x13 -> true;
            default -> escapeControls;
        };
    }

    private void putHex(byte b) {
        put(HEX[(b >>> 4) & 0xF]);
        put(HEX[b & 0xF]);
    }

    private void put(int c) {
        ensure(1);
        out[n++] = (byte) c;
    }

    private void ensure(int room) {
        if (n + room > out.length) {
            try {
                flushBuffer();
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }

    private void flushBuffer() throws IOException {
        if (n > 0) {
            link.write(out, 0, n);
            n = 0;
        }
    }

    void flush() throws IOException {
        try {
            flushBuffer();
        } catch (UncheckedIOException e) {
            throw e.getCause();
        }
        link.flush();
    }
}
