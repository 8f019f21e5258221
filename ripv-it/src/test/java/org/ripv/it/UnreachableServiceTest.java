package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.examples.ClockService;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.naming.Handles;
import org.ripv.rmi.DeadlineSocketFactory;
import org.ripv.server.ServerConfig;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;
import org.junit.jupiter.api.parallel.Isolated;

/**
 * A service host that stops answering without going away (a firewall dropping packets), in one
 * JVM over real RMI through a {@link BlackHoleRelay}: every request still ends within its
 * deadline, nobody else waits, {@code ?services} says why, and the service is back by itself
 * when the path is; and a service the server cannot call back is refused at once, with the
 * address and what to set.
 */
@Isolated // sets the RMI deadlines of every in-process server for its own
class UnreachableServiceTest {
    private static final String GOOD = "<ClockService>::<good>";
    private static final String DARK = "<ClockService>::<dark>";

    @TempDir
    Path dir;

    @BeforeAll
    static void shortDeadlines() {
        System.setProperty(DeadlineSocketFactory.CONNECT_PROPERTY, "1000");
        System.setProperty(DeadlineSocketFactory.READ_PROPERTY, "6000");
        System.setProperty("ripv.service.callbackMillis", "1500");
    }

    @AfterAll
    static void clear() {
        System.clearProperty(DeadlineSocketFactory.CONNECT_PROPERTY);
        System.clearProperty(DeadlineSocketFactory.READ_PROPERTY);
        System.clearProperty("ripv.service.callbackMillis");
    }

    private static TestSystem system(Path dir) throws Exception {
        TestSystem sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")).withRequestTimeout(Duration.ofSeconds(10)));
        sys.user("alice", "operators");
        sys.register(new ClockService("good"));
        return sys;
    }

    private static ServiceConnector dark(TestSystem sys, BlackHoleRelay relay, List<String> notices) throws Exception {
        ClockService dark = new ClockService("dark");
        ServiceOptions o = sys.serviceOptions();
        ServiceConnector c = ServiceConnector.connect(dark, new ServiceOptions(o.serverHost(), o.registryPort(), o.secret(),
                relay.port(), o.heartbeat()), relay);
        c.onNotice(notices::add);
        return c;
    }

    private static long millisSince(long t0) {
        return (System.nanoTime() - t0) / 1_000_000;
    }

    @Test
    void aHostThatDropsPacketsCostsEachRequestItsDeadlineAndNobodyElseAnything() throws Exception {
        List<String> notices = new CopyOnWriteArrayList<>();
        try (TestSystem sys = system(dir); BlackHoleRelay relay = new BlackHoleRelay()) {
            ServiceConnector dark = dark(sys, relay, notices);
            try {
                assertThat(dark.awaitRegistered(Duration.ofSeconds(20))).isTrue();
                ClientSocketHandler c = sys.login("alice");
                String box = Handles.platformDefault();
                assertThat(c.call(DARK + box, "echo before", Priority.NORMAL, Duration.ofSeconds(10), null).footer().replyText())
                        .isEqualTo("before");

                relay.freeze();
                long t0 = System.nanoTime();
                CompletableFuture<OutgoingServerMessage> toDark = c.send(DARK + box, "echo lost", Priority.NORMAL, null);
                CompletableFuture<OutgoingServerMessage> mailboxes = c.send("", "?mailboxes", Priority.NORMAL, null);
                CompletableFuture<OutgoingServerMessage> status = c.send("", "?status " + DARK + box, Priority.NORMAL, null);
                OutgoingServerMessage good = c.call(GOOD + box, "echo still here", Priority.NORMAL, Duration.ofSeconds(10), null);
                assertThat(good.footer().replyText()).isEqualTo("still here");
                // Held up, it would wait out the dark service's 6 s read deadline.
                assertThat(millisSince(t0)).as("the other service is not held up").isLessThan(5_000);

                OutgoingServerMessage m = mailboxes.get(10, TimeUnit.SECONDS);
                assertThat(millisSince(t0)).as("?mailboxes waits one deadline at most, not the 10 s request timeout").isLessThan(9_000);
                assertThat(m.footer().replyText()).contains(GOOD + box + ": available").contains(DARK + ": not answering");

                OutgoingServerMessage s = status.get(10, TimeUnit.SECONDS);
                assertThat(s.footer().errorCode()).isEqualTo(ErrorCode.SERVICE_GONE);
                assertThat(s.footer().replyText()).contains("not answering");

                // SERVICE_GONE, not the request timeout's TIMEOUT: it ended at the service call's deadline.
                OutgoingServerMessage lost = toDark.get(30, TimeUnit.SECONDS);
                assertThat(lost.footer().errorCode()).isEqualTo(ErrorCode.SERVICE_GONE);
                assertThat(lost.footer().replyText()).contains("could not reach " + DARK + " at 127.0.0.1:" + relay.port())
                        .doesNotContain("may still complete");

                // Health checks (every 0.5 s here, 2 s deadline) say so within two intervals plus one deadline.
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(8);
                String services;
                do {
                    services = c.call("", "?services", Priority.NORMAL, Duration.ofSeconds(5), null).footer().replyText();
                    assertThat(System.nanoTime()).as("?services says the service is not answering").isLessThan(end);
                } while (!services.contains("NOT ANSWERING") && !services.contains(DARK + "  LOST"));
                assertThat(services).contains("127.0.0.1:" + relay.port());

                relay.thaw();
                end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
                while (true) {
                    OutgoingServerMessage again = c.call(DARK + box, "echo back", Priority.NORMAL, Duration.ofSeconds(15), null);
                    if ("back".equals(again.footer().replyText())) {
                        break;
                    }
                    assertThat(System.nanoTime()).as("back by itself: " + again.footer().replyText()).isLessThan(end);
                    Thread.sleep(300);
                }
                assertThat(c.call("", "?services", Priority.NORMAL, Duration.ofSeconds(5), null).footer().replyText())
                        .contains(DARK).doesNotContain("NOT ANSWERING").doesNotContain("LOST");
            } finally {
                dark.close();
            }
        }
    }

    @Test
    void aServiceTheServerCannotCallBackIsRefusedWithTheAddressAndWhatToSetThenAdmittedOnceReachable() throws Exception {
        List<String> notices = new CopyOnWriteArrayList<>();
        try (TestSystem sys = system(dir); BlackHoleRelay relay = new BlackHoleRelay()) {
            relay.freeze();
            ServiceConnector dark = dark(sys, relay, notices);
            try {
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
                while (notices.isEmpty()) {
                    assertThat(System.nanoTime()).as("the service is told").isLessThan(end);
                    Thread.sleep(50);
                }
                assertThat(notices.get(0)).contains("registration refused")
                        .contains("could not call " + DARK + " back at 127.0.0.1:" + relay.port())
                        .contains("--host").contains("--export-port").contains("--outbound-only");
                assertThat(sys.server().serviceCount()).as("never listed").isEqualTo(1);
                ClientSocketHandler c = sys.login("alice");
                assertThat(c.call("", "?services", Priority.NORMAL, Duration.ofSeconds(5), null).footer().replyText())
                        .as("the operator sees why").contains(DARK + "  REFUSED at ")
                        .contains("cannot call it back at 127.0.0.1:" + relay.port());
                assertThat(dark.isRegistered()).isFalse();
                relay.thaw();
                assertThat(dark.awaitRegistered(Duration.ofSeconds(20))).as("keeps retrying").isTrue();
                assertThat(sys.server().serviceCount()).isEqualTo(2);
                assertThat(c.call("", "?services", Priority.NORMAL, Duration.ofSeconds(5), null).footer().replyText())
                        .contains(DARK + "  SID").doesNotContain("REFUSED");
            } finally {
                dark.close();
            }
        }
    }
}
