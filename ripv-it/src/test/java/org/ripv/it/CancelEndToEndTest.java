package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.services.database.DatabaseServer;
import org.ripv.services.database.DatabaseTarget;
import org.ripv.services.database.EmbeddedDatabase;
import org.ripv.services.database.QueryLimits;

/**
 * {@code ?cancel} through the whole stack against embedded Derby: a queued request is withdrawn,
 * a running cross-join is stopped, and the MailBox serves the next query at once.
 */
class CancelEndToEndTest {
    static final Duration T = Duration.ofSeconds(60);
    static final String DB = "<DatabaseServer>::<localhost>TTY1";
    static final String SLOW = "SELECT COUNT(*) FROM sensor_data a, sensor_data b, sensor_data c";

    @TempDir
    static Path dir;
    static TestSystem sys;

    @BeforeAll
    static void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators").user("bob", "operators").user("olga", "observers");
        DatabaseTarget db = EmbeddedDatabase.prepare(dir.resolve("database"), "TTY1");
        // a query timeout far beyond the test: only the cancel can end the cross-join in time
        database = new DatabaseServer("localhost", List.of(db), new QueryLimits(1000, 600, QueryLimits.DEFAULT_MAX_RESULT_CHARS));
        sys.register(database);
    }

    static DatabaseServer database;

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    private static void awaitBusy(ClientSocketHandler c) throws Exception {
        long end = System.nanoTime() + T.toNanos();
        while (System.nanoTime() < end) {
            if (c.call("", "?status " + DB, Priority.NORMAL, T, null).footer().replyText().contains("busy")) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError(DB + " never became busy");
    }

    @Test
    void aWorkflowStepThatRunsPastItsTimeoutFailsAndIsCancelled() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        Path wf = dir.resolve("slow.wf");
        java.nio.file.Files.writeString(wf, "send \"" + SLOW + "\" timeout=2s\n");
        alice.upload(wf, "slow.wf", null);
        assertThat(alice.call("", "?queue add " + DB + " slow.wf", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
        long t0 = System.nanoTime();
        org.ripv.service.ConsoleTap.publish(database, org.ripv.messages.ConsoleEntry.event(DB,
                org.ripv.messages.VehicleEvent.SURFACED, "test", null, null));
        String receipt = "";
        long end = System.nanoTime() + T.toNanos();
        while (System.nanoTime() < end && !receipt.contains("result: FAILED")) {
            receipt = alice.call("", "?receipts " + DB, Priority.NORMAL, T, null).footer().replyText();
            Thread.sleep(100);
        }
        assertThat(receipt).contains("result: FAILED").contains("within 2 s (timeout=); asked the service to cancel it");
        // the cancel reached Derby: the MailBox is free again long before the 600 s query timeout
        OutgoingServerMessage next = alice.call(DB, "SELECT COUNT(*) FROM mission", Priority.NORMAL, T, null);
        assertThat(next.status()).as(next.footer().replyText()).isEqualTo(Status.OK);
        assertThat(Duration.ofNanos(System.nanoTime() - t0)).isLessThan(Duration.ofSeconds(30));
        assertThat(alice.call("", "?queue " + DB, Priority.NORMAL, T, null).footer().replyText()).contains("failed at step 1/1");
        alice.call("", "?queue clear " + DB, Priority.NORMAL, T, null);
    }

    @Test
    void aQueuedRequestIsWithdrawnAndARunningQueryIsStopped() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        long slowId = alice.nextId();
        CompletableFuture<OutgoingServerMessage> slow = alice.send(Header.request(slowId, DB, SLOW, Priority.NORMAL), null);
        awaitBusy(alice);
        long queuedId = alice.nextId();
        CompletableFuture<OutgoingServerMessage> queued = alice.send(Header.request(queuedId, DB, "SELECT COUNT(*) FROM mission",
                Priority.NORMAL), null);
        Thread.sleep(200); // let it reach the service's MailBox, behind the cross-join

        // the sender cancels the queued one: it never runs
        OutgoingServerMessage c1 = alice.call("", "?cancel " + queuedId, Priority.NORMAL, T, null);
        assertThat(c1.status()).as(c1.footer().replyText()).isEqualTo(Status.OK);
        assertThat(c1.footer().serviceId()).isEqualTo(Ids.FID_CANCEL);
        assertThat(c1.footer().replyText()).contains("had not started");
        OutgoingServerMessage q = queued.get(10, TimeUnit.SECONDS);
        assertThat(q.footer().errorCode()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(q.footer().replyText()).contains("cancelled by alice before it ran");

        // an observer may not cancel alice's request; an operator (a permit rule allows ?cancel) may
        String clientId = alice.session().clientId();
        ClientSocketHandler olga = sys.login("olga");
        OutgoingServerMessage refused = olga.call("", "?cancel " + slowId + " " + clientId, Priority.NORMAL, T, null);
        assertThat(refused.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(slow.isDone()).isFalse();

        ClientSocketHandler bob = sys.login("bob");
        long t0 = System.nanoTime();
        OutgoingServerMessage c2 = bob.call("", "?cancel " + slowId + " " + clientId, Priority.NORMAL, T, null);
        assertThat(c2.status()).as(c2.footer().replyText()).isEqualTo(Status.OK);
        OutgoingServerMessage s = slow.get(30, TimeUnit.SECONDS);
        assertThat(s.footer().errorCode()).as(s.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(s.footer().replyText()).contains("cancelled by bob");
        assertThat(Duration.ofNanos(System.nanoTime() - t0)).isLessThan(Duration.ofSeconds(30));

        // the query really stopped: the MailBox answers the next one at once
        OutgoingServerMessage next = alice.call(DB, "SELECT COUNT(*) FROM mission", Priority.NORMAL, T, null);
        assertThat(next.status()).as(next.footer().replyText()).isEqualTo(Status.OK);

        // nothing left to cancel
        OutgoingServerMessage none = alice.call("", "?cancel " + slowId, Priority.NORMAL, T, null);
        assertThat(none.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(none.footer().replyText()).contains("is queued or running");
    }
}
