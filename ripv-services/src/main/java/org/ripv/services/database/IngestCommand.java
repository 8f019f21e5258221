package org.ripv.services.database;

import java.io.IOException;
import java.sql.Connection;
import java.sql.DatabaseMetaData;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.BooleanSupplier;
import org.ripv.dac.delivery.Deliveries;
import org.ripv.messages.Attachment;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Progress;
import org.ripv.messages.UpdateCount;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.ingest.DbaFormatException;
import org.ripv.services.ingest.DbaIngest;
import org.ripv.services.ingest.IngestLimits;
import org.ripv.services.ingest.IngestStopped;
import org.ripv.services.ingest.MissingSensorListException;
import org.ripv.services.ingest.SlocumFormatException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code ingest NAME...}: stores Slocum DBA files from the server's download directory, which the
 * server attaches as one bundle ({@link DatabaseServer#downloadPrefixes()}). Each file is its own
 * transaction: a refused file stores nothing and the others still go in; the reply has one line
 * per file and is an ERROR when any file was refused. The tables and views of
 * {@code sql/slocumDB.sql} are created on first use.
 */
final class IngestCommand {
    private static final Logger log = LoggerFactory.getLogger(IngestCommand.class);
    /** The command word. */
    static final String WORD = "ingest";
    static final String SCRIPT = "slocumDB.sql";
    /** Tables and views of the script, for the reader's GRANT. */
    static final List<String> OBJECTS = List.of("DATA_FILE", "SENSOR_DEF", "READING", "SENSOR_LATEST", "POSITION_FIX",
            "CYCLE", "POSITIONS", "LATEST", "DEPTHS", "DIVES");
    /** The objects an older database (without CYCLE) gets from {@link #addCycles}. */
    static final List<String> CYCLE_OBJECTS = List.of("CYCLE", "DIVES");
    /**
     * How an older database's cycles come into CYCLE: each (vehicle, segment, time) stored, under
     * the first file and row that has it.
     */
    private static final String CYCLE_BACKFILL = "INSERT INTO cycle (vehicle, segment, t, file_id, row_no)"
            + " SELECT r.vehicle, COALESCE(d.dba_filename, d.name), r.t, MIN(r.file_id), MIN(r.row_no)"
            + " FROM reading r JOIN data_file d ON d.file_id = r.file_id"
            + " GROUP BY r.vehicle, COALESCE(d.dba_filename, d.name), r.t";
    /** The objects an older database (without POSITION_FIX) gets from {@link #addPositionFixes}. */
    static final List<String> POSITION_OBJECTS = List.of("POSITION_FIX", "POSITIONS");
    /**
     * How an older database's fixes come into POSITION_FIX: its positions view's join of a
     * latitude and a longitude of the same row, with the row number.
     */
    private static final String BACKFILL = "INSERT INTO position_fix (vehicle, t, lat, lon, source, file_id, row_no)"
            + " SELECT la.vehicle, la.t, la.value, lo.value, CAST('%s' AS VARCHAR(16)), la.file_id, la.row_no"
            + " FROM sensor_def sa JOIN reading la ON la.sensor_id = sa.sensor_id"
            + " JOIN sensor_def so ON so.name = '%s'"
            + " JOIN reading lo ON lo.file_id = la.file_id AND lo.row_no = la.row_no AND lo.sensor_id = so.sensor_id"
            + " WHERE sa.name = '%s' AND la.value BETWEEN -90 AND 90 AND lo.value BETWEEN -180 AND 180";
    static final int MAX_FILES = 1000;

    private final DatabaseTarget target;
    private final SlocumArrivals slocum;
    private final IngestNotices notices;
    private boolean schemaChecked;
    /** The DAC deployments each stored Slocum binary file goes to (issue 37 item 4). */
    private volatile Deliveries deliveries = Deliveries.NONE;
    /** The files waiting for a sensor-list cache, as {@code ?status} shows them; empty when none. */
    private volatile String waiting = "";

    IngestCommand(DatabaseTarget target) {
        this(target, IngestNotices.NONE);
    }

    IngestCommand(DatabaseTarget target, IngestNotices notices) {
        this.target = target;
        this.slocum = SlocumArrivals.of(target);
        this.notices = notices;
        refreshWaiting();
    }

    /**
     * What {@code ?status} adds: "waiting for sensor lists: 6b016a2e.cac: a.sbd b.sbd", or empty.
     * Kept on disk, so files kept before a restart are still reported after it.
     */
    String waiting() {
        return waiting;
    }

    private void refreshWaiting() {
        try {
            List<String> w = slocum.waitingFor();
            waiting = w.isEmpty() ? "" : "waiting for sensor lists: " + String.join("; ", w);
        } catch (IOException e) {
            waiting = "cannot list the files waiting for sensor lists: " + e.getMessage();
        }
    }

    void deliverTo(Deliveries deliveries) {
        this.deliveries = deliveries;
    }

    /** True when a command line is {@code ingest ...}. */
    static boolean matches(String command) {
        String c = command == null ? "" : command.strip();
        return c.regionMatches(true, 0, WORD, 0, WORD.length()) && (c.length() == WORD.length()
                || Character.isWhitespace(c.charAt(WORD.length())));
    }

    Reply run(Request request, Connection c) {
        return run(request, c, IngestLimits.defaults(), () -> false);
    }

    /** As above, each file within {@code limits}, stopping when {@code cancelled} says so ({@code ?cancel}). */
    Reply run(Request request, Connection c, IngestLimits limits, BooleanSupplier cancelled) {
        List<String> names = request.arguments();
        if (names.isEmpty()) {
            return Reply.error(ErrorCode.BAD_REQUEST, "usage: ingest NAME... (Slocum DBA files in the server's download"
                    + " directory; ?dlfiles lists them)");
        }
        Optional<Attachment> attached = request.attachment();
        if (attached.isEmpty()) {
            return Reply.error(ErrorCode.BAD_REQUEST, "ingest found no files attached: the server attaches the named"
                    + " download-directory files (is this DatabaseServer registered with a server?)");
        }
        List<Attachment> files;
        try {
            files = attached.get().files(MAX_FILES);
        } catch (IOException e) {
            return Reply.error(ErrorCode.BAD_REQUEST, "the attached files are not a readable bundle: " + e.getMessage());
        }
        try {
            ensureSchema(c);
        } catch (SQLException | IOException e) {
            return Reply.error(ErrorCode.DATABASE_ERROR, "cannot create the Slocum tables of " + SCRIPT + ": "
                    + (e instanceof SQLException s ? DatabaseHandler.describe(s) : e.getMessage()));
        }
        List<String> lines = new ArrayList<>();
        int refused = 0;
        long values = 0;
        DbaIngest ingest = new DbaIngest(c).limitedBy(limits, cancelled);
        slocum.limit(limits.maxPlainBytes());
        // Cache files first: a bundle of ymodem:get *.sbd *.cac decodes whatever its order.
        List<Attachment> ordered = new ArrayList<>(files.stream().filter(f -> SlocumArrivals.isCache(f.name())).toList());
        files.stream().filter(f -> !SlocumArrivals.isCache(f.name())).forEach(ordered::add);
        for (int i = 0; i < ordered.size(); i++) {
            Attachment f = ordered.get(i);
            long t0 = System.nanoTime();
            try {
                if (SlocumArrivals.isCache(f.name())) {
                    String crc = slocum.acceptCache(f);
                    lines.add(f.name() + ": sensor list " + crc + " kept in the cache");
                    for (Attachment w : slocum.released(crc)) {
                        String line = w.name() + " (waited for " + crc + ".cac): ";
                        try {
                            line += store(ingest, w, request.user()).describe();
                            notices.released(w.name(), crc, line, request.user());
                        } catch (DbaFormatException | SlocumFormatException | SQLException e) {
                            refused++;
                            line += "refused, nothing stored: " + (e instanceof SQLException s ? DatabaseHandler.describe(s)
                                    : e.getMessage());
                            notices.released(w.name(), crc, line, request.user());
                        }
                        lines.add(line);
                    }
                    continue;
                }
                DbaIngest.Outcome o = store(ingest, f, request.user());
                lines.add(o.describe());
                if (o.duplicate()) {
                    notices.repeated(f.name() + ": " + o.describe(), request.user());
                }
                values += o.duplicate() ? 0 : o.values();
                log.info("{} ingest {} for {}: {} in {} ms", target.handle(), f.name(), request.user(), o.describe(),
                        (System.nanoTime() - t0) / 1_000_000);
            } catch (MissingSensorListException e) {
                lines.add(f.name() + ": kept, waiting for the sensor list " + e.crc() + ".cac (ymodem:get " + e.crc()
                        + ".cac, or upload it and ingest it); it is ingested by itself when that arrives");
                notices.waiting(f.name(), e.crc(), request.user());
                log.info("{} ingest {} for {}: waits for {}.cac", target.handle(), f.name(), request.user(), e.crc());
            } catch (IngestStopped e) {
                if (e.cancelled()) {
                    lines.add(e.getMessage());
                    log.info("{} ingest of {} for {} cancelled", target.handle(), f.name(), request.user());
                    refreshWaiting();
                    return Reply.error(ErrorCode.CANCELLED, String.join("\n", lines) + "\ningest cancelled: the files above it"
                            + " were stored, the rest were not");
                }
                refused++;
                lines.add(f.name() + ": refused, nothing stored: " + e.getMessage());
                log.info("{} ingest {} for {} refused: {}", target.handle(), f.name(), request.user(), e.getMessage());
            } catch (DbaFormatException | SlocumFormatException | IllegalArgumentException e) {
                refused++;
                lines.add(f.name() + ": refused, nothing stored: " + e.getMessage());
                notices.refused(lines.get(lines.size() - 1), request.user());
                log.info("{} ingest {} for {} refused: {}", target.handle(), f.name(), request.user(), e.getMessage());
            } catch (SQLException e) {
                refused++;
                lines.add(f.name() + ": the database failed, nothing stored: " + DatabaseHandler.describe(e));
                notices.refused(lines.get(lines.size() - 1), request.user());
                log.warn("{} ingest {} failed: {}", target.handle(), f.name(), DatabaseHandler.describe(e));
            } catch (IOException | RuntimeException e) {
                refused++;
                lines.add(f.name() + ": could not be read, nothing stored: " + e);
                notices.refused(lines.get(lines.size() - 1), request.user());
                log.warn("{} ingest {} failed", target.handle(), f.name(), e);
            }
            if (ordered.size() > 1) {
                request.progress(lines.get(lines.size() - 1), new Progress("files ingested", i + 1, ordered.size(), 0));
            }
        }
        refreshWaiting();
        String text = String.join("\n", lines);
        if (refused > 0) {
            return Reply.error(ErrorCode.BAD_REQUEST, text);
        }
        return Reply.ok(text, new UpdateCount((int) Math.min(Integer.MAX_VALUE, values)));
    }

    /** Stores a DBA file, or a Slocum binary file's cycles as they are decoded (no DBA text in between). */
    private DbaIngest.Outcome store(DbaIngest ingest, Attachment f, String user)
            throws IOException, SQLException, DbaFormatException, SlocumFormatException {
        if (SlocumArrivals.isBinary(f)) {
            DbaIngest.Outcome o = ingest.ingest(f.name(), DbaIngest.sha256(f.data()), () -> slocum.open(f), user);
            try {
                deliveries.arrived(f.name(), f.data(), slocum.cache());
            } catch (RuntimeException e) {
                // the DAC delivery is a consumer of what was stored: it never changes the ingest's verdict
                log.warn("{}: the DAC delivery did not take {}: {}", target.handle(), f.name(), e.toString());
            }
            return o;
        }
        return ingest.ingest(f.name(), f.data(), user);
    }

    /**
     * Creates the tables and views of {@value #SCRIPT} unless DATA_FILE exists, and lets the reader
     * see them; a database made before POSITION_FIX existed gets it ({@link #addPositionFixes}).
     */
    void ensureSchema(Connection c) throws SQLException, IOException {
        if (schemaChecked && !c.isClosed()) {
            return;
        }
        if (!exists(c, "DATA_FILE")) {
            inTransaction(c, () -> SqlScript.run(c, SqlScript.resource(SCRIPT), SCRIPT));
            log.info("{}: created the Slocum tables and views of {}", target.handle(), SCRIPT);
            grantReader(c, OBJECTS);
        } else {
            if (!exists(c, "POSITION_FIX")) {
                long fixes = inTransaction(c, () -> addPositionFixes(c));
                log.info("{}: added POSITION_FIX to the Slocum tables, with the {} fixes stored before", target.handle(), fixes);
                grantReader(c, POSITION_OBJECTS);
            }
            if (!exists(c, "CYCLE")) {
                long cycles = inTransaction(c, () -> addCycles(c));
                log.info("{}: added CYCLE to the Slocum tables, with the {} cycles stored before", target.handle(), cycles);
                grantReader(c, CYCLE_OBJECTS);
            }
        }
        schemaChecked = true;
    }

    /**
     * Brings a database made by an earlier RIPV, whose positions view joined READING with itself,
     * to today's {@value #SCRIPT}: POSITION_FIX, its index and the positions view are made by the
     * script's own statements, and the fixes already stored are copied in.
     *
     * @return the fixes copied
     */
    static long addPositionFixes(Connection c) throws SQLException, IOException {
        long copied = 0;
        try (Statement st = c.createStatement()) {
            st.execute("DROP VIEW positions");
            for (String sql : SqlScript.split(SqlScript.resource(SCRIPT))) {
                if (sql.matches("(?is)CREATE\\s+(TABLE|INDEX|VIEW)\\s+(position_fix|positions|position_fix_\\w+)\\b.*")) {
                    st.execute(sql);
                }
            }
            copied += st.executeUpdate(String.format(BACKFILL, "gps", "m_gps_lon", "m_gps_lat"));
            copied += st.executeUpdate(String.format(BACKFILL, "dead-reckoned", "m_lon", "m_lat"));
        }
        return copied;
    }

    /**
     * Brings a database made before CYCLE existed to today's {@value #SCRIPT}: CYCLE and the dives
     * view (one row a segment) by the script's own statements, and the cycles already stored
     * entered under the first file that has each.
     *
     * @return the cycles entered
     */
    static long addCycles(Connection c) throws SQLException, IOException {
        try (Statement st = c.createStatement()) {
            st.execute("DROP VIEW dives");
            for (String sql : SqlScript.split(SqlScript.resource(SCRIPT))) {
                if (sql.matches("(?is)CREATE\\s+(TABLE|VIEW)\\s+(cycle|dives)\\b.*")) {
                    st.execute(sql);
                }
            }
            return st.executeUpdate(CYCLE_BACKFILL);
        }
    }

    private interface Work<T> {
        T run() throws SQLException, IOException;
    }

    private static <T> T inTransaction(Connection c, Work<T> work) throws SQLException, IOException {
        boolean auto = c.getAutoCommit();
        c.setAutoCommit(false);
        try {
            T result = work.run();
            c.commit();
            return result;
        } catch (SQLException | IOException | RuntimeException e) {
            c.rollback();
            throw e;
        } finally {
            c.setAutoCommit(auto);
        }
    }

    private void grantReader(Connection c, List<String> objects) {
        if (target.readerUser() == null) {
            return;
        }
        try (Statement st = c.createStatement()) {
            for (String o : objects) {
                st.execute("GRANT SELECT ON " + o + " TO " + target.readerUser());
            }
        } catch (SQLException e) {
            log.warn("{}: could not let {} read the Slocum tables: {}", target.handle(), target.readerUser(),
                    DatabaseHandler.describe(e));
        }
    }

    private static boolean exists(Connection c, String table) throws SQLException {
        DatabaseMetaData md = c.getMetaData();
        String schema = c.getSchema();
        for (String name : new String[] {table, table.toLowerCase(Locale.ROOT)}) {
            try (ResultSet rs = md.getTables(null, schema, name, new String[] {"TABLE"})) {
                if (rs.next()) {
                    return true;
                }
            }
        }
        return false;
    }
}
