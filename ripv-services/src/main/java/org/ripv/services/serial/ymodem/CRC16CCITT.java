package org.ripv.services.serial.ymodem;

/**
 * CRC-16-CCITT as XMODEM/YMODEM use it (thesis, class CRC16CCITT): polynomial 0x1021, initial
 * value 0, no reflection, sent high byte first. {@code compute("123456789")} is 0x31C3.
 */
public final class CRC16CCITT {
    private static final int[] TABLE = new int[256];

    static {
        for (int i = 0; i < 256; i++) {
            int crc = i << 8;
            for (int bit = 0; bit < 8; bit++) {
                crc = (crc & 0x8000) != 0 ? (crc << 1) ^ 0x1021 : crc << 1;
            }
            TABLE[i] = crc & 0xFFFF;
        }
    }

    private CRC16CCITT() {
    }

    /** Continues {@code crc} over {@code len} bytes of {@code data} from {@code offset}. */
    public static int update(int crc, byte[] data, int offset, int len) {
        int c = crc & 0xFFFF;
        for (int i = offset; i < offset + len; i++) {
            c = ((c << 8) ^ TABLE[((c >>> 8) ^ data[i]) & 0xFF]) & 0xFFFF;
        }
        return c;
    }

    /** The CRC of {@code len} bytes of {@code data} from {@code offset}. */
    public static int compute(byte[] data, int offset, int len) {
        return update(0, data, offset, len);
    }

    /** The CRC of all of {@code data}. */
    public static int compute(byte[] data) {
        return compute(data, 0, data.length);
    }
}
