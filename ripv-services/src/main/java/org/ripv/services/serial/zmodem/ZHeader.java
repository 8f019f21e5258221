package org.ripv.services.serial.zmodem;

import java.util.Locale;

/**
 * One ZMODEM header: a frame type and four bytes that are either a file position (ZP0 lowest
 * first) or flags (ZF0 is the last byte, as the protocol numbers them).
 *
 * @param type  {@link Zmodem#ZRQINIT} … {@link Zmodem#ZSTDERR}
 * @param p     the four argument bytes, ZP0..ZP3
 * @param crc32 true when it came as (or is to be sent as) a 32-bit binary header, whose data
 *              subpackets then carry CRC-32 too
 */
public record ZHeader(int type, byte[] p, boolean crc32) {

    public ZHeader {
        if (p.length != 4) {
            throw new IllegalArgumentException("a ZMODEM header has 4 argument bytes, not " + p.length);
        }
        p = p.clone();
    }

    /** A header carrying a position (ZRPOS, ZDATA, ZEOF, ZACK, ZCRC). */
    public static ZHeader position(int type, long position) {
        return new ZHeader(type, new byte[] {(byte) position, (byte) (position >>> 8), (byte) (position >>> 16),
                (byte) (position >>> 24)}, false);
    }

    /** A header carrying flags ZF0..ZF3. */
    public static ZHeader flags(int type, int zf0, int zf1, int zf2, int zf3) {
        return new ZHeader(type, new byte[] {(byte) zf3, (byte) zf2, (byte) zf1, (byte) zf0}, false);
    }

    /** The argument as a file position (unsigned 32 bits). */
    public long position() {
        return (p[0] & 0xFFL) | (p[1] & 0xFFL) << 8 | (p[2] & 0xFFL) << 16 | (p[3] & 0xFFL) << 24;
    }

    /** Flag byte ZF0 (the protocol's ZF0 is the fourth argument byte). */
    public int zf0() {
        return p[3] & 0xFF;
    }

    public int zf1() {
        return p[2] & 0xFF;
    }

    @Override
    public byte[] p() {
        return p.clone();
    }

    public ZHeader as32(boolean on) {
        return new ZHeader(type, p, on);
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%s(%d)", Zmodem.name(type), position());
    }
}
