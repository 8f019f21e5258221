package org.ripv.services.serial.ymodem;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;

/** The test playing the other end of a transfer byte by byte. */
final class ScriptedPeer {
    private final ByteLink link;

    ScriptedPeer(ByteLink link) {
        this.link = link;
    }

    void send(int... bytes) throws IOException {
        byte[] b = new byte[bytes.length];
        for (int i = 0; i < bytes.length; i++) {
            b[i] = (byte) bytes[i];
        }
        link.write(b, 0, b.length);
    }

    void send(byte[] bytes) throws IOException {
        link.write(bytes, 0, bytes.length);
    }

    int next() throws IOException {
        byte[] b = new byte[1];
        if (link.read(b, 0, 1, 5000) != 1) {
            fail("no byte from the other end within 5 s");
        }
        return b[0] & 0xFF;
    }

    /** Reads bytes until SOH or STX and returns it. */
    int expectPacketStart() throws IOException {
        for (int i = 0; i < 10_000; i++) {
            int c = next();
            if (c == 0x01 || c == 0x02) {
                return c;
            }
        }
        fail("no packet");
        return -1;
    }

    void skip(int n) throws IOException {
        for (int i = 0; i < n; i++) {
            next();
        }
    }

    /** A block with sequence {@code seq} of {@code size} bytes holding {@code data} (zero-filled). */
    static byte[] packet(int seq, int size, byte[] data) {
        assertTrue(data.length <= size);
        byte[] p = new byte[size + 5];
        p[0] = (byte) (size == 128 ? 0x01 : 0x02);
        p[1] = (byte) seq;
        p[2] = (byte) ~seq;
        System.arraycopy(data, 0, p, 3, data.length);
        if (seq != 0) {
            java.util.Arrays.fill(p, 3 + data.length, 3 + size, (byte) 0x1A);
        }
        int crc = CRC16CCITT.compute(p, 3, size);
        p[3 + size] = (byte) (crc >>> 8);
        p[4 + size] = (byte) crc;
        return p;
    }
}
