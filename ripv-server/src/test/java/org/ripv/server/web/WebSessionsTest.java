package org.ripv.server.web;

import static org.assertj.core.api.Assertions.assertThat;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** Sessions' caps and expiry on a clock the test turns (issue 33 items 2, 3, 4 and 10). */
class WebSessionsTest {
    final AtomicLong now = new AtomicLong(1_000_000);
    final WebSessions sessions = new WebSessions(Duration.ofMinutes(30), Duration.ofHours(12), now::get);

    /** A page's socket: a distinct object each (a lambda without captures is one shared instance). */
    static AutoCloseable page() {
        return new AutoCloseable() {
            @Override
            public void close() {
            }
        };
    }

    @Test
    void anExpiredSessionsPagesAreClosedBySweeping() {
        WebSessions.Session s = sessions.create("alice", List.of("operators"));
        AtomicBoolean closed = new AtomicBoolean();
        assertThat(sessions.admitSocket(s, () -> closed.set(true))).isNull();
        now.addAndGet(Duration.ofMinutes(31).toMillis());
        assertThat(sessions.sweep()).isEqualTo(1);
        assertThat(closed).as("the page's socket was closed without a request of its own").isTrue();
        assertThat(sessions.find(s.id)).isNull();
    }

    @Test
    void aUsersLogInsPastTheCapEndTheirOwnOldestNeverAnothers() {
        WebSessions.Session alice = sessions.create("alice", List.of());
        WebSessions.Session first = sessions.create("mallory", List.of());
        for (int i = 0; i < 2 * WebSessions.MAX_SESSIONS; i++) {
            assertThat(sessions.create("mallory", List.of())).isNotNull();
        }
        assertThat(sessions.of("mallory")).hasSize(WebSessions.MAX_SESSIONS_PER_USER);
        assertThat(sessions.find(first.id)).isNull();
        assertThat(sessions.find(alice.id)).isSameAs(alice);
    }

    @Test
    void aFullTableRefusesTheLogInRatherThanEvicting() {
        for (int i = 0; i < WebSessions.MAX_SESSIONS; i++) {
            assertThat(sessions.create("user" + i, List.of())).isNotNull();
        }
        assertThat(sessions.create("late", List.of())).isNull();
        assertThat(sessions.of("user0")).hasSize(1);
    }

    @Test
    void socketsAreCappedPerSessionAndPerUser() {
        int opened = 0;
        for (int k = 0; k < 4; k++) {
            WebSessions.Session s = sessions.create("mallory", List.of());
            for (int i = 0; i < 100; i++) {
                if (sessions.admitSocket(s, page()) != null) {
                    break;
                }
                opened++;
            }
            assertThat(s.sockets.size()).isLessThanOrEqualTo(WebSessions.MAX_SOCKETS_PER_SESSION);
        }
        assertThat(opened).isEqualTo(WebSessions.MAX_SOCKETS_PER_USER);
        assertThat(sessions.admitSocket(sessions.create("alice", List.of()), page())).isNull();
    }

    @Test
    void aPermitChangeEndsOrReDerivesSessions() {
        WebSessions.Session pete = sessions.create("pete", List.of("operators"));
        WebSessions.Session dora = sessions.create("dora", List.of("operators"));
        AtomicBoolean closed = new AtomicBoolean();
        sessions.admitSocket(pete, () -> closed.set(true));
        sessions.usersChanged(Set.of("pete"), Map.of("dora", List.of("observers")));
        assertThat(sessions.find(pete.id)).isNull();
        assertThat(closed).isTrue();
        assertThat(sessions.find(dora.id).roles).containsExactly("observers");
    }
}
