package org.ripv.service;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.IncomingServiceMessage;
import org.ripv.messages.OutgoingServiceMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;

/** The service side of ?cancel: RIPVService.cancel reaches the running CommandHandler, never another request. */
class CancelTest {
    final LinkedBlockingQueue<OutgoingServiceMessage> replies = new LinkedBlockingQueue<>();
    final CountDownLatch started = new CountDownLatch(1);
    final CountDownLatch stop = new CountDownLatch(1);
    String mailbox;

    final class Slow extends RIPVService {
        Slow() {
            super("SlowService", "100200", "localhost");
        }

        @Override
        protected void open() {
            mailbox = openMailBox("ONE", new CommandHandler() {
                @Override
                public Reply execute(Request r) throws Exception {
                    if (r.command().equals("quick")) {
                        return Reply.ok("quick done");
                    }
                    started.countDown();
                    if (!stop.await(30, TimeUnit.SECONDS)) {
                        return Reply.ok("finished on its own");
                    }
                    return Reply.error(ErrorCode.DEVICE_ERROR, "stopped half way");
                }

                @Override
                public boolean cancel(Request running) {
                    if (running.command().equals("uncancellable")) {
                        return false;
                    }
                    stop.countDown();
                    return true;
                }
            }).toString();
        }
    }

    final Slow service = new Slow();

    @AfterEach
    void close() {
        stop.countDown();
        service.stop();
    }

    private IncomingServiceMessage request(long id, String body) {
        return new IncomingServiceMessage(new Header(id, new IdBadge("100001", "alice"), java.util.List.of(), "", mailbox, body,
                Priority.NORMAL, null));
    }

    @Test
    void aRunningRequestIsCancelledAndItsErrorSaysCancelled() throws Exception {
        service.replyTo(replies::add);
        service.start();
        service.accept(request(1, "slow"));
        assertThat(started.await(10, TimeUnit.SECONDS)).isTrue();
        service.accept(request(2, "quick"));
        service.cancel(mailbox, "100002", 1); // another client's request #1: not the running one
        assertThat(stop.getCount()).as("the running request of client 100001 is not stopped").isEqualTo(1);
        assertThat(service.cancel("<SlowService>::<localhost>TWO", "100001", 1)).isFalse();
        assertThat(service.cancel(mailbox, "100001", 1)).isTrue();
        OutgoingServiceMessage first = replies.poll(10, TimeUnit.SECONDS);
        assertThat(first.header().messageId()).isEqualTo(1);
        assertThat(first.footer().errorCode()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(first.footer().replyText()).isEqualTo("stopped half way");
        OutgoingServiceMessage second = replies.poll(10, TimeUnit.SECONDS);
        assertThat(second.header().messageId()).isEqualTo(2);
        assertThat(second.status()).as("the next request is not touched by the cancel").isEqualTo(Status.OK);
    }

    @Test
    void aCancelThatOvertakesItsRequestStopsItBeforeItRuns() throws Exception {
        service.replyTo(replies::add);
        service.start();
        service.accept(request(1, "slow"));
        assertThat(started.await(10, TimeUnit.SECONDS)).isTrue();
        // #2 waits in the MailBox; #3 is still on its way from the server when its cancel comes.
        service.accept(request(2, "quick"));
        assertThat(service.cancel(mailbox, "100001", 2)).as("waiting: it will not run").isTrue();
        assertThat(service.cancel(mailbox, "100001", 3)).as("not here yet: it will not run").isTrue();
        service.accept(request(3, "quick"));
        service.accept(request(4, "quick"));
        assertThat(service.cancel(mailbox, "100001", 1)).isTrue();
        List<OutgoingServiceMessage> got = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            got.add(replies.poll(10, TimeUnit.SECONDS));
        }
        assertThat(got).extracting(r -> r.header().messageId()).containsExactly(1L, 2L, 3L, 4L);
        assertThat(got.get(0).footer().errorCode()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(got.subList(1, 3)).allSatisfy(r -> {
            assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.CANCELLED);
            assertThat(r.footer().replyText()).isEqualTo("'quick' was cancelled before it ran");
        });
        assertThat(got.get(3).status()).as("the request after them runs").isEqualTo(Status.OK);
        assertThat(got.get(3).footer().replyText()).isEqualTo("quick done");
        assertThat(service.cancel(mailbox, "100001", 4)).as("it ran and ended: nothing left to cancel").isFalse();
        assertThat(service.cancel(mailbox, "100001", 2)).as("answered CANCELLED already").isFalse();
    }

    @Test
    void aHandlerThatCannotStopSaysSoAndTheRequestEndsNormally() throws Exception {
        service.replyTo(replies::add);
        service.start();
        service.accept(request(1, "uncancellable"));
        assertThat(started.await(10, TimeUnit.SECONDS)).isTrue();
        assertThat(service.cancel(mailbox, "100001", 1)).isFalse();
        stop.countDown();
        OutgoingServiceMessage r = replies.poll(10, TimeUnit.SECONDS);
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.DEVICE_ERROR);
    }

    @Test
    void aFloodOfCancelsForRequestsThatNeverComeKeepsOnlyTheNewestAndTheServiceServesOn() throws Exception {
        service.replyTo(replies::add);
        service.start();
        // A client (or a server gone wrong) names 10,000 requests that never come: only the newest
        // MAX_CANCELLED_AHEAD are kept, so memory stays bounded and an old id is free to run.
        int flood = 10_000;
        for (long id = 1; id <= flood; id++) {
            assertThat(service.cancel(mailbox, "100001", id)).isTrue();
        }
        long oldestKept = flood - ServiceTaskManager.MAX_CANCELLED_AHEAD + 1;
        service.accept(request(1, "quick"));
        service.accept(request(oldestKept - 1, "quick"));
        service.accept(request(oldestKept, "quick"));
        service.accept(request(flood, "quick"));
        List<OutgoingServiceMessage> got = new ArrayList<>();
        for (int i = 0; i < 4; i++) {
            got.add(replies.poll(10, TimeUnit.SECONDS));
        }
        assertThat(got).extracting(r -> r.header().messageId()).containsExactly(1L, oldestKept - 1, oldestKept, (long) flood);
        assertThat(got.subList(0, 2)).as("forgotten: they run").allSatisfy(r -> {
            assertThat(r.status()).isEqualTo(Status.OK);
            assertThat(r.footer().replyText()).isEqualTo("quick done");
        });
        assertThat(got.subList(2, 4)).as("the newest kept: cancelled before they ran").allSatisfy(r ->
                assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.CANCELLED));
    }
}
