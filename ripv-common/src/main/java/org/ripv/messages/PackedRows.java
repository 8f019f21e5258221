package org.ripv.messages;

import java.io.InvalidObjectException;
import java.util.AbstractList;
import java.util.Arrays;
import java.util.Objects;
import java.util.RandomAccess;

/**
 * A table's rows as they travel: every cell in one byte array in {@link PackedTable}'s layout
 * (row by row, each cell its UTF-8 length, -1 for null, and bytes), turned into text only when
 * someone reads a row. A page of a query (issue 38) is packed once, by the service as it reads the
 * database's cursor, and unpacked once, by whoever reads the rows at the end; the server in between
 * checks the lengths, forwards the same bytes to the client and never builds a String of them
 * (docs/performance.md, "The database"). Before, each page was built as String rows, packed for RMI,
 * unpacked in the server, packed again for the client's socket and unpacked there.
 *
 * <p>Immutable to its readers: the rows are decoded into one array on the first read and that
 * array is handed out, as a {@code List<String[]>} of any other kind hands out its rows.
 * Thread-safe.
 */
public final class PackedRows extends AbstractList<String[]> implements RandomAccess {
    private final int width;
    private final int count;
    private final byte[] buf;
    private final int from;
    private final int to;
    private volatile String[][] decoded;

    private PackedRows(int width, int count, byte[] buf, int from, int to) {
        this.width = width;
        this.count = count;
        this.buf = buf;
        this.from = from;
        this.to = to;
    }

    /** Rows packed as they are read: {@link Builder#cell} each value of a row, then {@link Builder#endRow}. */
    public static Builder builder(int width) {
        return new Builder(width);
    }

    /**
     * The {@code count} rows of {@code width} cells that start at the reader's position, checked
     * against the bytes present (a hostile length is refused here, before anything is allocated for
     * it) and kept as bytes; the reader is left after them.
     */
    static PackedRows read(PackedBytes.Reader r, int width, int count) throws InvalidObjectException {
        int start = r.position();
        long cells = (long) width * count;
        for (long i = 0; i < cells; i++) {
            r.skipString();
        }
        return new PackedRows(width, count, r.array(), start, r.position());
    }

    /** Values per row. */
    public int width() {
        return width;
    }

    /** The packed cells' size in bytes. */
    public int bytes() {
        return to - from;
    }

    /**
     * What {@code head} holds followed by the packed cells as they are, in an array of exactly that
     * size: the very array these rows were read from when it holds just that (a page the server
     * sends on as it came), else a new one.
     */
    byte[] after(PackedBytes.Writer head) {
        if (from == head.size() && to == buf.length && Arrays.equals(buf, 0, from, head.buffer(), 0, from)) {
            return buf; // never written to: the rows are immutable, and so is the array they came in
        }
        byte[] out = Arrays.copyOf(head.buffer(), head.size() + bytes());
        System.arraycopy(buf, from, out, head.size(), bytes());
        return out;
    }

    @Override
    public int size() {
        return count;
    }

    @Override
    public String[] get(int index) {
        Objects.checkIndex(index, count);
        String[][] rows = decoded;
        return (rows != null ? rows : decode())[index];
    }

    private synchronized String[][] decode() {
        if (decoded != null) {
            return decoded;
        }
        PackedBytes.Reader r = new PackedBytes.Reader(buf, from, to, "packed rows");
        String[][] rows = new String[count][];
        try {
            for (int i = 0; i < count; i++) {
                String[] row = new String[width];
                for (int j = 0; j < width; j++) {
                    row[j] = r.readString();
                }
                rows[i] = row;
            }
        } catch (InvalidObjectException e) {
            // read() and Builder checked every length: only a bug gets here
            throw new IllegalStateException("packed rows changed after they were checked", e);
        }
        decoded = rows;
        return rows;
    }

    /** Packs rows cell by cell as a cursor is read; see {@link PackedRows#builder}. */
    public static final class Builder {
        private final int width;
        private PackedBytes.Writer out = new PackedBytes.Writer(4096, "page of rows");
        private int rows;
        private int cells;

        private Builder(int width) {
            if (width < 0) {
                throw new IllegalArgumentException("a row needs 0 or more values, not " + width);
            }
            this.width = width;
        }

        /** The next value of the row under way; null for SQL NULL. */
        public void cell(String value) {
            if (cells == width) {
                throw new IllegalStateException("a row has " + width + " values; endRow() before the next");
            }
            out.writeString(value);
            cells++;
        }

        /** Ends the row under way, which must have {@code width} values. */
        public void endRow() {
            if (cells != width) {
                throw new IllegalStateException("a row needs " + width + " values, got " + cells);
            }
            cells = 0;
            rows++;
        }

        /** Rows ended so far. */
        public int rows() {
            return rows;
        }

        /**
         * The rows ended so far, in an array of their size; the builder starts empty again and keeps
         * its grown buffer for the next page, so a page costs one array of its size, not a dozen
         * doublings up to one of twice its size.
         */
        public PackedRows build() {
            if (cells != 0) {
                throw new IllegalStateException("a row is under way: " + cells + " of " + width + " values");
            }
            byte[] exact = out.toArray();
            out.clear();
            PackedRows p = new PackedRows(width, rows, exact, 0, exact.length);
            rows = 0;
            return p;
        }
    }
}
