package org.ripv.services.database;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Embedded Derby's query limit as the service keeps it: the database's own time counts, the time
 * the rows wait for their reader does not; at the limit the statement's thread is interrupted
 * (embedded Derby has no {@code Statement.cancel}), and the interrupt never outlives the statement.
 * A cancel that comes while a request is under way but before its statement started is kept.
 */
class RunningStatementTest {
    private static final String URL = "jdbc:derby:memory:runningStatement;create=true";

    private Connection c;
    private Statement st;
    private final RunningStatement running = new RunningStatement("test");

    @BeforeEach
    void open() throws SQLException {
        c = DriverManager.getConnection(URL);
        st = c.createStatement();
    }

    @AfterEach
    void close() throws SQLException {
        Thread.interrupted(); // a failed assertion must not leave an interrupt to the next test
        st.close();
        c.close();
    }

    @Test
    void theLimitCountsTheDatabasesTimeNotTheReaders() throws Exception {
        running.start(st, 1);
        running.pause();
        Thread.sleep(1500); // waiting for the reader: past the limit, but not the database's time
        running.resume();
        assertThat(running.timedOut()).isFalse();
        assertThat(Thread.currentThread().isInterrupted()).isFalse();
        running.finish();

        running.start(st, 1);
        Thread.sleep(400);
        running.pause();
        Thread.sleep(1000);
        running.resume(); // 0.6 s of the limit left
        long until = System.nanoTime() + 5_000_000_000L;
        while (!Thread.currentThread().isInterrupted() && System.nanoTime() < until) {
            LockSupport.parkNanos(20_000_000); // unlike sleep, keeps the interrupt it wakes on
        }
        assertThat(Thread.interrupted()).as("the statement's thread is interrupted").isTrue();
        assertThat(running.timedOut()).as("the database's time reached the limit").isTrue();
        running.finish();
    }

    @Test
    void noInterruptOutlivesItsStatement() throws Exception {
        running.start(st, 1);
        running.finish();
        Thread.sleep(1300);
        assertThat(running.timedOut()).isFalse();
        assertThat(Thread.currentThread().isInterrupted()).isFalse();
        assertThat(running.cancel()).as("nothing runs").isFalse();
    }

    @Test
    void aCancelBeforeTheStatementStartsIsKeptForTheRequest() throws Exception {
        Object request = new Object();
        running.begin(request);
        assertThat(running.cancel(request)).as("a request is under way, its statement not yet made").isTrue();
        assertThatThrownBy(() -> running.start(st, 0)).isInstanceOf(SQLException.class)
                .satisfies(e -> assertThat(((SQLException) e).getSQLState()).isEqualTo("57014"));
        assertThat(running.cancelRequested()).isTrue();
        running.finish();
        running.end();

        // The next request starts clean: the kept cancel was its predecessor's.
        running.begin(new Object());
        running.start(st, 0);
        assertThat(running.cancelRequested()).isFalse();
        running.finish();
        running.end();
        assertThat(running.cancel()).as("between requests nothing runs").isFalse();
        assertThat(Thread.currentThread().isInterrupted()).isFalse();
    }

    /** The MailBox started the request (its cancel reaches the handler) but the handler has not begun it. */
    @Test
    void aCancelBeforeTheRequestBeginsIsKeptForItAlone() throws Exception {
        Object request = new Object();
        assertThat(running.cancel(request)).isTrue();
        running.begin(request);
        assertThatThrownBy(() -> running.start(st, 0)).isInstanceOf(SQLException.class);
        running.finish();
        running.end();

        running.begin(new Object());
        running.start(st, 0);
        assertThat(running.cancelRequested()).as("another request is not touched").isFalse();
        running.finish();
        running.end();
    }
}
