package org.ripv.messages;

import java.io.InvalidObjectException;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * The byte layout shared by the packed serialized forms ({@link PackedTable}, {@link PackedConsole}):
 * big-endian numbers, and strings as their UTF-8 length (-1 for null) and bytes. The reader checks
 * every length and count against the bytes actually present, so a hostile stream cannot make it
 * allocate more than it sent.
 */
final class PackedBytes {
    private PackedBytes() {}

    static final class Writer {
        private byte[] buf;
        private int size;
        private final String what;

        /** @param what names the value in the error when it grows past what an array holds */
        Writer(int capacity, String what) {
            buf = new byte[Math.max(64, Math.min(capacity, 1 << 26))];
            this.what = what;
        }

        private void ensure(int more) {
            if (size + more > buf.length) {
                long grown = Math.max((long) buf.length * 2, (long) size + more);
                if (grown > Integer.MAX_VALUE - 8) {
                    throw new IllegalStateException(what + " too large to send");
                }
                buf = Arrays.copyOf(buf, (int) grown);
            }
        }

        void writeByte(int v) {
            ensure(1);
            buf[size++] = (byte) v;
        }

        void writeInt(int v) {
            ensure(4);
            buf[size++] = (byte) (v >>> 24);
            buf[size++] = (byte) (v >>> 16);
            buf[size++] = (byte) (v >>> 8);
            buf[size++] = (byte) v;
        }

        void writeLong(long v) {
            writeInt((int) (v >>> 32));
            writeInt((int) v);
        }

        void writeString(String s) {
            if (s == null) {
                writeInt(-1);
                return;
            }
            // ASCII (nearly every cell of a query: numbers, times, names) goes in as it is read, with
            // no byte[] per string: half the CPU of getBytes for a query's 500,000 cells.
            int n = s.length();
            ensure(4 + n);
            int at = size + 4;
            for (int i = 0; i < n; i++) {
                char c = s.charAt(i);
                if (c >= 0x80) {
                    writeUtf8(s);
                    return;
                }
                buf[at + i] = (byte) c;
            }
            writeInt(n);
            size += n;
        }

        private void writeUtf8(String s) {
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            writeInt(b.length);
            ensure(b.length);
            System.arraycopy(b, 0, buf, size, b.length);
            size += b.length;
        }

        int size() {
            return size;
        }

        /** Empties the writer, keeping its array for what comes next. */
        void clear() {
            size = 0;
        }

        /** The bytes written so far, in an array that may be longer: read only its first {@link #size()}. */
        byte[] buffer() {
            return buf;
        }

        byte[] toArray() {
            return Arrays.copyOf(buf, size);
        }
    }

    static final class Reader {
        private final byte[] buf;
        private final String what;
        private final int end;
        private int pos;

        /** @param what names the value in errors ("packed table") */
        Reader(byte[] buf, String what) {
            this(buf, 0, buf.length, what);
        }

        /** Reads {@code buf[from..to)}. */
        Reader(byte[] buf, int from, int to, String what) {
            this.buf = buf;
            this.pos = from;
            this.end = to;
            this.what = what;
        }

        int remaining() {
            return end - pos;
        }

        /** Where the next read starts in the array. */
        int position() {
            return pos;
        }

        byte[] array() {
            return buf;
        }

        private void need(int n) throws InvalidObjectException {
            if (remaining() < n) {
                throw new InvalidObjectException(what + " cut short");
            }
        }

        int readByte() throws InvalidObjectException {
            need(1);
            return buf[pos++] & 0xff;
        }

        int readInt() throws InvalidObjectException {
            need(4);
            int v = ((buf[pos] & 0xff) << 24) | ((buf[pos + 1] & 0xff) << 16) | ((buf[pos + 2] & 0xff) << 8)
                    | (buf[pos + 3] & 0xff);
            pos += 4;
            return v;
        }

        long readLong() throws InvalidObjectException {
            long high = readInt();
            return high << 32 | (readInt() & 0xffffffffL);
        }

        /** A count of items that each take at least {@code minBytesEach} of what remains. */
        int readCount(int minBytesEach) throws InvalidObjectException {
            int n = readInt();
            if (n < 0 || (long) n * minBytesEach > remaining()) {
                throw new InvalidObjectException(what + " count " + n + " does not fit its data");
            }
            return n;
        }

        String readString() throws InvalidObjectException {
            int len = readInt();
            if (len == -1) {
                return null;
            }
            if (len < 0 || len > remaining()) {
                throw new InvalidObjectException(what + " string length " + len + " does not fit its data");
            }
            String s = new String(buf, pos, len, StandardCharsets.UTF_8);
            pos += len;
            return s;
        }

        /** Checks a string's length against the bytes present and steps over it, building nothing. */
        void skipString() throws InvalidObjectException {
            int len = readInt();
            if (len == -1) {
                return;
            }
            if (len < 0 || len > remaining()) {
                throw new InvalidObjectException(what + " string length " + len + " does not fit its data");
            }
            pos += len;
        }
    }
}
