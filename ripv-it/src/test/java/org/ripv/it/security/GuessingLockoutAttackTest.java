package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.it.TestSystem;

/**
 * Issue 23, item 15: twelve wrong passwords from twelve addresses locked the user everywhere, for
 * minutes: anyone could lock an operator out during a glider's call. Now the guessing sources are
 * penalized, the user name alone is slowed by seconds, and the real user from their own address
 * gets in at once.
 */
class GuessingLockoutAttackTest {
    @TempDir
    Path dir;

    @Test
    void guessesFromTwelveAddressesDoNotLockTheRealUserOut() throws Exception {
        try (TestSystem sys = TestSystem.start(dir)) {
            sys.user("alice", "operators");
            try (ClientSocketHandler own = LoginFloodAttackTest.connectFrom(sys, "127.0.6.100")) {
                own.login("alice", TestSystem.PASSWORD.toCharArray()); // alice's own machine
            }
            int refused = 0;
            for (int i = 1; i <= 12; i++) {
                try (ClientSocketHandler c = LoginFloodAttackTest.connectFrom(sys, "127.0.6." + i)) {
                    c.login("alice", ("guess" + i).toCharArray());
                    throw new AssertionError("a guess passed");
                } catch (RipvErrorException e) {
                    refused++;
                }
            }
            assertThat(refused).isEqualTo(12);

            // Before the fix: "too many failed log-ins for this user; try again in 64 s" here.
            try (ClientSocketHandler own = LoginFloodAttackTest.connectFrom(sys, "127.0.6.100")) {
                assertThat(own.login("alice", TestSystem.PASSWORD.toCharArray()).user()).isEqualTo("alice");
            }
            // From a machine she never used, she waits seconds, not minutes.
            long start = System.nanoTime();
            String last = "";
            while (true) {
                try (ClientSocketHandler c = LoginFloodAttackTest.connectFrom(sys, "127.0.6.200")) {
                    assertThat(c.login("alice", TestSystem.PASSWORD.toCharArray()).user()).isEqualTo("alice");
                    break;
                } catch (RipvErrorException e) {
                    last = e.getMessage();
                    assertThat(last).contains("for this user").doesNotContain("locked");
                    assertThat(Duration.ofNanos(System.nanoTime() - start)).as(last).isLessThan(Duration.ofSeconds(30));
                    Thread.sleep(500);
                }
            }
        }
    }
}
