package org.ripv.server.standby;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.Statement;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.condition.EnabledIfEnvironmentVariable;

/**
 * Two servers' claims on one PostgreSQL database, in its own database per run: one leads, the
 * other stands by and leads the moment the first gives up, dies, or loses its connection; the
 * one that lost its connection is told. Needs RIPV_PG_URL (CI sets it).
 */
@EnabledIfEnvironmentVariable(named = "RIPV_PG_URL", matches = ".+",
        disabledReason = "no PostgreSQL: set RIPV_PG_URL (and RIPV_PG_USER, RIPV_PG_PASSWORD) to run this test")
class LeadershipTest {
    private static final Leadership.Timings FAST = new Leadership.Timings(Duration.ofMillis(200), Duration.ofSeconds(2),
            Duration.ofSeconds(3), Duration.ofSeconds(1));
    private static String admin;
    private static String url;
    private static final String DB = "ripv_lead_" + ProcessHandle.current().pid();

    @BeforeAll
    static void database() throws Exception {
        admin = System.getenv("RIPV_PG_URL");
        try (Connection c = connect(admin); Statement s = c.createStatement()) {
            s.execute("CREATE DATABASE " + DB);
        }
        url = admin.replaceFirst("/[^/?]*(\\?|$)", "/" + DB + "$1");
    }

    @AfterAll
    static void drop() throws Exception {
        try (Connection c = connect(admin); Statement s = c.createStatement()) {
            s.execute("DROP DATABASE IF EXISTS " + DB + " WITH (FORCE)");
        }
    }

    private static Connection connect(String u) throws Exception {
        return DriverManager.getConnection(u, System.getenv("RIPV_PG_USER"), System.getenv("RIPV_PG_PASSWORD"));
    }

    private static Leadership claim(String me) {
        return new Leadership(url, System.getenv("RIPV_PG_USER"), System.getenv("RIPV_PG_PASSWORD"), me, FAST);
    }

    private static CompletableFuture<Void> standBy(Leadership l) {
        return CompletableFuture.runAsync(() -> {
            try {
                l.awaitLead();
            } catch (InterruptedException e) {
                throw new IllegalStateException(e);
            }
        });
    }

    @Test
    void oneLeadsTheOtherTakesOverWhenItCloses() throws Exception {
        try (Leadership a = claim("a:4444"); Leadership b = claim("b:4444")) {
            a.awaitLead();
            CompletableFuture<Void> waiting = standBy(b);
            Thread.sleep(1_000);
            assertThat(waiting).as("b stands by while a leads").isNotDone();
            a.close();
            waiting.get(5, TimeUnit.SECONDS);
            assertThat(b.lost()).isNotDone();
        }
    }

    @Test
    void theHolderThatLosesItsConnectionIsToldAndTheStandbyLeads() throws Exception {
        try (Leadership a = claim("a:4444"); Leadership b = claim("b:4444")) {
            a.awaitLead();
            CompletableFuture<Void> waiting = standBy(b);
            // What a dead link or a restarted database looks like from here: the session is gone.
            try (Connection c = connect(url); Statement s = c.createStatement()) {
                s.execute("SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE application_name = 'ripv-server a:4444'");
            }
            assertThat(a.lost().get(5, TimeUnit.SECONDS)).contains("lost the state database");
            waiting.get(5, TimeUnit.SECONDS);
        }
    }

    @Test
    void anUnreachableDatabaseFailsAServersStartButOnlyDelaysAStandby() throws Exception {
        String nowhere = "jdbc:postgresql://127.0.0.1:1/ripv?password=hunter2";
        try (Leadership l = new Leadership(nowhere, null, null, "a:4444", FAST)) {
            assertThatThrownBy(() -> l.awaitLead(true)).isInstanceOf(java.io.IOException.class)
                    .hasMessageContaining("cannot use the state database jdbc:postgresql://127.0.0.1:1/ripv?password=***")
                    .hasMessageNotContaining("hunter2");
        }
        Leadership later = new Leadership(nowhere, null, null, "a:4444", FAST);
        CompletableFuture<Void> waiting = standBy(later);
        Thread.sleep(1_000);
        assertThat(waiting).as("without failFast it stands by").isNotDone();
        later.close();
        assertThat(waiting).failsWithin(5, TimeUnit.SECONDS);
    }

    @Test
    void timingsThatWouldLetTwoServeAreRefused() {
        assertThatThrownBy(() -> new Leadership.Timings(Duration.ofSeconds(5), Duration.ofSeconds(5), Duration.ofSeconds(2),
                Duration.ofSeconds(1))).hasMessageContaining("two servers could serve at once");
        assertThatThrownBy(() -> new Leadership("jdbc:derby:x", null, null, "me", FAST)).hasMessageContaining("PostgreSQL");
    }
}
