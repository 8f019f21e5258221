package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.server.ServerConfig;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Issue 33 item 10: one client's 20,000 urgent requests raised everyone's latency to 17 s and the
 * server's memory to 2.5 GB: nothing capped what one client had waiting, and urgent was anyone's
 * to take. Now a client has at most 32 priority or urgent requests and 2,048 in all waiting; the
 * rest are refused at once, and another user's urgent request goes to the head as before.
 */
@ResourceLock(Shared.CPU)
class RequestFloodAttackTest {
    static final String CLOCK = WebConsoleAttackTest.CLOCK;
    static final Duration T = Duration.ofSeconds(60);

    @TempDir
    static Path dir;
    static TestSystem sys;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("mallory", "operators").user("alice", "operators");
        sys.register(new ClockService("localhost"));
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    static String reply(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, p -> { }).footer().replyText();
    }

    static List<OutgoingServerMessage> all(List<CompletableFuture<OutgoingServerMessage>> sent) throws Exception {
        List<OutgoingServerMessage> got = new ArrayList<>();
        for (CompletableFuture<OutgoingServerMessage> f : sent) {
            got.add(f.get(T.toSeconds(), TimeUnit.SECONDS));
        }
        return got;
    }

    static long refused(List<OutgoingServerMessage> replies, String why) {
        return replies.stream().filter(r -> r.status() == Status.ERROR && r.footer().replyText().contains(why)).count();
    }

    @Test
    void oneClientsFloodIsCappedAndOthersAreServed() throws Exception {
        ClientSocketHandler mallory = sys.login("mallory");
        ClientSocketHandler alice = sys.login("alice");
        // The clock is busy for 3 s: everything mallory sends meanwhile waits.
        CompletableFuture<OutgoingServerMessage> busy = mallory.send(CLOCK, "sleep 3000", Priority.NORMAL, p -> { });
        long until = System.nanoTime() + T.toNanos();
        while (!reply(alice, "?status " + CLOCK).contains("busy")) { // the sleep runs: nothing of the flood can finish before it
            assertThat(System.nanoTime()).as("the clock starts its sleep").isLessThan(until);
            Thread.sleep(10);
        }
        List<CompletableFuture<OutgoingServerMessage>> urgent = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            urgent.add(mallory.send(CLOCK, "echo urgent " + i, Priority.URGENT, p -> { }));
        }
        List<CompletableFuture<OutgoingServerMessage>> normal = new ArrayList<>();
        for (int i = 0; i < 2_500; i++) {
            normal.add(mallory.send(CLOCK, "echo normal " + i, Priority.NORMAL, p -> { }));
        }
        // Alice's urgent request is taken and goes ahead of mallory's queue.
        long t0 = System.nanoTime();
        OutgoingServerMessage mine = alice.call(CLOCK, "echo alice", Priority.URGENT, T, p -> { });
        Duration aliceWaited = Duration.ofNanos(System.nanoTime() - t0);
        assertThat(mine.status()).as(mine.footer().replyText()).isEqualTo(Status.OK);

        List<OutgoingServerMessage> u = all(urgent);
        java.util.Map<String, Long> kinds = u.stream().collect(java.util.stream.Collectors.groupingBy(
                r -> r.status() + " " + r.footer().replyText().replaceAll("\\d+", "N"), java.util.TreeMap::new, java.util.stream.Collectors.counting()));
        assertThat(refused(u, "priority or urgent requests waiting, the most one client may")).as("urgent requests refused: " + kinds)
                .isEqualTo(200 - 32);
        List<OutgoingServerMessage> n = all(normal);
        long refusedNormal = refused(n, "requests waiting for replies, the most one client may");
        assertThat(refusedNormal).as("requests over 2,048 waiting refused").isGreaterThanOrEqualTo(2_500 + 32 + 1 - 2_048);
        assertThat(busy.get(T.toSeconds(), TimeUnit.SECONDS).status()).isEqualTo(Status.OK);
        assertThat(aliceWaited).as("alice waited for the sleep and mallory's 32 urgent, not the flood").isLessThan(Duration.ofSeconds(15));

        // Once the replies are in, mallory may send again.
        assertThat(mallory.call(CLOCK, "echo again", Priority.URGENT, T, p -> { }).status()).isEqualTo(Status.OK);
        mallory.close();
        alice.close();
    }
}
