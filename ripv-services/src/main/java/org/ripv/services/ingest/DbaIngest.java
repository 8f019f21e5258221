package org.ripv.services.ingest;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.sql.Timestamp;
import java.sql.Types;
import java.time.Instant;
import java.util.Arrays;
import java.util.Calendar;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TimeZone;
import java.util.function.BooleanSupplier;

/**
 * Stores one Slocum file — DBA text or binary, read as {@link Cycles} — in the narrow schema of
 * {@code sql/slocumDB.sql}: a DATA_FILE row, the sensors it names in SENSOR_DEF, one CYCLE per
 * row, one READING per non-NaN value and one POSITION_FIX per row with a latitude and longitude
 * pair (GPS or dead-reckoned) — all in one transaction, in JDBC batches, streaming the rows
 * ({@link CycleWriter}). A file whose SHA-256 is stored already is not stored again; a cycle
 * stored already by another file of the same segment is merged into, not stored twice; a file
 * the reader refuses stores nothing.
 *
 * <p>Not thread-safe: one instance per connection, used by one thread.
 *
 * <p>Over 400 lines because one transaction's steps (the file row, its sensors, the latest
 * values, the merge of a cycle stored already) share its connection, batches and rollback; the
 * rows themselves are {@link CycleWriter}'s.
 */
public final class DbaIngest {
    /** Rows per JDBC batch. */
    static final int BATCH = 5_000;
    /** Per instance: JDBC drivers may set a Calendar's fields while they convert, so no two threads share one. */
    private final Calendar utc = Calendar.getInstance(TimeZone.getTimeZone("UTC"));

    /**
     * What one file gave.
     *
     * @param name       the name it was ingested under (the store's file name)
     * @param dbaName    the header's {@code filename} (e.g. {@code cp_388-2016-012-0-0}), or the name
     * @param fileId     DATA_FILE.FILE_ID (of the earlier copy when {@code duplicate})
     * @param duplicate  true when the same bytes were stored already (nothing was added)
     * @param positions  rows with a valid latitude/longitude pair (GPS or dead-reckoned)
     * @param untimed    rows with neither m_present_time nor sci_m_present_time (not stored)
     * @param merged     rows whose cycle (vehicle, segment, time) was stored already, by an earlier file
     *                   of the same segment (a {@code .sbd} before its {@code .dbd}) or earlier in this
     *                   one: their values went into that cycle instead of a new one
     * @param leftOut    what a file cut short of its end left out ({@link Cycles#leftOut()}), empty if nothing
     */
    public record Outcome(String name, String dbaName, String vehicle, long fileId, boolean duplicate, long rows,
                          int sensors, long values, long positions, long noFix, long impossible, long untimed, long merged,
                          String leftOut) {
        /** "cp_388-2016-012-0-0: 23 rows, 52 sensors, 296 values, 2 positions", and what else is worth saying. */
        public String describe() {
            if (duplicate) {
                return dbaName + ": stored already (file " + fileId + "), nothing added";
            }
            StringBuilder b = new StringBuilder(dbaName).append(": ").append(rows).append(" rows, ").append(sensors)
                    .append(" sensors, ").append(values).append(" values, ").append(positions).append(" positions");
            if (noFix > 0) {
                b.append(" (").append(noFix).append(" no-fix values left out)");
            }
            if (impossible > 0) {
                b.append(" (").append(impossible).append(" impossible positions left out)");
            }
            if (untimed > 0) {
                b.append(" (").append(untimed).append(" rows without a time left out)");
            }
            if (merged > 0) {
                b.append(" (").append(merged).append(" of the rows' cycles were stored already: their values were merged"
                        + " into them, not stored twice)");
            }
            if (!leftOut.isEmpty()) {
                b.append(" (").append(leftOut).append(')');
            }
            return b.toString();
        }
    }

    private final Connection c;
    private IngestLimits limits = IngestLimits.defaults();
    private BooleanSupplier cancelled = () -> false;

    public DbaIngest(Connection connection) {
        this.c = connection;
    }

    /** At most {@code limits.maxRows()} rows a file; {@code cancelled} is asked every {@link IngestLimits#CANCEL_EVERY} rows. */
    public DbaIngest limitedBy(IngestLimits limits, BooleanSupplier cancelled) {
        this.limits = limits;
        this.cancelled = cancelled;
        return this;
    }

    /** The SHA-256 of a file's bytes, as 64 hex digits. */
    public static String sha256(byte[] data) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(data));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }

    /** Opens a file's cycles; called only when the file is not stored already. */
    @FunctionalInterface
    public interface Opener {
        Cycles open() throws IOException, DbaFormatException, SlocumFormatException;
    }

    /**
     * Stores a DBA text file, or finds it stored already.
     *
     * @param name the file's name in the store (kept in DATA_FILE.NAME)
     * @param user who asked (DATA_FILE.INGESTED_BY)
     * @throws DbaFormatException when the file is not a good DBA file; nothing is stored
     * @throws SQLException       when the database fails; nothing is stored
     */
    public Outcome ingest(String name, byte[] data, String user) throws DbaFormatException, SQLException, IOException {
        try {
            return ingest(name, sha256(data), () -> new DbaReader(new ByteArrayInputStream(data)), user);
        } catch (SlocumFormatException e) {
            throw new IllegalStateException("a DBA reader threw a binary format error", e);
        }
    }

    /**
     * Stores a file's cycles (DBA text or binary: {@link Cycles}), or finds the same bytes stored
     * already. A cycle stored before — same vehicle, segment ({@code filename}) and time, from
     * another form of the same segment — is not stored again: this file's values go into it, its
     * own values replacing those stored, so the later, fuller file ({@code .dbd} after
     * {@code .sbd}) is what stays.
     *
     * @param sha  the SHA-256 of the file's bytes ({@link #sha256})
     * @throws DbaFormatException    when a DBA file is not good; nothing is stored
     * @throws SlocumFormatException when a binary file is not good (or its cache is missing); nothing is stored
     * @throws SQLException          when the database fails; nothing is stored
     */
    public Outcome ingest(String name, String sha, Opener opener, String user)
            throws DbaFormatException, SlocumFormatException, SQLException, IOException {
        Outcome earlier = stored(name, sha);
        if (earlier != null) {
            return earlier;
        }
        countRows(name, opener); // a file over the row limit is refused before a row is written: the refusal costs less
        boolean auto = c.getAutoCommit();
        c.setAutoCommit(false);
        try (Cycles r = opener.open()) {
            Outcome o = write(name, r, user, sha);
            c.commit();
            return o;
        } catch (SQLException e) {
            rollback();
            if (isUniqueViolation(e)) {
                Outcome again = stored(name, sha); // the same file, stored by someone else meanwhile
                if (again != null) {
                    return again;
                }
            }
            throw e;
        } catch (DbaFormatException | SlocumFormatException | IOException | RuntimeException e) {
            rollback();
            throw e;
        } finally {
            c.setAutoCommit(auto);
        }
    }

    /** Decodes the file once without writing, refusing it past the row limit or on a cancel. */
    private void countRows(String name, Opener opener) throws IOException, DbaFormatException, SlocumFormatException {
        try (Cycles r = opener.open()) {
            double[] row = new double[r.header().sensors().size()];
            while (r.next(row)) {
                if (r.rows() > limits.maxRows()) {
                    throw IngestStopped.overLimit(limits.tooManyRows(name));
                }
                if (r.rows() % IngestLimits.CANCEL_EVERY == 0 && cancelled.getAsBoolean()) {
                    throw IngestStopped.onCancel(name + ": cancelled after reading " + r.rows() + " rows; nothing of it stored");
                }
            }
        }
    }

    private void rollback() {
        try {
            c.rollback();
        } catch (SQLException ignored) {
            // the connection is going anyway; the caller reports the first failure
        }
    }

    private static boolean isUniqueViolation(SQLException e) {
        for (SQLException x = e; x != null; x = x.getNextException()) {
            if ("23505".equals(x.getSQLState())) {
                return true;
            }
        }
        return false;
    }

    private Outcome stored(String name, String sha) throws SQLException {
        try (PreparedStatement st = c.prepareStatement("SELECT file_id, dba_filename, vehicle, row_count, sensor_count,"
                + " value_count, position_count FROM data_file WHERE sha256 = ?")) {
            st.setString(1, sha);
            try (ResultSet rs = st.executeQuery()) {
                if (!rs.next()) {
                    return null;
                }
                String dba = rs.getString(2);
                return new Outcome(name, dba == null ? name : dba, rs.getString(3), rs.getLong(1), true, rs.getLong(4),
                        rs.getInt(5), rs.getLong(6), rs.getLong(7), 0, 0, 0, 0, "");
            }
        }
    }

    private Outcome write(String name, Cycles r, String user, String sha)
            throws DbaFormatException, SlocumFormatException, SQLException, IOException {
        DbaHeader h = r.header();
        String vehicle = h.vehicle() != null ? h.vehicle() : vehicleFromName(name);
        String dbaName = h.filename() != null && !h.filename().isBlank() ? h.filename() : name;
        int[] sensorIds = sensorIds(h.sensors());
        long fileId = insertFile(h, name, vehicle, sha, user);
        int depth = h.column("m_depth");
        double minDepth = Double.NaN;
        double maxDepth = Double.NaN;
        long depths = 0;
        double[] row = new double[h.sensors().size()];
        double[] lastT = new double[row.length];
        double[] lastV = new double[row.length];
        Arrays.fill(lastT, Double.NaN);
        long untimed = 0;
        double first = Double.NaN;
        double last = Double.NaN;
        try (CycleWriter w = new CycleWriter(c, utc, vehicle, cut(dbaName, 255), fileId, h)) {
            while (r.next(row)) {
                if (r.rows() > limits.maxRows()) {
                    throw IngestStopped.overLimit(limits.tooManyRows(name)); // rolled back: nothing of the file stays
                }
                if (r.rows() % IngestLimits.CANCEL_EVERY == 0 && cancelled.getAsBoolean()) {
                    throw IngestStopped.onCancel(name + ": cancelled after " + r.rows() + " rows; nothing of it stored");
                }
                double t = r.time(row);
                if (!Double.isFinite(t) || t < 0 || t > 32_503_680_000d) { // up to year 3000
                    untimed++;
                    continue;
                }
                first = Double.isNaN(first) ? t : Math.min(first, t);
                last = Double.isNaN(last) ? t : Math.max(last, t);
                if (depth >= 0 && !Double.isNaN(row[depth])) {
                    minDepth = depths == 0 ? row[depth] : Math.min(minDepth, row[depth]);
                    maxDepth = depths == 0 ? row[depth] : Math.max(maxDepth, row[depth]);
                    depths++;
                }
                for (int i = 0; i < row.length; i++) {
                    if (!Double.isNaN(row[i]) && !(lastT[i] > t)) {
                        lastT[i] = t;
                        lastV[i] = row[i];
                    }
                }
                w.cycle(r.rows(), t, row, sensorIds);
            }
            w.finish();
            latest(vehicle, fileId, sensorIds, lastT, lastV);
            try (PreparedStatement up = c.prepareStatement("UPDATE data_file SET row_count = ?, value_count = ?,"
                    + " position_count = ?, first_time = ?, last_time = ?, min_depth = ?, max_depth = ?, depth_count = ?"
                    + " WHERE file_id = ?")) {
                up.setLong(1, r.rows() - untimed);
                up.setLong(2, w.values());
                up.setLong(3, w.positions());
                up.setTimestamp(4, Double.isNaN(first) ? null : timestamp(first), utc);
                up.setTimestamp(5, Double.isNaN(last) ? null : timestamp(last), utc);
                if (depths == 0) {
                    up.setNull(6, Types.DOUBLE);
                    up.setNull(7, Types.DOUBLE);
                } else {
                    up.setDouble(6, minDepth);
                    up.setDouble(7, maxDepth);
                }
                up.setLong(8, depths);
                up.setLong(9, fileId);
                up.executeUpdate();
            }
            return new Outcome(name, dbaName, vehicle, fileId, false, r.rows() - untimed, h.sensors().size(), w.values(),
                    w.positions(), r.noFix(), r.impossible(), untimed, w.merged(), r.leftOut());
        }
    }

    /** Moves SENSOR_LATEST on for the sensors whose last value in this file is newer than the one kept. */
    private void latest(String vehicle, long fileId, int[] sensorIds, double[] lastT, double[] lastV) throws SQLException {
        Map<Integer, Timestamp> kept = new HashMap<>();
        try (PreparedStatement q = c.prepareStatement("SELECT sensor_id, t FROM sensor_latest WHERE vehicle = ?")) {
            q.setString(1, vehicle);
            try (ResultSet rs = q.executeQuery()) {
                while (rs.next()) {
                    kept.put(rs.getInt(1), rs.getTimestamp(2, utc));
                }
            }
        }
        try (PreparedStatement ins = c.prepareStatement(
                "INSERT INTO sensor_latest (vehicle, sensor_id, t, value, file_id) VALUES (?, ?, ?, ?, ?)");
             PreparedStatement up = c.prepareStatement(
                     "UPDATE sensor_latest SET t = ?, value = ?, file_id = ? WHERE vehicle = ? AND sensor_id = ?")) {
            for (int i = 0; i < sensorIds.length; i++) {
                if (Double.isNaN(lastT[i])) {
                    continue;
                }
                Timestamp t = timestamp(lastT[i]);
                Timestamp old = kept.get(sensorIds[i]);
                if (old == null) {
                    ins.setString(1, vehicle);
                    ins.setInt(2, sensorIds[i]);
                    ins.setTimestamp(3, t, utc);
                    ins.setDouble(4, lastV[i]);
                    ins.setLong(5, fileId);
                    ins.addBatch();
                } else if (!t.before(old)) {
                    up.setTimestamp(1, t, utc);
                    up.setDouble(2, lastV[i]);
                    up.setLong(3, fileId);
                    up.setString(4, vehicle);
                    up.setInt(5, sensorIds[i]);
                    up.addBatch();
                }
            }
            ins.executeBatch();
            up.executeBatch();
        }
    }

    /** Epoch seconds to a Timestamp, to the microsecond (what the glider's clock resolves, and no float noise). */
    static Timestamp timestamp(double epochSeconds) {
        long micros = Math.round(epochSeconds * 1e6);
        return Timestamp.from(Instant.ofEpochSecond(Math.floorDiv(micros, 1_000_000L), Math.floorMod(micros, 1_000_000L) * 1000));
    }

    /** A vehicle name from a store name when the header has none: what comes before the first '-', '_' + digit or '.'. */
    static String vehicleFromName(String name) {
        String v = name.replaceFirst("(?:-|_\\d|\\.).*$", "");
        v = v.isEmpty() ? name : v;
        return v.length() > 64 ? v.substring(0, 64) : v;
    }

    private long insertFile(DbaHeader h, String name, String vehicle, String sha, String user) throws SQLException {
        try (PreparedStatement st = c.prepareStatement("INSERT INTO data_file (vehicle, name, dba_filename, filename_extension,"
                + " mission_name, fileopen_time, sensors_per_cycle, sensor_count, row_count, value_count, position_count,"
                + " sha256, ingested, ingested_by) VALUES (?, ?, ?, ?, ?, ?, ?, ?, 0, 0, 0, ?, ?, ?)",
                Statement.RETURN_GENERATED_KEYS)) {
            st.setString(1, vehicle);
            st.setString(2, cut(name, 255));
            st.setString(3, cut(h.filename(), 255));
            st.setString(4, cut(h.tag("filename_extension"), 32));
            st.setString(5, cut(h.tag("mission_name"), 255));
            st.setString(6, cut(h.tag("fileopen_time"), 64));
            st.setInt(7, Integer.parseInt(h.tag("sensors_per_cycle").strip()));
            st.setInt(8, h.sensors().size());
            st.setString(9, sha);
            st.setTimestamp(10, Timestamp.from(Instant.now()), utc);
            st.setString(11, cut(user, 64));
            st.executeUpdate();
            try (ResultSet keys = st.getGeneratedKeys()) {
                if (keys.next()) {
                    return keys.getLong(1);
                }
            }
        }
        try (PreparedStatement st = c.prepareStatement("SELECT file_id FROM data_file WHERE sha256 = ?")) {
            st.setString(1, sha);
            try (ResultSet rs = st.executeQuery()) {
                rs.next();
                return rs.getLong(1);
            }
        }
    }

    static String cut(String s, int n) {
        return s == null || s.length() <= n ? s : s.substring(0, n);
    }

    /** The SENSOR_DEF ids of a file's sensors, adding the ones not seen before. */
    private int[] sensorIds(List<Sensor> sensors) throws SQLException {
        Map<String, Integer> known = new HashMap<>();
        try (Statement st = c.createStatement(); ResultSet rs = st.executeQuery("SELECT sensor_id, name, unit FROM sensor_def")) {
            while (rs.next()) {
                known.put(rs.getString(2) + "\u0000" + rs.getString(3), rs.getInt(1));
            }
        }
        int[] ids = new int[sensors.size()];
        try (PreparedStatement ins = c.prepareStatement("INSERT INTO sensor_def (name, unit) VALUES (?, ?)",
                Statement.RETURN_GENERATED_KEYS)) {
            for (Sensor s : sensors) {
                Integer id = known.get(s.name() + "\u0000" + s.unit());
                if (id == null) {
                    ins.setString(1, s.name());
                    ins.setString(2, s.unit());
                    ins.executeUpdate();
                    try (ResultSet keys = ins.getGeneratedKeys()) {
                        keys.next();
                        id = keys.getInt(1);
                    }
                    known.put(s.name() + "\u0000" + s.unit(), id);
                }
                ids[s.index()] = id;
            }
        }
        return ids;
    }
}
