package org.ripv.it.console;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.stream.IntStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.VehicleConsoleService;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.it.TestSystem;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.SessionState;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.ServerConfig;

/** The live console end to end over real sockets and RMI: watchers, state, rights, transcript. */
class ConsoleSessionTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    Path dir;
    TestSystem sys;
    VehicleConsoleService vehicle;
    org.ripv.service.ServiceConnector connector;
    String box;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators").user("olga", "observers").user("eve");
        vehicle = new VehicleConsoleService("localhost", "ru29");
        connector = sys.register(vehicle);
        box = vehicle.mailbox();
    }

    @AfterEach
    void stop() {
        sys.close();
    }

    static OutgoingServerMessage call(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    @Test
    void twoWatchersOneAnObserverSeeTheSameStreamAndTheObserverCannotSend() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler olga = sys.login("olga");
        Pushes a = Pushes.on(alice);
        Pushes o = Pushes.on(olga);
        OutgoingServerMessage w = call(alice, "?watch " + box);
        assertThat(w.status()).isEqualTo(Status.OK);
        assertThat(w.footer().serviceId()).isEqualTo(Ids.FID_WATCH);
        assertThat(call(olga, "?watch " + box).status()).isEqualTo(Status.OK);

        vehicle.event(VehicleEvent.SURFACED, "Glider ru29 at surface", 41.63323, -70.53647);
        for (int i = 0; i < 200; i++) {
            vehicle.line("unsolicited line " + i);
        }
        OutgoingServerMessage said = alice.call(box, "say hello from alice", Priority.NORMAL, T, null);
        assertThat(said.status()).isEqualTo(Status.OK);
        vehicle.event(VehicleEvent.DIVED, "", null, null);

        assertThat(a.await(e -> e.event() == VehicleEvent.DIVED, T)).isTrue();
        assertThat(o.await(e -> e.event() == VehicleEvent.DIVED, T)).isTrue();
        assertThat(o.entries).isEqualTo(a.entries);
        assertThat(a.texts()).containsSubsequence("Glider ru29 at surface", "unsolicited line 0", "unsolicited line 199",
                "say hello from alice", "hello from alice");
        ConsoleEntry command = a.entries.stream().filter(e -> e.kind() == ConsoleEntry.Kind.COMMAND).findFirst().orElseThrow();
        assertThat(command.user()).isEqualTo("alice");
        List<Long> times = a.entries.stream().map(ConsoleEntry::time).toList();
        assertThat(times).isSorted();

        OutgoingServerMessage refused = olga.call(box, "say I am only watching", Priority.NORMAL, T, null);
        assertThat(refused.status()).isEqualTo(Status.ERROR);
        assertThat(refused.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);

        MailboxList boxes = (MailboxList) call(olga, "?mailboxes").footer().result();
        SessionState s = boxes.mailboxes().stream().filter(m -> m.address().equals(box)).findFirst().orElseThrow().session();
        assertThat(s.state()).isEqualTo(SessionState.State.DIVED);
        assertThat(s.calls()).isEqualTo(1);
        assertThat(s.lat()).isEqualTo(41.63323);
        assertThat(s.lon()).isEqualTo(-70.53647);
        assertThat(s.lastContact()).isGreaterThan(0);
        OutgoingServerMessage status = call(alice, "?status " + box);
        assertThat(((MailboxStatus) status.footer().result()).session().state()).isEqualTo(SessionState.State.DIVED);
        assertThat(status.footer().replyText()).contains("dived", "1 call");
    }

    @Test
    void watchingAndHistoryNeedTheReadRight() throws Exception {
        ClientSocketHandler eve = sys.login("eve");
        OutgoingServerMessage w = call(eve, "?watch " + box);
        assertThat(w.status()).isEqualTo(Status.ERROR);
        assertThat(w.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(call(eve, "?history " + box).footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(sys.server().console().watcherCount()).isZero();
        assertThat(call(eve, "?watch not-an-address").footer().errorCode()).isEqualTo(ErrorCode.UNKNOWN_MAILBOX);
        assertThat(call(eve, "?history " + box + " --last x").footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
    }

    @Test
    void locksAndALostServiceAreEventsAndState() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler olga = sys.login("olga");
        Pushes o = Pushes.on(olga);
        call(olga, "?watch " + box);
        assertThat(call(alice, "?lock " + box + " 60").status()).isEqualTo(Status.OK);
        assertThat(call(alice, "?unlock " + box).status()).isEqualTo(Status.OK);
        assertThat(o.await(e -> e.event() == VehicleEvent.LOCK_RELEASED, T)).isTrue();
        ConsoleEntry taken = o.entries.stream().filter(e -> e.event() == VehicleEvent.LOCK_TAKEN).findFirst().orElseThrow();
        assertThat(taken.user()).isEqualTo("alice");

        vehicle.event(VehicleEvent.SURFACED, "", 41.5, -70.5);
        assertThat(o.await(e -> e.event() == VehicleEvent.SURFACED, T)).isTrue();
        connector.close(); // the service goes away mid-call: the server notices and calls the vehicle lost
        assertThat(o.await(e -> e.event() == VehicleEvent.LINK_LOST, T)).isTrue();
        assertThat(sys.server().console().state(box).state()).isEqualTo(SessionState.State.LOST);
    }

    @Test
    void aLockThatRunsOutIsReleasedWithAnEvent() throws Exception {
        sys.user("bob", "operators");
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler bob = sys.login("bob");
        ClientSocketHandler olga = sys.login("olga");
        Pushes o = Pushes.on(olga);
        call(olga, "?watch " + box);
        // A lock renewed before its end is not released at the first lock's end.
        assertThat(call(alice, "?lock " + box + " 1").status()).isEqualTo(Status.OK);
        assertThat(call(alice, "?lock " + box + " 3").status()).isEqualTo(Status.OK);
        long renewed = System.nanoTime();
        assertThat(call(bob, "?lock " + box + " 60").footer().errorCode()).isEqualTo(ErrorCode.MAILBOX_LOCKED);
        assertThat(o.await(e -> e.event() == VehicleEvent.LOCK_RELEASED, T)).isTrue();
        long held = (System.nanoTime() - renewed) / 1_000_000;
        assertThat(held).isBetween(2_000L, 10_000L); // the 3 s lock, not the 1 s one
        List<ConsoleEntry> released = o.entries.stream().filter(e -> e.event() == VehicleEvent.LOCK_RELEASED).toList();
        assertThat(released).singleElement().satisfies(e -> {
            assertThat(e.user()).isEqualTo("alice");
            assertThat(e.text()).isEqualTo("its time ran out");
        });
        assertThat(o.entries.stream().filter(e -> e.event() == VehicleEvent.LOCK_TAKEN).count()).isEqualTo(2);
        // The lock is really gone: bob takes it; when he unlocks, that is the release, with no second one at its end.
        assertThat(call(bob, "?lock " + box + " 1").status()).isEqualTo(Status.OK);
        assertThat(call(bob, "?unlock " + box).status()).isEqualTo(Status.OK);
        assertThat(o.await(e -> e.event() == VehicleEvent.LOCK_RELEASED && e.user().equals("bob"), T)).isTrue();
        Thread.sleep(1_500);
        assertThat(o.entries.stream().filter(e -> e.event() == VehicleEvent.LOCK_RELEASED).count()).isEqualTo(2);
        assertThat(sys.server().console().history(box, null, 100).entries().stream()
                .filter(e -> e.event() == VehicleEvent.LOCK_RELEASED).map(ConsoleEntry::text))
                .containsExactly("its time ran out", "");
    }

    @Test
    void aServiceRestartedMidCallLeavesTheVehicleLostUntilItsNextCall() throws Exception {
        ClientSocketHandler olga = sys.login("olga");
        Pushes o = Pushes.on(olga);
        call(olga, "?watch " + box);
        vehicle.event(VehicleEvent.SURFACED, "", 41.5, -70.5);
        assertThat(o.await(e -> e.event() == VehicleEvent.SURFACED, T)).isTrue();
        // The same service registers again (a restart: the old instance is gone): the call in progress is lost.
        connector.close();
        VehicleConsoleService restarted = new VehicleConsoleService("localhost", "ru29");
        sys.register(restarted);
        assertThat(o.await(e -> e.event() == VehicleEvent.LINK_LOST, T)).isTrue();
        assertThat(o.entries.stream().filter(e -> e.event() == VehicleEvent.LINK_LOST).findFirst().orElseThrow().text())
                .contains("registered again");
        assertThat(sys.server().console().state(box).state()).isEqualTo(SessionState.State.LOST);
        restarted.event(VehicleEvent.SURFACED, "", 41.6, -70.6);
        assertThat(o.await(e -> e.event() == VehicleEvent.SURFACED && e.lat() == 41.6, T)).isTrue();
        SessionState s = sys.server().console().state(box);
        assertThat(s.state()).isEqualTo(SessionState.State.ON_CALL);
        // Calls are counted per run of the service: the restarted one's first, once the server has
        // squared its calls with the new instance (in the background, after the registration).
        long end = System.nanoTime() + T.toNanos();
        while (sys.server().console().state(box).calls() != 1 && System.nanoTime() < end) {
            Thread.sleep(50);
        }
        assertThat(sys.server().console().state(box).calls()).isEqualTo(1);
    }

    /** Polls {@code ?queue MAILBOX} until its answer contains {@code text}; returns that answer. */
    static String awaitQueue(ClientSocketHandler c, String mailbox, String text, Duration within) throws Exception {
        long end = System.nanoTime() + within.toNanos();
        String q = "";
        while (System.nanoTime() < end) {
            q = call(c, "?queue " + mailbox).footer().replyText();
            if (q.contains(text)) {
                return q;
            }
            Thread.sleep(100);
        }
        throw new AssertionError("?queue never said '" + text + "'; last: " + q);
    }

    @Test
    void aWorkflowOnACallWhoseServiceGoesAwayIsCutAtOnceAndResumesOnTheNextCall() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        Path wf = dir.resolve("wait.wf");
        Files.writeString(wf, "send say first\nwait-for 'go on' timeout=5m\nsend say last\n");
        alice.upload(wf, "wait.wf", null);
        assertThat(call(alice, "?queue add " + box + " wait.wf").footer().replyText()).contains("it runs when the vehicle calls");
        vehicle.event(VehicleEvent.SURFACED, "", 41.5, -70.5);
        awaitQueue(alice, box, "running step 2/3", T);

        // The service dies mid-call: the call is lost for the workflows too, not only for the
        // watchers — the waiting step is cut now (not failed when its 5 minutes are up) ...
        connector.close();
        awaitQueue(alice, box, "cut at step 2/3, resumes on the next call", Duration.ofSeconds(10));
        // ... and a workflow queued now waits for the next call instead of running on a vehicle that is gone.
        assertThat(call(alice, "?queue add " + box + " wait.wf").footer().replyText()).contains("it runs when the vehicle calls");

        VehicleConsoleService back = new VehicleConsoleService("localhost", "ru29");
        sys.register(back);
        back.event(VehicleEvent.SURFACED, "", 41.6, -70.6);
        awaitQueue(alice, box, "running step 2/3", T);
        back.line("go on");
        long end = System.nanoTime() + T.toNanos();
        String receipts = "";
        while (System.nanoTime() < end && !receipts.contains("result: DONE")) {
            receipts = call(alice, "?receipts " + box).footer().replyText();
            Thread.sleep(100);
        }
        // Resumed where it was cut, on the next call: the cut run's receipt, then the resumed one's.
        assertThat(receipts).contains("result: CUT").contains("(resumed at step 2)").contains("result: DONE");
    }

    @Test
    void aSlowWatcherSkipsWithAMarkerWhileTheOthersGetEverything() throws Exception {
        ClientSocketHandler fast = sys.login("alice");
        ClientSocketHandler slow = sys.login("olga");
        Pushes f = Pushes.on(fast);
        CountDownLatch release = new CountDownLatch(1);
        CountDownLatch blocked = new CountDownLatch(1);
        Pushes s = new Pushes() {
            @Override
            public void onReply(OutgoingServerMessage reply) {
                if (reply.footer().serviceId().equals(Ids.FID_CONSOLE)) {
                    blocked.countDown();
                    try {
                        release.await(); // the client's only reader thread stops reading the socket
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                    }
                }
                super.onReply(reply);
            }
        };
        slow.addListener(s);
        call(fast, "?watch " + box);
        call(slow, "?watch " + box);
        String pad = "x".repeat(400);
        int n = 30_000;
        for (int i = 0; i < n; i++) {
            vehicle.line(i + " " + pad);
            if (i % 1000 == 999) {
                // Stay within the service's own publishing queue: wait for the fast watcher.
                String want = i + " " + pad;
                assertThat(f.await(e -> e.text().equals(want), T)).as("line " + i + " reached the fast watcher").isTrue();
            }
        }
        vehicle.line("last");
        assertThat(f.await(e -> e.text().equals("last"), Duration.ofSeconds(60))).isTrue();
        assertThat(blocked.getCount()).isZero();
        // The fast one got everything the service sent, in order, and no marker.
        List<String> got = f.texts().stream().filter(t -> !t.equals("last")).toList();
        assertThat(got.stream().noneMatch(t -> t.contains("lines skipped"))).isTrue();
        assertThat(got).hasSize(n);
        assertThat(got.get(n - 1)).startsWith((n - 1) + " ");
        // The server holds at most a bounded backlog for the slow one.
        assertThat(sys.server().console().backlogTotal()).isLessThanOrEqualTo(2_000);
        release.countDown();
        assertThat(s.await(e -> e.text().equals("last"), Duration.ofSeconds(60))).isTrue();
        ConsoleEntry marker = s.entries.stream().filter(e -> e.text().contains("lines skipped")).findFirst().orElseThrow();
        assertThat(marker.text()).contains("?history " + box + " --since ");
        assertThat(s.batches.stream().mapToLong(ConsoleBatch::skipped).sum()).isGreaterThan(0);
        // What it missed is in the transcript.
        String since = marker.text().replaceAll(".*--since (\\S+) fetches.*", "$1");
        OutgoingServerMessage h = call(slow, "?history " + box + " --since " + since + " --last 5");
        assertThat(h.status()).isEqualTo(Status.OK);
        assertThat(((ConsoleBatch) h.footer().result()).entries()).hasSize(5);
    }

    @Test
    void hostileEntriesAreCutOrIgnored() throws Exception {
        ClientSocketHandler olga = sys.login("olga");
        Pushes o = Pushes.on(olga);
        call(olga, "?watch " + box);
        String other = "<SerialPortServer>::<localhost>ru29";
        Pushes elsewhere = Pushes.on(olga);
        call(olga, "?watch " + other);
        vehicle.publishEntry(ConsoleEntry.line(other, "pretending to be another service's vehicle"));
        vehicle.publishEntry(ConsoleEntry.line("<VehicleConsole>::<localhost>../../etc", "a malformed MailBox"));
        vehicle.publishEntry(ConsoleEntry.line(box, "m".repeat(1_000_000)));
        vehicle.publishEntry(new ConsoleEntry(Long.MAX_VALUE / 2, box, ConsoleEntry.Kind.LINE, "u".repeat(500),
                "from the far future \u0000\u0007\u001b[31m", null, Double.NaN, 1e300));
        vehicle.line("end");
        assertThat(o.await(e -> e.text().equals("end"), T)).isTrue();
        assertThat(o.entries).hasSize(3);
        assertThat(o.entries.get(0).text()).hasSize(4096 + " [cut: 995904 more characters]".length())
                .endsWith("[cut: 995904 more characters]");
        ConsoleEntry future = o.entries.get(1);
        assertThat(future.time()).isBetween(System.currentTimeMillis() - 60_000, System.currentTimeMillis());
        assertThat(future.user()).hasSize(64);
        assertThat(elsewhere.entries.stream().filter(e -> e.mailbox().equals(other))).isEmpty();
        // The junk position is not taken as the vehicle's position; the transcript reads back.
        assertThat(sys.server().console().state(box).hasPosition()).isFalse();
        List<ConsoleEntry> h = ((ConsoleBatch) call(olga, "?history " + box).footer().result()).entries();
        assertThat(h).extracting(ConsoleEntry::text).contains("from the far future \u0000\u0007\u001b[31m", "end");
    }

    @Test
    void aWatcherThatDisconnectsLeavesNothingBehind() throws Exception {
        List<ClientSocketHandler> clients = IntStream.range(0, 20).mapToObj(i -> {
            try {
                ClientSocketHandler c = sys.login("olga");
                call(c, "?watch " + box);
                return c;
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }).toList();
        assertThat(sys.server().console().watcherCount()).isEqualTo(20);
        vehicle.line("before");
        clients.forEach(ClientSocketHandler::close);
        long end = System.nanoTime() + T.toNanos();
        while (sys.server().console().watcherCount() > 0 && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertThat(sys.server().console().watcherCount()).isZero();
        assertThat(sys.server().console().backlogTotal()).isZero();
        vehicle.line("after"); // nobody left to push to: nothing breaks
        ClientSocketHandler c = sys.login("olga");
        assertThat(call(c, "?unwatch " + box).footer().replyText()).contains("was not watching");
    }

    @Test
    void theTranscriptSurvivesARestartAndHistoryReturnsIt() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        Pushes a = Pushes.on(alice);
        call(alice, "?watch " + box);
        vehicle.event(VehicleEvent.SURFACED, "GPS Location: 4137.994 N -7032.188 E", 41.6332, -70.5365);
        for (int i = 0; i < 10; i++) {
            vehicle.line("before restart " + i);
        }
        vehicle.publishEntry(ConsoleEntry.line(box, "a line with \"quotes\", a tab\tand ünïcödé"));
        assertThat(a.await(e -> e.text().contains("quotes"), T)).isTrue();
        ServerConfig config = ServerConfig.forTests(sys.dataDir());
        sys.close();

        sys = TestSystem.start(config);
        ClientSocketHandler c = sys.login("olga");
        OutgoingServerMessage h = call(c, "?history " + box);
        assertThat(h.status()).isEqualTo(Status.OK);
        assertThat(h.footer().serviceId()).isEqualTo(Ids.FID_HISTORY);
        List<ConsoleEntry> all = ((ConsoleBatch) h.footer().result()).entries();
        assertThat(all).extracting(ConsoleEntry::text).contains("before restart 0", "before restart 9",
                "a line with \"quotes\", a tab\tand ünïcödé");
        assertThat(all.get(0).event()).isEqualTo(VehicleEvent.SURFACED);
        assertThat(all.get(0).lat()).isEqualTo(41.6332);
        List<ConsoleEntry> last2 = ((ConsoleBatch) call(c, "?history " + box + " --last 2").footer().result()).entries();
        assertThat(last2).extracting(ConsoleEntry::text).containsExactly("before restart 9",
                "a line with \"quotes\", a tab\tand ünïcödé");
        Instant mid = Instant.ofEpochMilli(all.get(5).time());
        List<ConsoleEntry> since = ((ConsoleBatch) call(c, "?history " + box + " --since " + mid).footer().result()).entries();
        assertThat(since).allMatch(e -> e.time() >= mid.toEpochMilli()).isNotEmpty();
        // The state survived too: on call, one call, at the last position.
        SessionState s = sys.server().console().state(box);
        assertThat(s.state()).isEqualTo(SessionState.State.ON_CALL);
        assertThat(s.calls()).isEqualTo(1);
        assertThat(s.lat()).isEqualTo(41.6332);
        try (var files = Files.walk(sys.dataDir().resolve("transcripts"))) {
            assertThat(files.filter(p -> p.toString().endsWith(".jsonl")).count()).isEqualTo(1);
        }

        // The service comes back as a new instance (it restarted with the server): nobody saw that
        // call end, and this instance cannot be on it, so the call is lost — not "on call" forever.
        Pushes o = Pushes.on(c);
        call(c, "?watch " + box);
        VehicleConsoleService restarted = new VehicleConsoleService("localhost", "ru29");
        sys.register(restarted);
        assertThat(o.await(e -> e.event() == VehicleEvent.LINK_LOST, T)).isTrue();
        assertThat(o.entries.stream().filter(e -> e.event() == VehicleEvent.LINK_LOST).findFirst().orElseThrow().text())
                .isEqualTo("the service restarted during the call");
        assertThat(sys.server().console().state(box).state()).isEqualTo(SessionState.State.LOST);
    }
}
