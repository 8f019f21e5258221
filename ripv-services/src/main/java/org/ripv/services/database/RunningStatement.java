package org.ripv.services.database;

import java.sql.SQLException;
import java.sql.Statement;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * What runs on a DatabaseServer MailBox's thread now, so that another thread can stop it: a
 * statement (stopped by {@code Statement.cancel}, or, where the driver does not implement it —
 * embedded Derby — by an interrupt of the thread running it, which Derby answers by stopping the
 * statement), or an ingest (which looks at {@link #cancelRequested} between rows). The interrupt
 * is only ever sent while the statement runs.
 *
 * <p>It also keeps embedded Derby's query time limit. Derby's own ({@code setQueryTimeout})
 * schedules a timer task and cancels it on every {@code ResultSet.next()}: for a 100,000-row
 * query, 100,000 of each on one shared {@code java.util.Timer}, a tenth of the MailBox's CPU
 * (docs/performance.md, "The database"). Here one task is scheduled per stretch of the database's
 * own work, and none runs while the rows wait for their reader ({@link #pause}, {@link #resume}):
 * the limit counts the time the database works on the statement, as Derby's does.
 *
 * <p>A request's run is bracketed by {@link #begin} and {@link #end}: a cancel that comes after
 * the request started but before its statement did (the connection, the statement being made)
 * is kept, and the statement then never starts ({@link #start} throws).
 *
 * <p>Thread-safe: the MailBox's thread starts and ends a run, any thread may cancel it.
 */
final class RunningStatement {
    private static final Logger log = LoggerFactory.getLogger(RunningStatement.class);
    /** One thread for every handler's time limits: a task runs only when a statement overran. */
    private static final ScheduledThreadPoolExecutor LIMITS = new ScheduledThreadPoolExecutor(1, r -> {
        Thread t = new Thread(r, "ripv-database-time-limit");
        t.setDaemon(true);
        return t;
    });

    static {
        LIMITS.setRemoveOnCancelPolicy(true); // a query paused at each of its pages leaves no dead task queued
    }

    private final String handle;
    /** Guarded by {@code this}. */
    private Statement statement;
    private Thread thread;
    private boolean ingesting;
    /** Between {@link #begin} and {@link #end}: the request under way, though maybe with no statement yet; else null. */
    private Object underWay;
    /** A request cancelled after its MailBox started it but before it reached {@link #begin}. */
    private Object cancelledBeforeBegin;
    private ScheduledFuture<?> limit;
    /** What is left of the time limit, in nanoseconds; 0 when there is none (or the driver keeps it). */
    private long leftNanos;
    private long resumedAt;
    private volatile boolean cancelRequested;
    private volatile boolean timedOut;

    /** @param handle names the database in the log */
    RunningStatement(String handle) {
        this.handle = handle;
    }

    /**
     * A request starts on the MailBox's thread: from now on a cancel is kept even before a
     * statement runs; one that came for it before this call counts too.
     */
    synchronized void begin(Object request) {
        underWay = request;
        cancelRequested = cancelledBeforeBegin == request;
        cancelledBeforeBegin = null;
        timedOut = false;
    }

    /** The request ended. */
    synchronized void end() {
        underWay = null;
    }

    /**
     * A statement starts on the calling thread; {@code limitSeconds} (0: none) is kept here rather
     * than by the driver.
     *
     * @throws SQLException (state 57014, cancelled) when the request was cancelled before its statement started
     */
    synchronized void start(Statement st, int limitSeconds) throws SQLException {
        if (underWay == null) {
            cancelRequested = false; // a statement run outside a request has no earlier cancel
        } else if (cancelRequested) {
            throw new SQLException("cancelled before the statement started", "57014");
        }
        statement = st;
        thread = Thread.currentThread();
        timedOut = false;
        leftNanos = TimeUnit.SECONDS.toNanos(limitSeconds);
        resume();
    }

    /** The rows wait for their reader: that time does not count against the limit. */
    synchronized void pause() {
        if (limit != null) {
            limit.cancel(false);
            limit = null;
            leftNanos = Math.max(1, leftNanos - (System.nanoTime() - resumedAt));
        }
    }

    /** The database works on the statement again. */
    synchronized void resume() {
        if (leftNanos > 0 && statement != null) {
            resumedAt = System.nanoTime();
            limit = LIMITS.schedule(this::timeOut, leftNanos, TimeUnit.NANOSECONDS);
        }
    }

    /** The statement ended; a cancel's interrupt must not reach the MailBox's worker loop. */
    synchronized void finish() {
        if (limit != null) {
            limit.cancel(false);
            limit = null;
        }
        statement = null;
        thread = null;
        leftNanos = 0;
        Thread.interrupted();
    }

    /** An ingest starts (it has no one statement to cancel: it looks at {@link #cancelRequested} between rows). */
    synchronized void startIngest() {
        ingesting = true;
        if (underWay == null) {
            cancelRequested = false;
        } // else a cancel kept since begin() stops the ingest at its first look
    }

    synchronized void finishIngest() {
        ingesting = false;
    }

    /** Stops what runs now, or what a request under way is about to start; false when nothing does. */
    synchronized boolean cancel() {
        if (ingesting) {
            cancelRequested = true; // the ingest stops at its next look, rolling back the file under way
            return true;
        }
        if (statement == null) {
            if (underWay != null) {
                cancelRequested = true; // kept: the statement about to start never does
                return true;
            }
            return false;
        }
        cancelRequested = true;
        stop();
        return true;
    }

    /**
     * Stops {@code request}, which its MailBox runs now ({@code CommandHandler.cancel}): as
     * {@link #cancel()}, and kept for it when the MailBox started it but it has not reached
     * {@link #begin} yet.
     */
    synchronized boolean cancel(Object request) {
        if (cancel()) {
            return true;
        }
        cancelledBeforeBegin = request;
        return true;
    }

    private synchronized void timeOut() {
        if (statement != null && !cancelRequested) {
            timedOut = true;
            stop();
        }
    }

    private void stop() {
        try {
            statement.cancel();
        } catch (SQLException e) {
            log.debug("{}: Statement.cancel is not supported ({}); interrupting the query's thread", handle, e.getMessage());
            thread.interrupt();
        }
    }

    /** Whether someone cancelled what runs (or ran last). */
    boolean cancelRequested() {
        return cancelRequested;
    }

    /** Whether the time limit stopped the statement that runs (or ran last). */
    boolean timedOut() {
        return timedOut;
    }
}
