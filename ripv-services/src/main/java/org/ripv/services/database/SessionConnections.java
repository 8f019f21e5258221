package org.ripv.services.database;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.util.Properties;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A DatabaseHandler's two connections to its database: the owner's, and the reader's (a database
 * user that can only read). Each is opened on first use and reopened after it was lost, and put
 * back as it was opened before every command, so that session state one user's statement changed
 * never carries over to the next user of the shared connection.
 *
 * <p>Used by the MailBox's one worker thread only; not thread-safe.
 */
final class SessionConnections {
    private static final Logger log = LoggerFactory.getLogger(SessionConnections.class);

    private final DatabaseTarget target;
    private Connection owner;
    private Connection reader;
    private Defaults ownerDefaults;
    private Defaults readerDefaults;

    /** A connection's session state as opened, to which it is reset before each command. */
    private record Defaults(String schema, int isolation) {}

    SessionConnections(DatabaseTarget target) {
        this.target = target;
    }

    /** The reader's or the owner's connection, reset, or opened when there is none (or it was closed). */
    Connection get(boolean asReader) throws SQLException {
        Connection c = asReader ? reader : owner;
        if (c != null && !c.isClosed()) {
            reset(c, asReader ? readerDefaults : ownerDefaults);
            return c;
        }
        c = open(asReader);
        if (asReader) {
            reader = c;
            readerDefaults = defaults(c);
        } else {
            owner = c;
            ownerDefaults = defaults(c);
        }
        return c;
    }

    private Connection open(boolean asReader) throws SQLException {
        if (target.driver() != null && !target.driver().isBlank()) {
            try {
                Class.forName(target.driver());
            } catch (ClassNotFoundException e) {
                throw new SQLException("JDBC driver class " + target.driver()
                        + " is not on the class path; add its jar (java -cp ripv-services.jar:driver.jar ...)", "08001", e);
            }
        }
        Properties p = new Properties();
        String user = asReader ? target.readerUser() : target.user();
        String password = asReader ? target.readerPassword() : target.password();
        if (user != null) {
            p.setProperty("user", user);
        }
        if (password != null) {
            p.setProperty("password", password);
        }
        Connection c = DriverManager.getConnection(target.url(), p);
        try {
            c.setAutoCommit(true);
            if (asReader) {
                c.setReadOnly(true); // a second line of defence; the database user is what enforces it
                if (target.schema() != null) {
                    c.setSchema(target.schema());
                }
            }
        } catch (SQLException e) {
            c.close();
            throw e;
        }
        log.info("{}: connected to {} as {}", target.handle(), target.safeUrl(), user == null ? "(no user)" : user);
        return c;
    }

    private static Defaults defaults(Connection c) throws SQLException {
        return new Defaults(c.getSchema(), c.getTransactionIsolation());
    }

    /**
     * Puts a shared connection back as it was opened: the default schema, autocommit, the
     * default isolation. One user's {@code SET SCHEMA SYS} must not decide where the next one's
     * query runs.
     */
    private static void reset(Connection c, Defaults d) throws SQLException {
        if (!c.getAutoCommit()) {
            c.rollback();
            c.setAutoCommit(true);
        }
        if (c.getTransactionIsolation() != d.isolation()) {
            c.setTransactionIsolation(d.isolation());
        }
        if (d.schema() != null && !d.schema().equals(c.getSchema())) {
            c.setSchema(d.schema());
        }
    }

    /** Closes both; the next command opens them again. */
    void close() {
        for (Connection c : new Connection[] {reader, owner}) {
            if (c != null) {
                try {
                    c.close();
                } catch (SQLException e) {
                    log.debug("closing a connection to {}: {}", target.safeUrl(), e.getMessage());
                }
            }
        }
        reader = null;
        owner = null;
    }
}
