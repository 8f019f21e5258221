package org.ripv.messages;

import java.io.InvalidObjectException;
import java.io.ObjectStreamException;
import java.io.Serial;
import java.io.Serializable;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * The serialized form of a {@link TableResult}: the whole table as one byte array. Java
 * serialization of a table as objects writes, and on reading checks against the wire filter,
 * one object per cell and per row (600,000 for 100,000 rows of five columns); a table crosses
 * two object streams on its way (RMI, then the client socket), and that dominated the time of a
 * large query. One array is written and read at memory speed.
 *
 * <p>Layout: version, query, truncated, column count, columns, types, row count, cells row by
 * row; a string is its UTF-8 length (-1 for null) and bytes. Reading checks every count and
 * length against what is left, so a hostile stream cannot make it allocate more than it sent.
 */
final class PackedTable implements Serializable {
    @Serial
    private static final long serialVersionUID = 1L;
    private static final int VERSION = 1;

    private final byte[] data;

    PackedTable(TableResult t) {
        Writer w = new Writer(64 + t.rows().size() * Math.max(1, t.columns().size()) * 12);
        w.writeInt(VERSION);
        w.writeString(t.query());
        w.writeInt(t.truncated() ? 1 : 0);
        w.writeInt(t.columns().size());
        for (String c : t.columns()) {
            w.writeString(c);
        }
        for (String c : t.types()) {
            w.writeString(c);
        }
        w.writeInt(t.rows().size());
        for (String[] row : t.rows()) {
            for (String cell : row) {
                w.writeString(cell);
            }
        }
        this.data = w.toArray();
    }

    @Serial
    private Object readResolve() throws ObjectStreamException {
        if (data == null) {
            throw new InvalidObjectException("packed table without data");
        }
        Reader r = new Reader(data);
        if (r.readInt() != VERSION) {
            throw new InvalidObjectException("unknown packed table version");
        }
        String query = r.readString();
        boolean truncated = r.readInt() != 0;
        int n = r.readCount(4);
        List<String> columns = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            columns.add(r.readString());
        }
        List<String> types = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            types.add(r.readString());
        }
        // every cell takes at least 4 bytes, so the count is bounded by what was sent
        int rows = r.readCount(4 * Math.max(1, n));
        List<String[]> out = new ArrayList<>(rows);
        for (int i = 0; i < rows; i++) {
            String[] row = new String[n];
            for (int j = 0; j < n; j++) {
                row[j] = r.readString();
            }
            out.add(row);
        }
        if (r.remaining() != 0) {
            throw new InvalidObjectException("packed table has " + r.remaining() + " bytes after its last row");
        }
        try {
            return new TableResult(query, columns, types, out, truncated);
        } catch (IllegalArgumentException e) {
            throw new InvalidObjectException(e.getMessage());
        }
    }

    private static final class Writer {
        private byte[] buf;
        private int size;

        Writer(int capacity) {
            buf = new byte[Math.max(64, Math.min(capacity, 1 << 26))];
        }

        private void ensure(int more) {
            if (size + more > buf.length) {
                long grown = Math.max((long) buf.length * 2, (long) size + more);
                if (grown > Integer.MAX_VALUE - 8) {
                    throw new IllegalStateException("table too large to send");
                }
                buf = java.util.Arrays.copyOf(buf, (int) grown);
            }
        }

        void writeInt(int v) {
            ensure(4);
            buf[size++] = (byte) (v >>> 24);
            buf[size++] = (byte) (v >>> 16);
            buf[size++] = (byte) (v >>> 8);
            buf[size++] = (byte) v;
        }

        void writeString(String s) {
            if (s == null) {
                writeInt(-1);
                return;
            }
            byte[] b = s.getBytes(StandardCharsets.UTF_8);
            writeInt(b.length);
            ensure(b.length);
            System.arraycopy(b, 0, buf, size, b.length);
            size += b.length;
        }

        byte[] toArray() {
            return java.util.Arrays.copyOf(buf, size);
        }
    }

    private static final class Reader {
        private final byte[] buf;
        private int pos;

        Reader(byte[] buf) {
            this.buf = buf;
        }

        int remaining() {
            return buf.length - pos;
        }

        int readInt() throws InvalidObjectException {
            if (remaining() < 4) {
                throw new InvalidObjectException("packed table cut short");
            }
            int v = ((buf[pos] & 0xff) << 24) | ((buf[pos + 1] & 0xff) << 16) | ((buf[pos + 2] & 0xff) << 8)
                    | (buf[pos + 3] & 0xff);
            pos += 4;
            return v;
        }

        int readCount(int minBytesEach) throws InvalidObjectException {
            int n = readInt();
            if (n < 0 || (long) n * minBytesEach > remaining()) {
                throw new InvalidObjectException("packed table count " + n + " does not fit its data");
            }
            return n;
        }

        String readString() throws InvalidObjectException {
            int len = readInt();
            if (len == -1) {
                return null;
            }
            if (len < 0 || len > remaining()) {
                throw new InvalidObjectException("packed table string length " + len + " does not fit its data");
            }
            String s = new String(buf, pos, len, StandardCharsets.UTF_8);
            pos += len;
            return s;
        }
    }
}
