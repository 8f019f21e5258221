package org.ripv.services.serial.ymodem;

import java.io.IOException;

/** Buffered, timed byte access to a {@link ByteLink}, shared by sender and receiver. */
final class YmodemIo {
    static final int SOH = 0x01;
    static final int STX = 0x02;
    static final int EOT = 0x04;
    static final int ACK = 0x06;
    static final int NAK = 0x15;
    static final int CAN = 0x18;
    static final int CRC_REQUEST = 'C';
    static final int SUB = 0x1A;

    private final ByteLink link;
    private final byte[] buffer = new byte[16 * 1024];
    private int position;
    private int limit;

    YmodemIo(ByteLink link) {
        this.link = link;
    }

    /** The next byte, or -1 when none arrived within {@code timeoutMillis}. */
    int read(long timeoutMillis) throws IOException {
        if (position == limit && !fill(timeoutMillis)) {
            return -1;
        }
        return buffer[position++] & 0xFF;
    }

    /** Reads exactly {@code len} bytes, allowing {@code gapMillis} between them; false on a timeout. */
    boolean readFully(byte[] dst, int offset, int len, long gapMillis) throws IOException {
        int done = 0;
        while (done < len) {
            if (position == limit && !fill(gapMillis)) {
                return false;
            }
            int n = Math.min(len - done, limit - position);
            System.arraycopy(buffer, position, dst, offset + done, n);
            position += n;
            done += n;
        }
        return true;
    }

    /** Throws away what arrives until the line has been quiet for {@code quietMillis}. */
    void purge(long quietMillis) throws IOException {
        position = limit;
        while (fill(quietMillis)) {
            position = limit;
        }
    }

    /** Drops bytes already read from the link but not consumed (stale answers); never waits. */
    void discardBuffered() {
        position = limit;
    }

    private boolean fill(long timeoutMillis) throws IOException {
        int n = link.read(buffer, 0, buffer.length, Math.max(1, timeoutMillis));
        position = 0;
        limit = Math.max(0, n);
        return n > 0;
    }

    void write(byte[] bytes) throws IOException {
        link.write(bytes, 0, bytes.length);
        link.flush();
    }

    void write(int b) throws IOException {
        write(new byte[] {(byte) b});
    }

    /** lrzsz's abort: CANs to stop the far end, then backspaces to erase them from a shell. */
    void cancel() {
        try {
            write(new byte[] {CAN, CAN, CAN, CAN, CAN, CAN, CAN, CAN, 8, 8, 8, 8, 8, 8, 8, 8});
        } catch (IOException ignored) {
            // the link is already gone; nothing more to tell the other end
        }
    }
}
