package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.client.handlers.Tls;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.ServerConfig;
import org.ripv.server.permit.Passwords;
import org.ripv.server.security.LoginThrottle;
import org.ripv.server.permit.PermitFile;
import org.junit.jupiter.api.parallel.Isolated;

/**
 * Issue 10, item 4: guessing passwords is slow and visible, and a log-in flood does not slow down
 * users already logged in. Before the fix, PBKDF2 ran on each connection's reader thread (50
 * attackers raised {@code ?status} from 2.4 ms to 91 ms median), nothing limited guesses across
 * connections, and the "too many failures" reply was lost to the close.
 */
@Isolated // judges ?status latency in ms under its own flood: failed beside other classes at load ~30 (issue 38)
class LoginFloodAttackTest {
    static final String CLOCK = "<ClockService>::<localhost>TTY1";
    static final Duration T = Duration.ofSeconds(20);

    /** The least a quiet median counts as (ms): the scheduling latency of a loaded 2-core machine. */
    static final double QUIET_FLOOR_MS = 5.0;

    @TempDir
    Path dir;

    @Test
    void aFloodOfFiftyGuessingConnectionsLeavesALoggedInUsersStatusFast() throws Exception {
        try (TestSystem sys = TestSystem.start(dir.resolve("a"))) {
            sys.register(new ClockService("localhost"));
            // The attacked account has a production-strength hash (120,000 iterations).
            PermitFile.setUser(sys.dataDir().resolve("permit.txt"), "alice", TestSystem.PASSWORD.toCharArray(),
                    List.of("operators"), Passwords.DEFAULT_ITERATIONS);
            sys.user("bob", "operators");
            ClientSocketHandler bob = sys.login("bob");

            // One measurement, quiet then flooded, back to back. The bound is the median (scheduling
            // spikes on a shared 2-core machine move a p99, not a median) at 10x the quiet one, which
            // counts as at least QUIET_FLOOR_MS: the regression this guards against, PBKDF2 on the
            // readers' threads, took the median from 2.4 ms to 91 ms. The p99s are printed for the record.
            double[] quiet = latencies(bob, 300);
            Flood flood = new Flood(sys, 1);
            flood.start();
            long until = System.nanoTime() + Duration.ofSeconds(60).toNanos();
            while (flood.answers.get() < 20) {
                assertThat(System.nanoTime()).as("the flood gets going").isLessThan(until);
                Thread.sleep(50);
            }
            int before = flood.answers.get();
            double[] loaded = latencies(bob, 300);
            int during = flood.answers.get() - before;
            flood.stop();
            String figures = String.format("?status median/p99 quiet %.2f/%.2f ms, under a 50-connection log-in flood %.2f/%.2f ms"
                    + " (%d guesses answered meanwhile, %d 'too many' replies)", quiet[0], quiet[1], loaded[0], loaded[1], during,
                    flood.tooMany.get());
            System.out.println(figures);
            assertThat(during).as("the flood ran while ?status was measured").isPositive();
            assertThat(flood.errors).as("no attacker saw anything but refusals").isEmpty();
            assertThat(loaded[0]).as("a log-in flood leaves a logged-in user's ?status fast: " + figures)
                    .isLessThan(10 * Math.max(quiet[0], QUIET_FLOOR_MS));
            assertThat(flood.tooMany.get()).as("attackers are told they are blocked before the close").isPositive();
        }
    }

    @Test
    void failuresAreLimitedAcrossConnectionsAndAnAdminLiftsTheLock() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("b"));
        // Blocks of a minute, so that the test's own pace cannot outlast one.
        config = config.withSecurity(config.security().withThrottle(
                new LoginThrottle.Policy(5, 10, Duration.ofMinutes(1), Duration.ofMinutes(15))));
        try (TestSystem sys = TestSystem.start(config)) {
            sys.user("alice", "operators");
            sys.user("admin", "operators");
            sys.user("olga", "observers");
            // Five failures on one connection: the fifth reply says why it is the last, then the close.
            ClientSocketHandler c = connectFrom(sys, "127.0.5.1");
            for (int i = 1; i <= 5; i++) {
                RipvErrorException e = refused(c, "alice", "guess" + i);
                assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN);
                if (i == 5) {
                    assertThat(e.getMessage()).contains("too many failures, disconnecting");
                }
            }
            awaitClosed(c);
            // A new connection from another address does not start afresh: the user is now blocked,
            // refused at once without trying the password (even the right one).
            ClientSocketHandler d = connectFrom(sys, "127.0.5.2");
            RipvErrorException blocked = refused(d, "alice", "guess6");
            assertThat(blocked.getMessage()).contains("too many failed log-ins for this user");
            awaitClosed(d);
            ClientSocketHandler e = connectFrom(sys, "127.0.5.3");
            assertThat(refused(e, "alice", TestSystem.PASSWORD).getMessage()).contains("too many failed log-ins");

            // Keeping at the blocked name from one address counts against the address: after its ten
            // free tries it is blocked too, and its next connection is refused before the TLS handshake.
            for (int i = 1; i <= 10; i++) {
                ClientSocketHandler again = connectFrom(sys, "127.0.5.4");
                assertThat(refused(again, "alice", "guess" + i).getMessage()).contains("too many failed log-ins for this user");
                awaitClosed(again);
            }
            ClientSocketHandler last = connectFrom(sys, "127.0.5.4");
            assertThat(refused(last, "alice", "guess11").getMessage()).contains("too many failed log-ins for this address");
            awaitClosed(last);
            assertThatThrownBy(() -> connectFrom(sys, "127.0.5.4").close()).as("refused at connect").isInstanceOf(IOException.class);

            // An observer may not lift it; an admin (here: operators, whom the template allows all) may.
            ClientSocketHandler olga = sys.login("olga");
            assertThat(olga.call("", "?unlock-login alice", Priority.NORMAL, T, null).footer().errorCode())
                    .isEqualTo(ErrorCode.FORBIDDEN);
            ClientSocketHandler admin = sys.login("admin");
            OutgoingServerMessage list = admin.call("", "?logins", Priority.NORMAL, T, null);
            assertThat(list.footer().replyText()).contains("user alice").contains("blocked").contains("address 127.0.5.1");
            OutgoingServerMessage lift = admin.call("", "?unlock-login alice", Priority.NORMAL, T, null);
            assertThat(lift.status()).isEqualTo(Status.OK);
            assertThat(lift.footer().replyText()).contains("lifted");
            sys.login("alice");
        }
    }

    private static RipvErrorException refused(ClientSocketHandler c, String user, String password) throws IOException {
        try {
            c.login(user, password.toCharArray());
        } catch (RipvErrorException e) {
            return e;
        }
        throw new AssertionError("log-in as " + user + " with " + password + " passed");
    }

    private static void awaitClosed(ClientSocketHandler c) throws InterruptedException {
        long end = System.nanoTime() + Duration.ofSeconds(10).toNanos();
        while (c.isOpen()) {
            assertThat(System.nanoTime()).as("the server closes the connection").isLessThan(end);
            Thread.sleep(20);
        }
    }

    static ClientSocketHandler connectFrom(TestSystem sys, String source) throws IOException {
        int port = sys.server().port();
        return ClientSocketHandler.connect("localhost", port,
                new FromAddress(Tls.trustOnFirstUse("localhost", port, Tls.defaultKnownHosts(), n -> { }), source), T);
    }

    /** The median and the p99 of n {@code ?status} round trips, in ms. */
    private static double[] latencies(ClientSocketHandler c, int n) throws IOException {
        for (int i = 0; i < 30; i++) {
            c.call("", "?status " + CLOCK, Priority.NORMAL, T, null);
        }
        long[] t = new long[n];
        for (int i = 0; i < n; i++) {
            long t0 = System.nanoTime();
            OutgoingServerMessage r = c.call("", "?status " + CLOCK, Priority.NORMAL, T, null);
            t[i] = System.nanoTime() - t0;
            assertThat(r.status()).isEqualTo(Status.OK);
        }
        Arrays.sort(t);
        return new double[] {t[n / 2] / 1e6, t[(int) Math.ceil(n * 0.99) - 1] / 1e6};
    }

    /** 50 connections from 50 addresses, each guessing passwords as fast as the server answers, reconnecting when cut off. */
    private static final class Flood {
        final TestSystem sys;
        final int round;
        final AtomicBoolean running = new AtomicBoolean(true);
        final AtomicInteger answers = new AtomicInteger();
        final AtomicInteger tooMany = new AtomicInteger();
        final List<Throwable> errors = new CopyOnWriteArrayList<>();
        final List<Thread> threads = new ArrayList<>();

        Flood(TestSystem sys, int round) {
            this.sys = sys;
            this.round = round;
        }

        void start() {
            for (int i = 0; i < 50; i++) {
                String source = "127.0." + (10 + round) + "." + (i + 1);
                String user = i % 2 == 0 ? "alice" : "root" + i;
                Thread t = new Thread(() -> attack(source, user), "attacker-" + i);
                t.setDaemon(true);
                threads.add(t);
                t.start();
            }
        }

        private void attack(String source, String user) {
            int guess = 0;
            while (running.get()) {
                try (ClientSocketHandler c = connectFrom(sys, source)) {
                    while (running.get() && c.isOpen()) {
                        try {
                            c.login(user, ("guess" + guess++).toCharArray());
                            errors.add(new AssertionError("a guess logged in"));
                            return;
                        } catch (RipvErrorException e) {
                            answers.incrementAndGet();
                            if (e.getMessage().contains("too many")) {
                                tooMany.incrementAndGet();
                            }
                        }
                    }
                } catch (IOException e) {
                    // cut off: connect again, as an attacker would (a little later, to spare the test's own CPU)
                }
                try {
                    Thread.sleep(50);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }

        void stop() throws InterruptedException {
            running.set(false);
            for (Thread t : threads) {
                t.join(30_000);
            }
        }
    }
}
