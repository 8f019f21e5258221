package org.ripv.server.standby;

import java.io.IOException;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.time.Duration;
import java.util.Properties;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Who serves, decided by PostgreSQL: a session-level advisory lock held on a connection of its
 * own. {@link #awaitLead} blocks (a standby) until this server holds the lock; from then on the
 * lock is checked every {@link Timings#check}, and {@link #lost} completes, with the reason, the
 * moment the check fails or cannot reach the database within {@link Timings#socket}.
 *
 * <p>Why the old holder always stops first: the lock's connection asks PostgreSQL to drop it
 * only after {@link Timings#keepaliveIdle} + 3 × {@link Timings#keepaliveInterval} without an
 * answer from this host (TCP keepalives, {@code tcp_user_timeout}), which is longer than
 * {@link Timings#check} + {@link Timings#socket}, the longest this side takes to notice. A process
 * that dies releases the lock at once (its kernel closes the socket).
 */
public final class Leadership implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(Leadership.class);
    /** The advisory lock's key: "RIPVLEAD" in ASCII; one lead per database. */
    static final long KEY = 0x524950564c454144L;

    /**
     * @param check             how often a standby asks for the lock and the holder checks it
     * @param socket            how long one exchange with the database may take (connect and read)
     * @param keepaliveIdle     silence after which PostgreSQL starts probing this server's connection
     * @param keepaliveInterval between those probes; the third unanswered one drops the session
     */
    public record Timings(Duration check, Duration socket, Duration keepaliveIdle, Duration keepaliveInterval) {
        public static final Timings DEFAULT = new Timings(Duration.ofSeconds(1), Duration.ofSeconds(3), Duration.ofSeconds(5),
                Duration.ofSeconds(1));

        public Timings {
            long notice = check.toMillis() + socket.toMillis();
            long drop = keepaliveIdle.toMillis() + 3 * keepaliveInterval.toMillis();
            if (drop <= notice) {
                throw new IllegalArgumentException("the database would drop a silent holder (" + drop + " ms) before it notices ("
                        + notice + " ms): two servers could serve at once");
            }
        }
    }

    private final String url;
    /** The URL with any password in it masked, for messages. */
    private final String shown;
    private final Properties properties;
    private final Timings timings;
    private final String me;
    private final ScheduledExecutorService timer;
    private final CompletableFuture<String> lost = new CompletableFuture<>();
    private volatile Connection connection;
    private ScheduledFuture<?> checking;
    private volatile boolean closed;

    /**
     * @param url      the PostgreSQL state database ({@code jdbc:postgresql://...})
     * @param user     its user, or null
     * @param password its password, or null
     * @param me       how this server is named to the others (shown in their "standing by" line)
     */
    public Leadership(String url, String user, String password, String me, Timings timings) {
        if (url == null || !url.startsWith("jdbc:postgresql:")) {
            throw new IllegalArgumentException("a standby needs a PostgreSQL state database (jdbc:postgresql://HOST/DB)");
        }
        this.url = url;
        this.shown = url.replaceAll("(?i)(password=)[^&]*", "$1***");
        this.timings = timings;
        this.me = me;
        this.properties = new Properties();
        if (user != null) {
            properties.setProperty("user", user);
        }
        if (password != null) {
            properties.setProperty("password", password);
        }
        int socketSeconds = (int) Math.max(1, timings.socket().toSeconds());
        properties.setProperty("connectTimeout", Integer.toString(socketSeconds));
        properties.setProperty("socketTimeout", Integer.toString(socketSeconds));
        properties.setProperty("loginTimeout", Integer.toString(socketSeconds));
        properties.setProperty("tcpKeepAlive", "true");
        properties.setProperty("ApplicationName", ("ripv-server " + me).substring(0, Math.min(63, 12 + me.length())));
        this.timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "ripv-lead");
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Blocks until this server holds the lead. Meanwhile it logs, once per change, who holds it
     * or why the database cannot be asked.
     *
     * @throws InterruptedException when stopped while standing by
     */
    public void awaitLead() throws InterruptedException {
        try {
            awaitLead(false);
        } catch (IOException e) {
            throw new IllegalStateException(e); // not thrown without failFast
        }
    }

    /**
     * As {@link #awaitLead()}; with {@code failFast}, a database that cannot be asked at the first
     * try fails at once (a wrong URL or password at a server's start is an error to report, not
     * an outage to sit out).
     *
     * @throws java.io.IOException with failFast, when the first try cannot reach the database
     */
    public void awaitLead(boolean failFast) throws InterruptedException, IOException {
        String said = null;
        boolean first = true;
        while (!closed) {
            String why;
            try {
                if (tryLock()) {
                    log.info("this server ({}) holds the lead in {}: serving", me, shown);
                    checking = timer.scheduleWithFixedDelay(this::check, timings.check().toMillis(), timings.check().toMillis(),
                            TimeUnit.MILLISECONDS);
                    return;
                }
                why = "standing by: " + holder() + " holds the lead in " + shown;
            } catch (SQLException e) {
                drop();
                if (first && failFast) {
                    throw new IOException("cannot use the state database " + shown + ": " + e.getMessage(), e);
                }
                why = "standing by: cannot reach the state database " + shown + " (" + e.getMessage() + "); serving nothing";
            }
            first = false;
            if (!why.equals(said)) {
                log.warn("{}", why);
                said = why;
            }
            Thread.sleep(timings.check().toMillis());
        }
        throw new InterruptedException("closed");
    }

    /** Completes with the reason when the lead is lost; never while standing by. */
    public CompletableFuture<String> lost() {
        return lost;
    }

    private boolean tryLock() throws SQLException {
        Connection c = connection;
        if (c == null) {
            c = DriverManager.getConnection(url, properties);
            try (Statement s = c.createStatement()) {
                // Ask the database to drop this session soon after this host goes silent (a cut link,
                // a dead host), so that a standby can take over; settable per session.
                long idle = Math.max(1, timings.keepaliveIdle().toSeconds());
                long interval = Math.max(1, timings.keepaliveInterval().toSeconds());
                s.execute("SET tcp_keepalives_idle = " + idle);
                s.execute("SET tcp_keepalives_interval = " + interval);
                s.execute("SET tcp_keepalives_count = 3");
                s.execute("SET tcp_user_timeout = " + (idle + 3 * interval) * 1000);
            }
            connection = c;
        }
        try (PreparedStatement p = c.prepareStatement("SELECT pg_try_advisory_lock(?)")) {
            p.setLong(1, KEY);
            try (ResultSet r = p.executeQuery()) {
                return r.next() && r.getBoolean(1);
            }
        }
    }

    /** Who holds the lock, as far as PostgreSQL can say. */
    private String holder() throws SQLException {
        try (PreparedStatement p = connection.prepareStatement("SELECT a.application_name, a.client_addr, a.backend_start"
                + " FROM pg_locks l JOIN pg_stat_activity a ON a.pid = l.pid WHERE l.locktype = 'advisory' AND l.granted"
                + " AND l.classid = ? AND l.objid = ? AND l.objsubid = 1")) {
            p.setLong(1, KEY >>> 32);
            p.setLong(2, KEY & 0xffffffffL);
            try (ResultSet r = p.executeQuery()) {
                if (!r.next()) {
                    return "another server";
                }
                String name = r.getString(1);
                String addr = r.getString(2);
                return (name == null || name.isBlank() ? "another server" : name.replaceAll("[^\\x20-\\x7e]", "?"))
                        + (addr == null ? "" : " (connected from " + addr + ")") + " since " + r.getString(3);
            }
        }
    }

    /** The holder's check: the lock still ours, answered within the socket timeout. */
    private void check() {
        if (lost.isDone()) {
            return;
        }
        try (Statement s = connection.createStatement();
             ResultSet r = s.executeQuery("SELECT count(*) FROM pg_locks WHERE locktype = 'advisory' AND granted"
                     + " AND pid = pg_backend_pid() AND objsubid = 1")) {
            if (r.next() && r.getInt(1) > 0) {
                return;
            }
            lose("the state database no longer shows this server's lock");
        } catch (SQLException | RuntimeException e) {
            lose("lost the state database " + shown + " (" + e.getMessage() + ")");
        }
    }

    private void lose(String why) {
        if (checking != null) {
            checking.cancel(false);
        }
        drop();
        if (!closed) {
            log.error("this server ({}) lost the lead: {}; it stops serving and stands by", me, why);
        }
        lost.complete(why);
    }

    /** Closes the lock's connection; the database then releases the lock. */
    private void drop() {
        Connection c = connection;
        connection = null;
        if (c != null) {
            try {
                c.abort(Runnable::run); // close() could wait on a dead link
            } catch (SQLException | RuntimeException e) {
                log.debug("lead connection abort: {}", e.toString());
            }
        }
    }

    /** Gives the lead up (another server may take it at once) and stops checking. Idempotent. */
    @Override
    public void close() {
        closed = true;
        Connection c = connection;
        if (c != null) {
            try (PreparedStatement p = c.prepareStatement("SELECT pg_advisory_unlock(?)")) {
                p.setLong(1, KEY);
                p.execute();
            } catch (SQLException | RuntimeException e) {
                log.debug("lead unlock: {}", e.toString());
            }
        }
        drop();
        lost.complete("closed");
        timer.shutdownNow();
    }
}
