package org.ripv.server.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** Back-off per user and per address, on a clock the test turns. */
class LoginThrottleTest {
    final AtomicLong now = new AtomicLong(1_000_000);
    final LoginThrottle t = new LoginThrottle(new LoginThrottle.Policy(3, 5, Duration.ofSeconds(1), Duration.ofSeconds(8)), now::get);

    @Test
    void aSourceGuessingOneUserIsBlockedLongerEachTimeUpToTheLock() {
        for (int i = 0; i < 3; i++) {
            assertThat(t.failure("alice", "10.0.0.9")).isNull();
        }
        assertThat(t.failure("alice", "10.0.0.9").left()).isEqualTo(Duration.ofSeconds(1));
        now.addAndGet(1_000);
        assertThat(t.failure("alice", "10.0.0.9").left()).isEqualTo(Duration.ofSeconds(2));
        now.addAndGet(2_000);
        assertThat(t.failure("alice", "10.0.0.9").left()).isEqualTo(Duration.ofSeconds(4));
        now.addAndGet(4_000);
        LoginThrottle.Block lock = t.failure("alice", "10.0.0.9");
        assertThat(lock.left()).isEqualTo(Duration.ofSeconds(8));
        assertThat(lock.locked()).isTrue();
        assertThat(lock.who()).isEqualTo("user alice from 10.0.0.9");
        now.addAndGet(8_000);
        assertThat(t.failure("alice", "10.0.0.9").left()).as("capped at the lock").isEqualTo(Duration.ofSeconds(8));
        assertThat(t.describe()).anyMatch(l -> l.startsWith("pair alice from 10.0.0.9") && l.contains("LOCKED"));
        assertThat(t.lift("alice")).isTrue();
        assertThat(t.describe()).noneMatch(l -> l.contains("alice"));
        assertThat(t.blocked("alice", "10.0.0.9").who()).as("the address's own block stays").isEqualTo("address 10.0.0.9");
        assertThat(t.lift("10.0.0.9")).isTrue();
        assertThat(t.blocked("alice", "10.0.0.9")).isNull();
    }

    @Test
    void guessesFromManyAddressesSlowTheUserBySecondsAndNeverLockItOutOfItsOwnAddress() {
        // Issue 23, item 15: twelve wrong passwords from twelve addresses locked the user everywhere.
        LoginThrottle slow = new LoginThrottle(new LoginThrottle.Policy(3, 5, Duration.ofSeconds(1), Duration.ofSeconds(60),
                Duration.ofSeconds(4)), now::get);
        slow.success("alice", "192.0.2.1");
        LoginThrottle.Block last = null;
        for (int i = 0; i < 12; i++) {
            last = slow.failure("alice", "10.0.0." + i);
            now.addAndGet(last == null ? 0 : last.left().toMillis());
        }
        now.addAndGet(-last.left().toMillis());
        assertThat(last.who()).isEqualTo("user alice");
        assertThat(last.left()).as("seconds, not minutes").isEqualTo(Duration.ofSeconds(4));
        assertThat(last.locked()).isFalse();
        assertThat(slow.blocked("alice", "10.0.0.77")).as("a new address waits a few seconds").isNotNull();
        assertThat(slow.blocked("alice", "192.0.2.1")).as("the real user's own address").isNull();
        now.addAndGet(4_000);
        assertThat(slow.blocked("alice", "10.0.0.77")).isNull();
        // One try per few seconds from addresses alice never used: the first takes the turn.
        assertThat(slow.admit("alice", "10.0.0.77")).isNull();
        assertThat(slow.admit("alice", "10.0.0.78")).as("the turn is taken").isNotNull();
        assertThat(slow.admit("alice", "192.0.2.1")).as("her own address waits for no turn").isNull();
    }

    @Test
    void anAddressThatKeepsTryingABlockedNameIsBlockedItself() {
        for (int i = 0; i < 4; i++) {
            t.failure("alice", "10.0.0." + i);
        }
        assertThat(t.blocked("alice", "192.0.2.50").who()).isEqualTo("user alice");
        for (int i = 0; i < 5; i++) {
            assertThat(t.refusedWhileBlocked("192.0.2.50")).as("free refusals " + i).isNull();
        }
        LoginThrottle.Block b = t.refusedWhileBlocked("192.0.2.50");
        assertThat(b.who()).isEqualTo("address 192.0.2.50");
        assertThat(b.left()).isEqualTo(Duration.ofSeconds(1));
        assertThat(t.addressBlocked("192.0.2.50")).isNotNull();
        assertThat(t.addressBlocked("192.0.2.51")).as("only that address").isNull();
    }

    @Test
    void anAddressGuessingManyNamesIsBlockedAndASuccessDoesNotClearIt() {
        for (int i = 0; i < 5; i++) {
            assertThat(t.failure("user" + i, "192.0.2.7")).isNull();
        }
        LoginThrottle.Block b = t.failure("user9", "192.0.2.7");
        assertThat(b.who()).isEqualTo("address 192.0.2.7");
        t.success("user9", "192.0.2.7");
        assertThat(t.blocked("someone", "192.0.2.7")).isNotNull();
        assertThat(t.blocked("someone", "192.0.2.8")).isNull();
        assertThat(t.lift("192.0.2.7")).isTrue();
        assertThat(t.blocked("someone", "192.0.2.7")).isNull();
    }

    @Test
    void aLockLengthOfQuietStartsTheCountAfresh() {
        for (int i = 0; i < 3; i++) {
            t.failure("bob", "10.1.1.1");
        }
        now.addAndGet(9_000);
        assertThat(t.failure("bob", "10.1.1.1")).as("the old failures are forgotten").isNull();
    }
}
