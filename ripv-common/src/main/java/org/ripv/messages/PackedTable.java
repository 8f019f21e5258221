package org.ripv.messages;

import java.io.InvalidObjectException;
import java.io.ObjectStreamException;
import java.io.Serial;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;

/**
 * The serialized form of a {@link TableResult}: the whole table as one byte array. Java
 * serialization of a table as objects writes, and on reading checks against the wire filter,
 * one object per cell and per row (600,000 for 100,000 rows of five columns); a table crosses
 * two object streams on its way (RMI, then the client socket), and that dominated the time of a
 * large query. One array is written and read at memory speed.
 *
 * <p>Layout ({@link PackedBytes}): version, query, truncated, column count, columns, types, row
 * count, cells row by row. The cells arrive as {@link PackedRows}: their lengths are checked on
 * reading, their text is built only when a row is read, and a table sent on (the server relaying
 * a page) writes the same bytes again.
 */
final class PackedTable implements Serializable {
    @Serial
    private static final long serialVersionUID = 1L;
    private static final int VERSION = 1;

    private final byte[] data;

    PackedTable(TableResult t) {
        boolean packed = t.rows() instanceof PackedRows;
        int cells = packed ? 0 : t.rows().size() * Math.max(1, t.columns().size()) * 12;
        PackedBytes.Writer w = new PackedBytes.Writer(256 + t.query().length() * 3 + cells, "table");
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
        if (t.rows() instanceof PackedRows rows) {
            this.data = rows.after(w); // the cells as they came, never turned into text here
            return;
        }
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
        PackedBytes.Reader r = new PackedBytes.Reader(data, "packed table");
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
        PackedRows out = PackedRows.read(r, n, rows);
        if (r.remaining() != 0) {
            throw new InvalidObjectException("packed table has " + r.remaining() + " bytes after its last row");
        }
        try {
            return new TableResult(query, columns, types, out, truncated);
        } catch (IllegalArgumentException e) {
            throw new InvalidObjectException(e.getMessage());
        }
    }
}
