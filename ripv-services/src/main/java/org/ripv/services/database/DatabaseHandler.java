package org.ripv.services.database;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.SQLTimeoutException;
import java.sql.Statement;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import org.ripv.dac.delivery.Deliveries;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.TableResult;
import org.ripv.messages.UpdateCount;
import org.ripv.service.Availability;
import org.ripv.service.CommandHandler;
import org.ripv.service.Reply;
import org.ripv.service.Request;
import org.ripv.services.ingest.IngestLimits;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Runs the SQL commands of one DatabaseServer MailBox against one database (thesis 4.1.4.2).
 *
 * <p>A query answers OK with a {@link TableResult} (column names, SQL type names, rows as text
 * with null for SQL NULL, truncated when cut at {@link QueryLimits#maxRows()} or at the result's
 * size limit); any other statement answers OK with an {@link UpdateCount}; a statement the
 * database rejects answers ERROR {@link ErrorCode#DATABASE_ERROR} with the database's message
 * and SQLState, {@link ErrorCode#FORBIDDEN} when it is a permission or read-only refusal, and
 * {@link ErrorCode#TIMEOUT} when the query timeout cancelled it. The handler keeps serving after
 * all of them.
 *
 * <p>Only users whose permit-file roles include {@value #WRITER_ROLE} or {@value #OPERATORS_ROLE}
 * (and not {@value #READER_ROLE}) run their commands on the owner connection; everyone else,
 * observers included, on the reader connection (a database user that can only read). Session
 * state a statement changes ({@code SET SCHEMA}, isolation, an open transaction) is reset before
 * the next command, so it never carries over to another user of the shared connection.
 *
 * <p>A query's rows leave in pages ({@link ResultPages}); what runs now, its cancel and its time
 * limit are {@link RunningStatement}'s.
 *
 * <p>Threading: {@link #execute} runs on the MailBox's one worker thread, so the connections
 * need no locking; {@link #availability} reads a volatile snapshot from any thread.
 */
public final class DatabaseHandler implements CommandHandler, AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(DatabaseHandler.class);

    /** The permit-file role that sends a user's SQL to the read-only database user. */
    public static final String READER_ROLE = "db-reader";
    /** A permit-file role that may change the database (besides {@value #OPERATORS_ROLE}). */
    public static final String WRITER_ROLE = "db-writer";
    /** The operators' role: they command vehicles and may change the database. */
    public static final String OPERATORS_ROLE = "operators";
    private final DatabaseTarget target;
    private final QueryLimits limits;
    private final IngestCommand ingest;
    private final SessionConnections connections;
    private volatile Availability availability;
    private final RunningStatement running;
    private IngestLimits ingestLimits = IngestLimits.defaults();
    private Deliveries deliveries = Deliveries.NONE;

    public DatabaseHandler(DatabaseTarget target, QueryLimits limits) {
        this(target, limits, IngestNotices.NONE);
    }

    /** As above, telling {@code notices} of files that wait for a sensor-list cache. */
    DatabaseHandler(DatabaseTarget target, QueryLimits limits, IngestNotices notices) {
        this.target = target;
        this.limits = limits;
        this.ingest = new IngestCommand(target, notices);
        this.running = new RunningStatement(target.handle());
        this.connections = new SessionConnections(target);
        this.availability = Availability.available(describe());
    }

    /** Sets how much one ingested file may hold ({@code --ingest-max-bytes}, {@code --ingest-max-rows}). */
    public DatabaseHandler withIngestLimits(IngestLimits limits) {
        this.ingestLimits = Objects.requireNonNull(limits, "limits");
        return this;
    }

    /** Hands every Slocum file ingested here to the DAC deployments, and answers {@code dac:status} from them. */
    DatabaseHandler withDeliveries(Deliveries deliveries) {
        this.deliveries = Objects.requireNonNull(deliveries, "deliveries");
        ingest.deliverTo(deliveries);
        return this;
    }

    /** Loads the driver and opens the owner connection now, so a bad URL shows at start. */
    public void connect() throws SQLException {
        connection(false);
    }

    @Override
    public Reply execute(Request request) {
        running.begin(request); // a cancel from here on stops the request, even before its statement starts
        try {
            return executeNow(request);
        } finally {
            running.end();
        }
    }

    private Reply executeNow(Request request) {
        if (IngestCommand.matches(request.command())) {
            return ingest(request);
        }
        if (Deliveries.matches(request.command())) {
            try {
                return Reply.ok(deliveries.status(request.arguments()));
            } catch (IllegalArgumentException e) {
                return Reply.error(ErrorCode.BAD_REQUEST, e.getMessage());
            }
        }
        if (ViewQuery.appliesTo(request.roles())) {
            // a view user: one SELECT from one view, read-only, under a short time limit (issue 33 item 6)
            String refused = ViewQuery.refusal(request.command() == null ? "" : request.command());
            if (refused != null) {
                return Reply.error(ErrorCode.FORBIDDEN, refused);
            }
            int limit = limits.queryTimeoutSeconds() == 0 ? ViewQuery.TIMEOUT_SECONDS
                    : Math.min(limits.queryTimeoutSeconds(), ViewQuery.TIMEOUT_SECONDS);
            return run(request.command(), true, limit, request);
        }
        return run(request.command(), readsOnly(request.roles()), limits.queryTimeoutSeconds(), request);
    }

    /** True unless the roles let the user change the database: observers and unknown roles only read. */
    public static boolean readsOnly(List<String> roles) {
        return roles.contains(READER_ROLE) || !(roles.contains(WRITER_ROLE) || roles.contains(OPERATORS_ROLE));
    }

    /** {@code ingest NAME...} on the owner connection ({@link IngestCommand}). */
    private Reply ingest(Request request) {
        if (readsOnly(request.roles())) {
            return Reply.error(ErrorCode.FORBIDDEN, "you may only read this database; ingest writes to it");
        }
        running.startIngest();
        try {
            return ingest.run(request, connection(false), ingestLimits, running::cancelRequested);
        } catch (SQLException e) {
            return Reply.error(ErrorCode.NOT_AVAILABLE, "cannot connect to " + target.safeUrl() + ": " + describe(e));
        } finally {
            running.finishIngest();
        }
    }

    /** Runs one SQL command as the owner, or as the reader; a query's whole table comes in the reply. */
    public Reply run(String command, boolean asReader) {
        return run(command, asReader, limits.queryTimeoutSeconds(), null);
    }

    /** As above, cancelled after {@code timeoutSeconds} (0: no limit). */
    Reply run(String command, boolean asReader, int timeoutSeconds) {
        return run(command, asReader, timeoutSeconds, null);
    }

    /** As above; with {@code pages}, a query's rows go to its reader in pages ({@link Request#page}). */
    private Reply run(String command, boolean asReader, int timeoutSeconds, Request pages) {
        List<String> statements;
        try {
            statements = SqlScript.split(command == null ? "" : command);
        } catch (IllegalArgumentException e) {
            return Reply.error(ErrorCode.BAD_REQUEST, "not one SQL statement: " + e.getMessage());
        }
        if (statements.isEmpty()) {
            return Reply.error(ErrorCode.BAD_REQUEST, "the DatabaseServer takes one SQL statement, e.g. SELECT * FROM mission");
        }
        if (statements.size() > 1) {
            return Reply.error(ErrorCode.BAD_REQUEST, "one SQL statement per command, got " + statements.size()
                    + " separated by ';'");
        }
        String sql = statements.get(0);
        if (asReader && !target.hasReader()) {
            return Reply.error(ErrorCode.FORBIDDEN, "you may only read this database, and " + target.safeUrl()
                    + " has no read-only database user configured (the service's --reader-user); ask the operator");
        }
        long started = System.nanoTime();
        Connection c;
        try {
            c = connection(asReader);
        } catch (SQLException e) {
            return Reply.error(ErrorCode.NOT_AVAILABLE, "cannot connect to " + target.safeUrl() + ": " + describe(e));
        }
        try (Statement st = c.createStatement(ResultSet.TYPE_FORWARD_ONLY, ResultSet.CONCUR_READ_ONLY)) {
            // Embedded Derby's own limit costs a timer task per row read; RunningStatement keeps it instead.
            boolean ownLimit = target.embeddedDerby();
            running.start(st, ownLimit ? timeoutSeconds : 0);
            // One row more than we keep tells us the result was cut.
            st.setMaxRows(limits.maxRows() + 1);
            st.setFetchSize(Math.min(limits.maxRows() + 1, 1000));
            st.setQueryTimeout(ownLimit ? 0 : timeoutSeconds);
            if (st.execute(sql)) {
                try (ResultSet rs = st.getResultSet()) {
                    ResultPages out = new ResultPages(pages, limits, running);
                    TableResult table = out.read(sql, rs);
                    long ms = (System.nanoTime() - started) / 1_000_000;
                    int total = out.sent() + table.rows().size();
                    log.debug("{} {}: {} rows{} in {} pages, {} ms", target.handle(), SqlScript.abbreviate(sql), total,
                            table.truncated() ? " (truncated)" : "", out.pages() + 1, ms);
                    return Reply.ok(summary(total, table.truncated(), ms), table);
                }
            }
            int count = st.getUpdateCount();
            long ms = (System.nanoTime() - started) / 1_000_000;
            return Reply.ok((count == 1 ? "1 row" : Math.max(count, 0) + " rows") + " changed in " + ms + " ms",
                    new UpdateCount(Math.max(count, 0)));
        } catch (SQLException e) {
            if (running.timedOut()) {
                closeAfterInterrupt(e);
                log.info("{}: '{}' stopped at the query timeout: {}", target.handle(), SqlScript.abbreviate(sql), describe(e));
                return Reply.error(ErrorCode.TIMEOUT, "the statement ran longer than the query timeout of " + timeoutSeconds
                        + " s and was stopped: " + describe(e));
            }
            if (running.cancelRequested()) {
                log.info("{}: '{}' cancelled: {}", target.handle(), SqlScript.abbreviate(sql), describe(e));
                closeAfterInterrupt(e);
                return Reply.error(ErrorCode.CANCELLED, "the statement was cancelled: " + describe(e));
            }
            return failure(sql, e);
        } catch (Request.PagesStopped e) {
            log.info("{}: '{}' stopped while sending its rows: {}", target.handle(), SqlScript.abbreviate(sql), e.getMessage());
            return e.cancelled() ? Reply.error(ErrorCode.CANCELLED, "the statement was cancelled while its rows were sent")
                    : Reply.error(ErrorCode.TIMEOUT, e.getMessage() + "; the statement was stopped");
        } catch (InterruptedException e) {
            // a cancel's interrupt while the query waited for its reader (embedded Derby has no Statement.cancel)
            if (running.timedOut()) {
                return Reply.error(ErrorCode.TIMEOUT, "the statement ran longer than the query timeout of " + timeoutSeconds
                        + " s and was stopped while its rows were sent");
            }
            log.info("{}: '{}' cancelled while sending its rows", target.handle(), SqlScript.abbreviate(sql));
            return Reply.error(ErrorCode.CANCELLED, "the statement was cancelled while its rows were sent");
        } finally {
            running.finish();
        }
    }

    /** An interrupt may have cost the connection: the next command then reconnects. */
    private void closeAfterInterrupt(SQLException e) {
        if (e.getSQLState() != null && e.getSQLState().startsWith("08")) {
            closeConnections();
        }
    }

    /** Cancels the running statement or ingest ({@link RunningStatement#cancel}). */
    @Override
    public boolean cancel(Request running) {
        return this.running.cancel(running);
    }

    private String summary(int n, boolean truncated, long ms) {
        String rows = n == 1 ? "1 row" : n + " rows";
        if (!truncated) {
            return rows + " in " + ms + " ms";
        }
        if (n == limits.maxRows()) {
            return "first " + rows + " (truncated: the service returns at most " + limits.maxRows()
                    + " rows; narrow the query, e.g. with WHERE or FETCH FIRST n ROWS ONLY) in " + ms + " ms";
        }
        return "first " + rows + " (truncated: the service returns at most " + limits.maxResultChars()
                + " characters of one result; narrow the query) in " + ms + " ms";
    }

    private Reply failure(String sql, SQLException e) {
        String state = e.getSQLState() == null ? "" : e.getSQLState();
        String text = describe(e);
        if (state.startsWith("08")) {
            // The connection is gone (server restarted, network down): reconnect on the next command.
            log.warn("{}: lost the connection to {}: {}", target.handle(), target.safeUrl(), text);
            closeConnections();
            availability = Availability.notAvailable("lost the connection to " + target.safeUrl() + ": " + text);
            return Reply.error(ErrorCode.NOT_AVAILABLE, "lost the connection to the database (" + text
                    + "); the next command reconnects");
        }
        log.debug("{}: '{}' failed: {}", target.handle(), SqlScript.abbreviate(sql), text);
        if (e instanceof SQLTimeoutException || state.equals("XCL52") || state.equals("57014")) {
            return Reply.error(ErrorCode.TIMEOUT, "the statement ran longer than the query timeout of "
                    + limits.queryTimeoutSeconds() + " s and was cancelled: " + text);
        }
        if (state.startsWith("4250") || state.equals("25502") || state.equals("25503") || state.equals("25505")
                || state.equals("25006")) {
            return Reply.error(ErrorCode.FORBIDDEN, "the database refused: " + text);
        }
        return Reply.error(ErrorCode.DATABASE_ERROR, text);
    }

    /** The database's message and SQLState, with any chained exceptions' messages. */
    static String describe(SQLException e) {
        StringBuilder b = new StringBuilder();
        String last = null;
        for (SQLException x = e; x != null; x = x.getNextException()) {
            String m = x.getMessage() == null ? x.toString() : x.getMessage().strip();
            if (m.equals(last)) {
                continue;
            }
            if (b.length() > 0) {
                b.append("; ");
            }
            b.append(m);
            if (x.getSQLState() != null) {
                b.append(" (SQLState ").append(x.getSQLState()).append(')');
            }
            last = m;
            if (b.length() > 2000) {
                break;
            }
        }
        return b.toString();
    }

    /** The owner's or the reader's connection, reset for this command; the availability follows whether it could be had. */
    private Connection connection(boolean asReader) throws SQLException {
        try {
            Connection c = connections.get(asReader);
            availability = Availability.available(describe());
            return c;
        } catch (SQLException e) {
            availability = Availability.notAvailable("cannot connect to " + target.safeUrl() + ": " + describe(e));
            throw e;
        }
    }

    private String describe() {
        String product = target.url().startsWith("jdbc:derby:") ? (target.embeddedDerby() ? "embedded Derby" : "Derby network")
                : target.url().split(":")[1].toLowerCase(Locale.ROOT);
        return product + " " + target.safeUrl();
    }

    @Override
    public Availability availability() {
        Availability a = availability;
        String waiting = ingest.waiting();
        return waiting.isEmpty() ? a : new Availability(a.available(), a.detail() + "; " + waiting, a.running());
    }

    public DatabaseTarget target() {
        return target;
    }

    private void closeConnections() {
        connections.close();
    }

    /** Closes the connections, and shuts an embedded Derby database down so its files are released. */
    @Override
    public void close() {
        closeConnections();
        availability = Availability.notAvailable("closed");
        if (target.embeddedDerby() && target.user() != null) {
            EmbeddedDatabase.shutdownQuietly(target.url(), target.user(), target.password());
        }
    }
}
