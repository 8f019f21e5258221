package org.ripv.services.ingest;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Timestamp;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.Calendar;
import java.util.HashSet;
import java.util.Set;

/**
 * Writes one file's cycles for {@link DbaIngest}: a CYCLE row (vehicle, segment, time → the file
 * and row that hold its values), its READINGs and POSITION_FIXes, in JDBC batches.
 *
 * <p>Each cycle is stored once. When no cycle of this vehicle's segment is stored yet and the
 * file's times only rise — a segment's first file, the usual case — nothing needs looking up and
 * everything goes in batches. Otherwise (the {@code .dbd} after its {@code .sbd}, the compressed
 * form after the plain one, a file whose clock steps back) each cycle is looked up by its key; one
 * stored already gets this file's values: those of sensors it had are replaced, the others added,
 * its fixes replaced. Only one cycle's values are ever held.
 */
final class CycleWriter implements AutoCloseable {
    /** POSITION_FIX.SOURCE of the (m_gps_lat, m_gps_lon) and (m_lat, m_lon) pairs. */
    private static final String[] FIXES = {"gps", "dead-reckoned"};

    private final Connection c;
    private final Calendar utc;
    private final String vehicle;
    private final String segment;
    private final long fileId;
    private final int[][] fixColumns;
    private final PreparedStatement ins;
    private final PreparedStatement fix;
    private final PreparedStatement cyc;
    private PreparedStatement find;
    private PreparedStatement sensorsOf;
    private PreparedStatement update;
    private PreparedStatement unfix;
    private boolean lookup;
    private long lastUnits = Long.MIN_VALUE;
    private int pending;
    private int pendingFixes;
    private int pendingCycles;
    private long values;
    private long positions;
    private long merged;

    CycleWriter(Connection c, Calendar utc, String vehicle, String segment, long fileId, DbaHeader h) throws SQLException {
        this.c = c;
        this.utc = utc;
        this.vehicle = vehicle;
        this.segment = segment;
        this.fileId = fileId;
        this.fixColumns = new int[][] {{h.column("m_gps_lat"), h.column("m_gps_lon")}, {h.column("m_lat"), h.column("m_lon")}};
        this.ins = c.prepareStatement("INSERT INTO reading (file_id, row_no, sensor_id, vehicle, t, value) VALUES (?, ?, ?, ?, ?, ?)");
        this.fix = c.prepareStatement("INSERT INTO position_fix (vehicle, t, lat, lon, source, file_id, row_no)"
                + " VALUES (?, ?, ?, ?, ?, ?, ?)");
        this.cyc = c.prepareStatement("INSERT INTO cycle (vehicle, segment, t, file_id, row_no) VALUES (?, ?, ?, ?, ?)");
        ins.setString(4, vehicle);
        fix.setString(1, vehicle);
        cyc.setString(1, vehicle);
        cyc.setString(2, segment);
        cyc.setLong(4, fileId);
        try (PreparedStatement any = c.prepareStatement("SELECT 1 FROM cycle WHERE vehicle = ? AND segment = ? FETCH FIRST 1 ROWS ONLY")) {
            any.setString(1, vehicle);
            any.setString(2, segment);
            try (ResultSet rs = any.executeQuery()) {
                lookup = rs.next();
            }
        }
    }

    /**
     * A cycle's key time: its time to {@value #KEY_RESOLUTION} µs. dbd2asc prints a time with 15
     * significant digits (1561011830.32263: 10 µs), the binary file holds the whole double; both
     * forms of a cycle must have the same key.
     */
    static final int KEY_RESOLUTION = 10;

    /**
     * The time in {@value #KEY_RESOLUTION} µs units, from its 15 significant digits rounded as
     * printf rounds the exact double: a binary 1561013288.967864990… and its text 1561013288.96786
     * are one key (t × 1e5 in doubles would round the first up).
     */
    static long keyUnits(double t) {
        return new BigDecimal(t).round(new MathContext(15, RoundingMode.HALF_EVEN))
                .movePointRight(5).setScale(0, RoundingMode.HALF_EVEN).longValueExact();
    }

    /** Stores a cycle (row {@code rowNo} of this file, at {@code t} epoch seconds), or merges it into the one stored. */
    void cycle(long rowNo, double t, double[] row, int[] sensorIds) throws SQLException {
        Timestamp time = DbaIngest.timestamp(t);
        long units = keyUnits(t);
        Timestamp key = Timestamp.from(Instant.ofEpochSecond(0, 0).plus(units * KEY_RESOLUTION,
                ChronoUnit.MICROS));
        if (!lookup && units <= lastUnits) {
            flush(); // the clock stepped back or stood still: from here on, cycles are looked up
            lookup = true;
        }
        lastUnits = Math.max(lastUnits, units);
        if (lookup) {
            long[] at = find(key);
            if (at != null) {
                merge(at[0], at[1], time, row, sensorIds);
                merged++;
                return;
            }
        }
        cyc.setTimestamp(3, key, utc);
        cyc.setLong(5, rowNo);
        if (lookup) {
            cyc.executeUpdate(); // later lookups of this file must see it
        } else {
            cyc.addBatch();
            if (++pendingCycles == DbaIngest.BATCH) {
                cyc.executeBatch();
                pendingCycles = 0;
            }
        }
        fixes(fileId, rowNo, time, row, false);
        ins.setLong(1, fileId);
        ins.setLong(2, rowNo);
        ins.setTimestamp(5, time, utc);
        for (int i = 0; i < row.length; i++) {
            if (!Double.isNaN(row[i])) {
                reading(sensorIds[i], row[i]);
            }
        }
    }

    private void reading(int sensorId, double v) throws SQLException {
        ins.setInt(3, sensorId);
        ins.setDouble(6, v);
        ins.addBatch();
        values++;
        if (++pending == DbaIngest.BATCH) {
            ins.executeBatch();
            pending = 0;
        }
    }

    private void fixes(long file, long rowNo, Timestamp time, double[] row, boolean replace) throws SQLException {
        for (int p = 0; p < FIXES.length; p++) {
            int lat = fixColumns[p][0];
            int lon = fixColumns[p][1];
            if (lat < 0 || lon < 0 || Double.isNaN(row[lat]) || Double.isNaN(row[lon])) {
                continue;
            }
            if (replace) {
                if (unfix == null) {
                    unfix = c.prepareStatement("DELETE FROM position_fix WHERE file_id = ? AND row_no = ? AND source = ?");
                }
                unfix.setLong(1, file);
                unfix.setLong(2, rowNo);
                unfix.setString(3, FIXES[p]);
                unfix.executeUpdate();
            }
            positions++;
            fix.setTimestamp(2, time, utc);
            fix.setDouble(3, row[lat]);
            fix.setDouble(4, row[lon]);
            fix.setString(5, FIXES[p]);
            fix.setLong(6, file);
            fix.setLong(7, rowNo);
            fix.addBatch();
            if (++pendingFixes == DbaIngest.BATCH) {
                fix.executeBatch();
                pendingFixes = 0;
            }
        }
    }

    /** The (file, row) of the stored cycle at this time, or null. */
    private long[] find(Timestamp time) throws SQLException {
        if (find == null) {
            find = c.prepareStatement("SELECT file_id, row_no FROM cycle WHERE vehicle = ? AND segment = ? AND t = ?");
            find.setString(1, vehicle);
            find.setString(2, segment);
        }
        find.setTimestamp(3, time, utc);
        try (ResultSet rs = find.executeQuery()) {
            return rs.next() ? new long[] {rs.getLong(1), rs.getLong(2)} : null;
        }
    }

    /** This file's values into the stored cycle (file, row): replacing the values of sensors it has, adding the others. */
    private void merge(long file, long rowNo, Timestamp time, double[] row, int[] sensorIds) throws SQLException {
        flush(); // what this file wrote so far must be there to be merged into
        if (sensorsOf == null) {
            sensorsOf = c.prepareStatement("SELECT sensor_id FROM reading WHERE file_id = ? AND row_no = ?");
            update = c.prepareStatement("UPDATE reading SET value = ? WHERE file_id = ? AND row_no = ? AND sensor_id = ?");
        }
        Set<Integer> stored = new HashSet<>();
        sensorsOf.setLong(1, file);
        sensorsOf.setLong(2, rowNo);
        try (ResultSet rs = sensorsOf.executeQuery()) {
            while (rs.next()) {
                stored.add(rs.getInt(1));
            }
        }
        ins.setLong(1, file);
        ins.setLong(2, rowNo);
        ins.setTimestamp(5, time, utc);
        update.setLong(2, file);
        update.setLong(3, rowNo);
        boolean updates = false;
        for (int i = 0; i < row.length; i++) {
            if (Double.isNaN(row[i])) {
                continue;
            }
            if (stored.contains(sensorIds[i])) {
                update.setDouble(1, row[i]);
                update.setInt(4, sensorIds[i]);
                update.addBatch();
                updates = true;
                values++;
            } else {
                reading(sensorIds[i], row[i]);
            }
        }
        if (updates) {
            update.executeBatch();
        }
        fixes(file, rowNo, time, row, true);
    }

    private void flush() throws SQLException {
        if (pendingCycles > 0) {
            cyc.executeBatch();
            pendingCycles = 0;
        }
        if (pending > 0) {
            ins.executeBatch();
            pending = 0;
        }
        if (pendingFixes > 0) {
            fix.executeBatch();
            pendingFixes = 0;
        }
    }

    /** Writes what is still batched. */
    void finish() throws SQLException {
        flush();
    }

    /** Values stored or merged. */
    long values() {
        return values;
    }

    /** Position fixes stored or replaced. */
    long positions() {
        return positions;
    }

    /** Cycles that were stored already and were merged into. */
    long merged() {
        return merged;
    }

    @Override
    public void close() throws SQLException {
        for (PreparedStatement st : new PreparedStatement[] {ins, fix, cyc, find, sensorsOf, update, unfix}) {
            if (st != null) {
                st.close();
            }
        }
    }
}
