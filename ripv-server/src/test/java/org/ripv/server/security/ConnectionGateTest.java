package org.ripv.server.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.InetAddress;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** The log-in deadline counts the client's time, not the server's time checking its password. */
class ConnectionGateTest {
    static final Duration DEADLINE = Duration.ofMillis(300);

    final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor();
    final ConnectionGate gate = new ConnectionGate(ConnectionGate.Limits.defaults().withLoginDeadline(DEADLINE), timer,
            new LoginThrottle(LoginThrottle.Policy.defaults()));
    final InetAddress from = InetAddress.getLoopbackAddress();

    @AfterEach
    void stop() {
        timer.shutdownNow();
    }

    @Test
    void aConnectionThatDoesNotLogInIsClosedAtTheDeadline() throws Exception {
        CountDownLatch expired = new CountDownLatch(1);
        assertThat(gate.admit("c1", from, expired::countDown)).isTrue();
        assertThat(expired.await(5, TimeUnit.SECONDS)).isTrue();
    }

    @Test
    void aLoginBeingCheckedIsNotClosedHoweverLongTheCheckTakes() throws Exception {
        CountDownLatch expired = new CountDownLatch(1);
        assertThat(gate.admit("c1", from, expired::countDown)).isTrue();
        gate.checking("c1");
        assertThat(expired.await(DEADLINE.toMillis() * 3, TimeUnit.MILLISECONDS)).as("closed during its check").isFalse();
        assertThat(gate.loggedIn("c1")).isTrue();
        gate.checked("c1");
        assertThat(expired.await(DEADLINE.toMillis() * 3, TimeUnit.MILLISECONDS)).as("closed after it logged in").isFalse();
        assertThat(gate.pendingCount()).isZero();
    }

    @Test
    void aRefusedLoginGoesOnWithTheTimeThatWasLeft() throws Exception {
        CountDownLatch expired = new CountDownLatch(1);
        long start = System.nanoTime();
        assertThat(gate.admit("c1", from, expired::countDown)).isTrue();
        Thread.sleep(100);
        gate.checking("c1");
        Thread.sleep(DEADLINE.toMillis() * 2); // the server's time: not counted
        assertThat(expired.getCount()).as("closed during its check").isOne();
        gate.checked("c1"); // a wrong password: the rest of the deadline, about 200 ms
        assertThat(expired.await(5, TimeUnit.SECONDS)).isTrue();
        assertThat(gate.pendingCount()).isOne(); // closing the socket releases it (closed())
        assertThat(Duration.ofNanos(System.nanoTime() - start)).isGreaterThanOrEqualTo(DEADLINE.multipliedBy(2));
    }
}
