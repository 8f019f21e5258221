package org.ripv.server.store;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.SQLTransientConnectionException;
import java.util.ArrayDeque;
import java.util.Properties;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A few JDBC connections to one database, each used by one transaction at a time. A connection
 * that failed is closed, and a transaction that failed because the connection broke is tried
 * once more on a fresh one (the server or the network came back, or a standby took over the
 * database's address).
 */
final class PgConnections implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(PgConnections.class);

    /** One transaction's work. */
    interface Work<T> {
        T run(Connection c) throws SQLException;
    }

    private final String url;
    private final Properties props;
    private final Semaphore slots;
    private final ArrayDeque<Connection> idle = new ArrayDeque<>();
    private volatile boolean closed;

    PgConnections(String url, Properties props, int max) {
        this.url = url;
        this.props = props;
        this.slots = new Semaphore(max, true);
    }

    /** The JDBC URL, secrets and all: never for messages as it stands. */
    String url() {
        return url;
    }

    /** A new connection of its own (the caller closes it). */
    Connection open() throws SQLException {
        return DriverManager.getConnection(url, props);
    }

    /** Runs {@code work} in one transaction: committed when it returns, rolled back when it throws. */
    <T> T transaction(Work<T> work) throws SQLException {
        try {
            if (!slots.tryAcquire(30, TimeUnit.SECONDS)) {
                throw new SQLTransientConnectionException("no free connection to the state database within 30 s");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new SQLTransientConnectionException("interrupted while waiting for a connection");
        }
        try {
            try {
                return attempt(work);
            } catch (SQLException e) {
                if (!broken(e) || closed) {
                    throw e;
                }
                log.warn("the state database connection failed ({}); trying once more on a new one", PostgresStateStore.reason(e));
                return attempt(work);
            }
        } finally {
            slots.release();
        }
    }

    private <T> T attempt(Work<T> work) throws SQLException {
        Connection c = take();
        boolean healthy = false;
        try {
            c.setAutoCommit(false);
            T result = work.run(c);
            c.commit();
            healthy = true;
            return result;
        } catch (AssertionError e) {
            // pgjdbc 42.7 throws this from a batch on a connection the server has closed
            throw new SQLException("the state database connection failed: " + e.getMessage(), "08006", e);
        } catch (SQLException | RuntimeException e) {
            try {
                c.rollback();
                healthy = !(e instanceof SQLException s) || !broken(s);
            } catch (SQLException ignored) {
                healthy = false;
            }
            throw e;
        } finally {
            give(c, healthy);
        }
    }

    /** A connection-class failure (SQLSTATE 08...), or a closed connection. */
    static boolean broken(SQLException e) {
        String state = e.getSQLState();
        return e instanceof SQLTransientConnectionException || state != null && (state.startsWith("08") || state.equals("57P01"));
    }

    /** An idle connection that still answers (the database may have restarted meanwhile), or a new one. */
    private Connection take() throws SQLException {
        while (true) {
            Connection c;
            synchronized (idle) {
                c = idle.pollFirst();
            }
            if (c == null) {
                return open();
            }
            if (c.isValid(2)) {
                return c;
            }
            try {
                c.close();
            } catch (SQLException ignored) {
                // already gone
            }
        }
    }

    private void give(Connection c, boolean healthy) {
        if (healthy && !closed) {
            synchronized (idle) {
                idle.addFirst(c);
            }
            return;
        }
        try {
            c.close();
        } catch (SQLException ignored) {
            // already broken
        }
    }

    @Override
    public void close() {
        closed = true;
        synchronized (idle) {
            for (Connection c : idle) {
                try {
                    c.close();
                } catch (SQLException ignored) {
                    // closing anyway
                }
            }
            idle.clear();
        }
    }
}
