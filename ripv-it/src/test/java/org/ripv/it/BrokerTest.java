package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.client.handlers.RipvErrorException;
import org.ripv.examples.ClockService;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;
import org.ripv.service.RIPVService;
import org.ripv.service.Reply;

/** The broker end to end: client socket → server → RMI → service → RMI → server → client. */
class BrokerTest {
    static final Duration T = Duration.ofSeconds(20);
    static final String CLOCK = "<ClockService>::<localhost>TTY1";

    @TempDir
    Path dir;
    TestSystem sys;

    @BeforeEach
    void start() throws Exception {
        sys = TestSystem.start(dir);
        sys.user("alice", "operators").user("olga", "observers");
        sys.register(new ClockService("localhost"));
    }

    @AfterEach
    void stop() {
        sys.close();
    }

    @Test
    void commandTravelsToTheServiceAndTheReplyComesBack() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        OutgoingServerMessage r = c.call(CLOCK, "echo over the sea", Priority.NORMAL, T, null);
        assertThat(r.status()).isEqualTo(Status.OK);
        assertThat(r.footer().replyText()).isEqualTo("over the sea");
        assertThat(r.footer().serviceId()).isEqualTo(ClockService.SID);
        assertThat(r.footer().route()).containsExactly("<ClockService>::<localhost>", "RIPVServer");
        assertThat(r.header().origin().user()).isEqualTo("alice");
    }

    @Test
    void everyServerCommandAnswersWithItsFid() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        assertThat(fid(c, "?dldir")).isEqualTo(Ids.FID_DLDIR);
        assertThat(fid(c, "?uldir")).isEqualTo(Ids.FID_ULDIR);
        assertThat(fid(c, "?dlfiles")).isEqualTo(Ids.FID_DLFILES);
        assertThat(fid(c, "?ulfiles")).isEqualTo(Ids.FID_ULFILES);
        assertThat(fid(c, "?mailboxes")).isEqualTo(Ids.FID_MAILBOXES);
        assertThat(fid(c, "?status " + CLOCK)).isEqualTo(Ids.FID_STATUS);
        assertThat(fid(c, "?services")).isEqualTo(Ids.FID_SERVICES);

        OutgoingServerMessage dl = c.call("", "?dldir", Priority.NORMAL, T, null);
        assertThat(dl.footer().replyText()).isEqualTo(sys.downloadDir().toString());
        assertThat(c.call("", "?ulfiles", Priority.NORMAL, T, null).footer().result()).isInstanceOf(FileListing.class);
        ServiceList services = (ServiceList) c.call("", "?services", Priority.NORMAL, T, null).footer().result();
        assertThat(services.services()).extracting(d -> d.name()).containsExactly("<ClockService>::<localhost>");
        MailboxList boxes = (MailboxList) c.call("", "?mailboxes", Priority.NORMAL, T, null).footer().result();
        assertThat(boxes.mailboxes()).extracting(MailboxStatus::address).containsExactly(CLOCK);
        MailboxStatus s = (MailboxStatus) c.call("", "?status " + CLOCK, Priority.NORMAL, T, null).footer().result();
        assertThat(s.available()).isTrue();

        OutgoingServerMessage unknown = c.call("", "?frobnicate", Priority.NORMAL, T, null);
        assertThat(unknown.status()).isEqualTo(Status.ERROR);
        assertThat(unknown.footer().errorCode()).isEqualTo(ErrorCode.UNKNOWN_COMMAND);
        assertThat(unknown.footer().replyText()).contains("?frobnicate");
    }

    private static String fid(ClientSocketHandler c, String command) throws Exception {
        OutgoingServerMessage r = c.call("", command, Priority.NORMAL, T, null);
        assertThat(r.status()).as(command + ": " + r.footer().replyText()).isEqualTo(Status.OK);
        return r.footer().serviceId();
    }

    @Test
    void urgentOvertakesQueuedNormalsInABusyMailbox() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        List<String> order = new CopyOnWriteArrayList<>();
        c.addListener(r -> {
            if (r.status().isFinal() && r.header().mailboxAddress().equals(CLOCK)) {
                order.add(r.footer().replyText());
            }
        });
        // Long enough that all 101 requests are queued behind it even on a loaded machine.
        CompletableFuture<OutgoingServerMessage> busy = c.send(CLOCK, "sleep 3000", Priority.NORMAL, null);
        awaitBusy(c);
        List<CompletableFuture<OutgoingServerMessage>> all = new ArrayList<>();
        for (int i = 0; i < 100; i++) {
            all.add(c.send(CLOCK, "echo normal " + i, Priority.NORMAL, null));
        }
        all.add(c.send(CLOCK, "echo URGENT", Priority.URGENT, null));
        busy.get(20, TimeUnit.SECONDS);
        for (CompletableFuture<OutgoingServerMessage> f : all) {
            assertThat(f.get(20, TimeUnit.SECONDS).status()).isEqualTo(Status.OK);
        }
        assertThat(order.get(0)).startsWith("slept");
        assertThat(order.get(1)).isEqualTo("URGENT");
        assertThat(order.subList(2, 102)).containsExactly(
                java.util.stream.IntStream.range(0, 100).mapToObj(i -> "normal " + i).toArray(String[]::new));
    }

    private static void awaitBusy(ClientSocketHandler c) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < end) {
            MailboxStatus s = (MailboxStatus) c.call("", "?status " + CLOCK, Priority.NORMAL, T, null).footer().result();
            if (s.busy()) {
                return;
            }
            Thread.sleep(20);
        }
        throw new AssertionError("the mailbox never became busy");
    }

    /** A service whose one command notices if another runs inside it at the same time. */
    static final class OverlapService extends RIPVService {
        final AtomicInteger inside = new AtomicInteger();
        final AtomicInteger overlaps = new AtomicInteger();

        OverlapService() {
            super("OverlapService", "100200", "localhost");
        }

        @Override
        protected void open() {
            openMailBox("TTY1", request -> {
                if (inside.incrementAndGet() != 1) {
                    overlaps.incrementAndGet();
                }
                Thread.sleep(1);
                inside.decrementAndGet();
                return Reply.ok(request.command());
            });
        }
    }

    @Test
    void twoClientsHammeringOneMailboxNeverInterleaveInsideACommand() throws Exception {
        OverlapService svc = new OverlapService();
        sys.register(svc);
        ClientSocketHandler a = sys.login("alice");
        ClientSocketHandler b = sys.login("alice");
        List<CompletableFuture<OutgoingServerMessage>> all = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            all.add(a.send("<OverlapService>::<localhost>TTY1", "a" + i, Priority.NORMAL, null));
            // mixed priorities, urgent ones within what one client may have waiting (WaitingRequests.MAX_RAISED, issue 33)
            all.add(b.send("<OverlapService>::<localhost>TTY1", "b" + i, i % 10 == 0 ? Priority.URGENT : Priority.NORMAL, null));
        }
        for (CompletableFuture<OutgoingServerMessage> f : all) {
            assertThat(f.get(60, TimeUnit.SECONDS).status()).isEqualTo(Status.OK);
        }
        assertThat(svc.overlaps.get()).isZero();
    }

    @Test
    void tenThousandMessagesOnOneConnectionAreAllAccepted() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        int n = 10_000;
        List<CompletableFuture<OutgoingServerMessage>> window = new ArrayList<>();
        int ok = 0;
        for (int i = 0; i < n; i++) {
            window.add(c.send(i % 2 == 0 ? "" : CLOCK, i % 2 == 0 ? "?ping" : "echo " + i, Priority.NORMAL, null));
            if (window.size() == 500 || i == n - 1) {
                for (CompletableFuture<OutgoingServerMessage> f : window) {
                    if (f.get(60, TimeUnit.SECONDS).status() == Status.OK) {
                        ok++;
                    }
                }
                window.clear();
            }
        }
        assertThat(ok).isEqualTo(n);
        assertThat(c.isOpen()).isTrue();
    }

    @Test
    void wrongPasswordAndCommandsBeforeLogInAreRefused() throws Exception {
        ClientSocketHandler c = sys.connect();
        OutgoingServerMessage before = c.call(CLOCK, "time", Priority.NORMAL, T, null);
        assertThat(before.status()).isEqualTo(Status.ERROR);
        assertThat(before.footer().errorCode()).isEqualTo(ErrorCode.NOT_LOGGED_IN);
        OutgoingServerMessage files = c.call("", "?ulfiles", Priority.NORMAL, T, null);
        assertThat(files.footer().errorCode()).isEqualTo(ErrorCode.NOT_LOGGED_IN);
        try {
            c.login("alice", "wrong password".toCharArray());
            throw new AssertionError("logged in with a wrong password");
        } catch (RipvErrorException e) {
            assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(e.getMessage()).contains("wrong user name or password");
        }
        try {
            c.login("nobody", TestSystem.PASSWORD.toCharArray());
            throw new AssertionError("logged in as an unknown user");
        } catch (RipvErrorException e) {
            assertThat(e.code()).isEqualTo(ErrorCode.FORBIDDEN);
        }
        c.login("alice", TestSystem.PASSWORD.toCharArray());
        assertThat(c.call(CLOCK, "time", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
    }

    @Test
    void secondTeamIsRefusedWhatItsRulesForbidAndAllowedWhatTheyPermit() throws Exception {
        sys.rules("allow @operators * * *",
                "allow @observers ClockService * time",
                "deny  @observers ClockService * echo *",
                "deny  @observers ClockService * *");
        ClientSocketHandler olga = sys.login("olga");
        assertThat(olga.call(CLOCK, "time", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
        OutgoingServerMessage refused = olga.call(CLOCK, "echo GO", Priority.NORMAL, T, null);
        assertThat(refused.status()).isEqualTo(Status.ERROR);
        assertThat(refused.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(refused.footer().replyText()).contains("olga").contains("echo GO").contains("deny  @observers ClockService * echo *");
        ClientSocketHandler alice = sys.login("alice");
        assertThat(alice.call(CLOCK, "echo GO", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
    }

    @Test
    void anOperatorLockKeepsOthersOutUntilReleased() throws Exception {
        ClientSocketHandler alice = sys.login("alice");
        sys.user("bob", "operators");
        ClientSocketHandler bob = sys.login("bob");
        assertThat(alice.call("", "?lock " + CLOCK + " 60", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
        OutgoingServerMessage refused = bob.call(CLOCK, "time", Priority.NORMAL, T, null);
        assertThat(refused.footer().errorCode()).isEqualTo(ErrorCode.MAILBOX_LOCKED);
        assertThat(refused.footer().replyText()).contains("alice");
        MailboxStatus s = (MailboxStatus) bob.call("", "?status " + CLOCK, Priority.NORMAL, T, null).footer().result();
        assertThat(s.lockedBy()).isEqualTo("alice");
        assertThat(alice.call(CLOCK, "time", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
        assertThat(bob.call("", "?unlock " + CLOCK, Priority.NORMAL, T, null).footer().errorCode()).isEqualTo(ErrorCode.MAILBOX_LOCKED);
        assertThat(alice.call("", "?unlock " + CLOCK, Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
        assertThat(bob.call(CLOCK, "time", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
    }

    @Test
    void unknownMailboxesAndServicesGetClearErrors() throws Exception {
        ClientSocketHandler c = sys.login("alice");
        OutgoingServerMessage noService = c.call("<Nope>::<localhost>TTY1", "time", Priority.NORMAL, T, null);
        assertThat(noService.footer().errorCode()).isEqualTo(ErrorCode.UNKNOWN_SERVICE);
        OutgoingServerMessage noBox = c.call("<ClockService>::<localhost>COM9", "time", Priority.NORMAL, T, null);
        assertThat(noBox.footer().errorCode()).isEqualTo(ErrorCode.UNKNOWN_MAILBOX);
        assertThat(noBox.footer().replyText()).contains("COM9");
        OutgoingServerMessage malformed = c.call("not a mailbox", "time", Priority.NORMAL, T, null);
        assertThat(malformed.footer().errorCode()).isEqualTo(ErrorCode.UNKNOWN_MAILBOX);
    }
}
