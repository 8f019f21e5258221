package org.ripv.messages;

import java.io.InvalidObjectException;
import java.io.ObjectStreamException;
import java.io.Serial;
import java.io.Serializable;
import java.util.ArrayList;
import java.util.List;

/**
 * The serialized form of a {@link ConsoleBatch}: the entries as one byte array. The default form
 * wrote the class descriptors of the batch, the list, the entry record and its two enums into
 * every console push — most of a one-line push's 880 bytes, which a server sends once per
 * watcher per line (docs/performance.md, "The live console"). Packed, a one-line push is about
 * half that, and reading it creates no object per field.
 *
 * <p>Layout ({@link PackedBytes}): version, mailbox, skipped, more, entry count; per entry its
 * time, its sequence number (from version 2), its mailbox (null when it is the batch's), kind,
 * user, text, event (255 for none), and a flag byte followed by the latitude and longitude when it
 * has a position. Version 1 (no sequence numbers) is still read.
 */
final class PackedConsole implements Serializable {
    @Serial
    private static final long serialVersionUID = 1L;
    private static final int VERSION = 2;
    private static final int NO_EVENT = 255;
    /** The fewest bytes an entry takes: time, mailbox, kind, user, text, event, position flag. */
    private static final int MIN_ENTRY = 8 + 4 + 1 + 4 + 4 + 1 + 1;
    private static final int SEQ_BYTES = 8;

    private final byte[] data;

    PackedConsole(ConsoleBatch b) {
        PackedBytes.Writer w = new PackedBytes.Writer(32 + b.mailbox().length() + b.entries().size() * 96, "console batch");
        w.writeInt(VERSION);
        w.writeString(b.mailbox());
        w.writeLong(b.skipped());
        w.writeByte(b.more() ? 1 : 0);
        w.writeInt(b.entries().size());
        for (ConsoleEntry e : b.entries()) {
            w.writeLong(e.time());
            w.writeLong(e.seq());
            w.writeString(e.mailbox().equals(b.mailbox()) ? null : e.mailbox());
            w.writeByte(e.kind().ordinal());
            w.writeString(e.user());
            w.writeString(e.text());
            w.writeByte(e.event() == null ? NO_EVENT : e.event().ordinal());
            boolean position = e.lat() != null && e.lon() != null;
            w.writeByte(position ? 1 : 0);
            if (position) {
                w.writeLong(Double.doubleToLongBits(e.lat()));
                w.writeLong(Double.doubleToLongBits(e.lon()));
            }
        }
        this.data = w.toArray();
    }

    @Serial
    private Object readResolve() throws ObjectStreamException {
        if (data == null) {
            throw new InvalidObjectException("packed console batch without data");
        }
        PackedBytes.Reader r = new PackedBytes.Reader(data, "packed console batch");
        int version = r.readInt();
        if (version != 1 && version != VERSION) {
            throw new InvalidObjectException("unknown packed console batch version " + version);
        }
        String mailbox = nonNull(r.readString(), "mailbox");
        long skipped = r.readLong();
        boolean more = r.readByte() != 0;
        int n = r.readCount(MIN_ENTRY + (version == 1 ? 0 : SEQ_BYTES));
        List<ConsoleEntry> entries = new ArrayList<>(n);
        try {
            for (int i = 0; i < n; i++) {
                long time = r.readLong();
                long seq = version == 1 ? 0 : r.readLong();
                String own = r.readString();
                ConsoleEntry.Kind kind = ConsoleEntry.Kind.values()[index(r.readByte(), ConsoleEntry.Kind.values().length)];
                String user = r.readString();
                String text = r.readString();
                int event = r.readByte();
                VehicleEvent ev = event == NO_EVENT ? null : VehicleEvent.values()[index(event, VehicleEvent.values().length)];
                Double lat = null;
                Double lon = null;
                if (r.readByte() != 0) {
                    lat = Double.longBitsToDouble(r.readLong());
                    lon = Double.longBitsToDouble(r.readLong());
                }
                entries.add(new ConsoleEntry(time, own == null ? mailbox : own, kind, user, text, ev, lat, lon, seq));
            }
            if (r.remaining() != 0) {
                throw new InvalidObjectException("packed console batch has " + r.remaining() + " bytes after its last entry");
            }
            return new ConsoleBatch(mailbox, entries, skipped, more);
        } catch (NullPointerException | IllegalArgumentException e) {
            throw new InvalidObjectException("packed console batch: " + e.getMessage());
        }
    }

    private static String nonNull(String s, String what) throws InvalidObjectException {
        if (s == null) {
            throw new InvalidObjectException("packed console batch without its " + what);
        }
        return s;
    }

    private static int index(int i, int size) throws InvalidObjectException {
        if (i >= size) {
            throw new InvalidObjectException("packed console batch: enum index " + i + " out of range");
        }
        return i;
    }
}
