package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Random;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.client.handlers.ClientSocketHandler;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;
import org.ripv.service.ConsoleTap;
import org.ripv.services.serial.LinkSettings;
import org.ripv.services.serial.SerialPortServer;
import org.ripv.services.simulator.GliderSimulator;

/**
 * Issue 12 end to end: the real server, the SerialPortServer over RMI, the glider simulator on
 * TCP, clients over sockets. The vehicle's call events travel the real console path (RMI
 * {@code console}) from the service, as issue 11's link code will send them.
 */
class WorkflowEndToEndTest {
    static final Duration T = Duration.ofSeconds(60);
    static final Pattern FILE = Pattern.compile("file (\\S+) (\\d+) bytes sha256 ([0-9a-f]{64})");

    @TempDir
    Path dir;
    TestSystem sys;
    GliderSimulator glider;
    SerialPortServer serial;
    String mb;

    @AfterEach
    void stop() {
        if (sys != null) {
            sys.close();
        }
        if (glider != null) {
            glider.close();
        }
    }

    private void start() throws Exception {
        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(3), SerialEndToEndTest.YMODEM);
        int port = glider.listen(0);
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators").user("bob", "operators").user("olga", "observers");
        register("tcp://127.0.0.1:" + port);
    }

    private void register(String device) throws Exception {
        LinkSettings link = LinkSettings.defaults(device).withIdleTimeout(Duration.ofSeconds(1))
                .withReconnectEvery(Duration.ofMillis(300)).withYmodem(SerialEndToEndTest.YMODEM);
        serial = new SerialPortServer("localhost", List.of(link), null, false, dir.resolve("work"));
        sys.register(serial);
        mb = "<SerialPortServer>::<localhost>" + serial.handles().get(0);
    }

    private static OutgoingServerMessage cmd(ClientSocketHandler c, String body) throws Exception {
        return c.call("", body, Priority.NORMAL, T, null);
    }

    private static String ok(ClientSocketHandler c, String body) throws Exception {
        OutgoingServerMessage r = cmd(c, body);
        assertThat(r.status()).as(body + " -> " + r.footer().replyText()).isEqualTo(Status.OK);
        return r.footer().replyText();
    }

    private void upload(ClientSocketHandler c, String name, byte[] content) throws Exception {
        Path local = dir.resolve("local").resolve(name);
        Files.createDirectories(local.getParent());
        Files.write(local, content);
        c.upload(local, name, null);
    }

    private void upload(ClientSocketHandler c, String name, String text) throws Exception {
        upload(c, name, text.getBytes(StandardCharsets.UTF_8));
    }

    private void event(VehicleEvent e) throws Exception {
        ConsoleTap.publish(serial, ConsoleEntry.event(mb, e, "test", null, null));
    }

    private void line(String text) throws Exception {
        ConsoleTap.publish(serial, ConsoleEntry.line(mb, text));
    }

    /** Waits until a server command's reply satisfies a condition (the runner works on its own thread). */
    private static String await(ClientSocketHandler c, String body, Predicate<String> done) throws Exception {
        long end = System.nanoTime() + T.toNanos();
        String last = "";
        while (System.nanoTime() < end) {
            last = cmd(c, body).footer().replyText();
            if (done.test(last)) {
                return last;
            }
            Thread.sleep(100);
        }
        throw new AssertionError("gave up waiting on '" + body + "'; last reply:\n" + last);
    }

    /** A receipt that says how its run ended. */
    static boolean ended(String receipts) {
        return receipts.matches("(?s).*result: (DONE|FAILED|CUT).*");
    }

    private static int count(String text, String what) {
        int n = 0;
        for (int i = text.indexOf(what); i >= 0; i = text.indexOf(what, i + 1)) {
            n++;
        }
        return n;
    }

    private static String sha256(byte[] b) throws Exception {
        return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(b));
    }

    @Test
    void aWorkflowQueuedWhileDivedRunsOnTheNextCallAndLeavesAReceipt() throws Exception {
        start();
        byte[] a = new byte[20_000];
        byte[] b = new byte[33_333];
        new Random(1).nextBytes(a);
        new Random(2).nextBytes(b);
        Files.write(glider.directory().resolve("01230000.SBD"), a);
        Files.write(glider.directory().resolve("01230001.SBD"), b);
        byte[] mission = "waypoints 41.5 -70.6\n".repeat(200).getBytes(StandardCharsets.US_ASCII);
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "goto_l10.ma", mission);
        upload(alice, "fetch.wf", """
                # the first call's work
                send dir expect=SBD
                ymodem:get *.SBD
                ymodem:put goto_l10.ma
                notify "ru29 done"
                """);

        String queued = ok(alice, "?queue add " + mb + " fetch.wf");
        assertThat(queued).contains("queued workflow 1 'fetch.wf' (4 step(s), once)");
        assertThat(ok(alice, "?queue " + mb)).contains("fetch.wf").contains("queued").contains("alice");
        assertThat(ok(alice, "?receipts " + mb)).contains("no workflow receipts");

        event(VehicleEvent.SURFACED);
        String receipt = await(alice, "?receipts " + mb, WorkflowEndToEndTest::ended);
        assertThat(receipt).as(receipt).contains("result: DONE").contains("step 1/4 (line 2) dir: OK")
                .contains("step 2/4 (line 3) ymodem:get *.SBD: OK").contains("step 3/4 (line 4) ymodem:put goto_l10.ma: OK")
                .contains("step 4/4 (line 5) notify ru29 done: OK");
        List<String[]> files = new ArrayList<>();
        Matcher m = FILE.matcher(receipt);
        while (m.find()) {
            files.add(new String[] {m.group(1), m.group(2), m.group(3)});
        }
        assertThat(files).hasSize(2);
        for (String[] f : files) {
            byte[] stored = Files.readAllBytes(sys.downloadDir().resolve(f[0]));
            assertThat(stored).isEqualTo(f[0].endsWith("/01230000.SBD") ? a : b);
            assertThat(f[1]).isEqualTo(Long.toString(stored.length));
            assertThat(f[2]).isEqualTo(sha256(stored));
        }
        assertThat(Files.readAllBytes(glider.directory().resolve("goto_l10.ma"))).isEqualTo(mission);
        // the receipt is in the vehicle's transcript too, files and SHA-256s included
        String history = await(alice, "?history " + mb, h -> h.contains("result: DONE"));
        assertThat(history).contains("receipt: workflow 1 'fetch.wf' of alice").contains("step 2/4 (line 3) ymodem:get *.SBD: OK");
        for (String[] f : files) {
            assertThat(history).contains("file " + f[0] + " " + f[1] + " bytes sha256 " + f[2]);
        }
        // once: gone from the queue, and the lock it held is free again
        assertThat(await(alice, "?queue " + mb, q -> q.contains("empty"))).contains("empty");
        assertThat(ok(alice, "?status " + mb)).doesNotContain("locked");

        event(VehicleEvent.DIVED);
        // an every-call workflow fetches only what is new: nothing on the second call, the new file on the third
        upload(alice, "every.wf", "workflow every-call\nymodem:get *.SBD\n");
        ok(alice, "?queue add " + mb + " every.wf");
        event(VehicleEvent.SURFACED);
        String second = await(alice, "?receipts " + mb + " --last 1", r -> r.contains("'every.wf'") && r.contains("result: DONE"));
        assertThat(second).contains("nothing new: all 2 matching file(s) were fetched before");
        event(VehicleEvent.DIVED);
        byte[] c = new byte[1234];
        new Random(3).nextBytes(c);
        Files.write(glider.directory().resolve("01230002.SBD"), c);
        event(VehicleEvent.SURFACED);
        String third = await(alice, "?receipts " + mb + " --last 1", r -> r.contains("run 2") && r.contains("result: DONE"));
        assertThat(third).contains("/01230002.SBD 1234 bytes sha256 " + sha256(c)).contains("2 file(s) skipped");
        assertThat(ok(alice, "?queue " + mb)).contains("every.wf").contains("every-call");
    }

    @Test
    void aWorkflowOfAThousandStepsRunsToTheEnd() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        StringBuilder wf = new StringBuilder("# a long night's checklist\n");
        for (int i = 1; i <= 1000; i++) {
            wf.append(i % 100 == 0 ? "notify \"step " + i + "\"\n" : "send dir\n");
        }
        upload(alice, "long.wf", wf.toString());
        assertThat(ok(alice, "?queue add " + mb + " long.wf")).contains("(1000 step(s), once)");
        event(VehicleEvent.SURFACED);
        String receipt = await(alice, "?receipts " + mb, WorkflowEndToEndTest::ended);
        assertThat(receipt).contains("result: DONE").contains("step 1000/1000 (line 1001) notify step 1000: OK")
                .contains("step 999/1000 (line 1000) dir: OK");
        assertThat(count(receipt, ": OK in ")).isEqualTo(1000);
    }

    @Test
    void aBadWorkflowIsRefusedWholeWithLineAndReasonAndRightsApply() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "bad.wf", "send dir\nymodem:put nothere.bin\n");
        OutgoingServerMessage r = cmd(alice, "?queue add " + mb + " bad.wf");
        assertThat(r.footer().errorCode()).isEqualTo(ErrorCode.BAD_REQUEST);
        assertThat(r.footer().serviceId()).isEqualTo(Ids.FID_QUEUE);
        assertThat(r.footer().replyText()).contains("bad.wf:2: ymodem:put nothere.bin: no such file in the upload store");
        upload(alice, "regex.wf", "send dir expect='(('\n");
        assertThat(cmd(alice, "?queue add " + mb + " regex.wf").footer().replyText()).contains("regex.wf:1: bad expect regex");
        assertThat(cmd(alice, "?queue add " + mb + " missing.wf").footer().errorCode()).isEqualTo(ErrorCode.BAD_FILE_NAME);
        assertThat(ok(alice, "?queue " + mb)).contains("empty");

        // an observer may not queue a workflow that sends GO, nor remove alice's
        ClientSocketHandler olga = sys.login("olga");
        upload(alice, "go.wf", "send GO\n");
        sys.rules("allow @operators * * *", "allow @observers RIPVServer * ?upload*", "allow @observers RIPVServer * ?queue add *",
                "allow @observers SerialPortServer * dir*", "allow @observers SerialPortServer * ?read",
                "deny @observers SerialPortServer * *");
        OutgoingServerMessage refused = cmd(olga, "?queue add " + mb + " go.wf");
        assertThat(refused.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(refused.footer().replyText()).contains("go.wf:1").contains("may not send 'GO'");
        ok(alice, "?queue add " + mb + " go.wf");
        OutgoingServerMessage notHers = cmd(olga, "?queue remove " + mb + " 1");
        assertThat(notHers.footer().errorCode()).isEqualTo(ErrorCode.FORBIDDEN);
        assertThat(notHers.footer().replyText()).contains("belongs to alice");
        // a vehicle that never calls: the workflow stays queued, visible, and can be removed
        assertThat(ok(olga, "?queue " + mb)).contains("go.wf");
        assertThat(ok(alice, "?queue remove " + mb + " 1")).contains("removed workflow 1");
        assertThat(ok(alice, "?queue " + mb)).contains("empty");
    }

    @Test
    void theQueueAndTheReceiptsNeedTheReadRightOnTheMailBox() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "dir.wf", "send dir\n");
        ok(alice, "?queue add " + mb + " dir.wf");
        ClientSocketHandler olga = sys.login("olga");
        // olga may upload and queue in general, but not read this vehicle
        sys.rules("allow @operators * * *", "allow @observers RIPVServer * ?queue*", "allow @observers RIPVServer * ?receipts*",
                "allow @observers SerialPortServer * dir*", "deny @observers SerialPortServer * *");
        for (String body : List.of("?queue " + mb, "?receipts " + mb, "?receipts " + mb + " --last 3",
                "?queue add " + mb + " dir.wf", "?queue remove " + mb + " 1", "?queue clear " + mb)) {
            OutgoingServerMessage r = cmd(olga, body);
            assertThat(r.footer().errorCode()).as(body).isEqualTo(ErrorCode.FORBIDDEN);
            assertThat(r.footer().replyText()).as(body).contains("may not read " + mb);
        }
        assertThat(ok(alice, "?queue " + mb)).contains("dir.wf"); // nothing was changed
        sys.rules("allow @operators * * *", "allow @observers RIPVServer * ?queue*", "allow @observers RIPVServer * ?receipts*",
                "allow @observers SerialPortServer * ?read", "deny @observers SerialPortServer * *");
        assertThat(ok(olga, "?queue " + mb)).contains("dir.wf");
        assertThat(ok(olga, "?receipts " + mb)).contains("no workflow receipts");
    }

    @Test
    void theQueueSurvivesAServerRestart() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "dir.wf", "send dir expect=MISSION1.LOG\n");
        ok(alice, "?queue add " + mb + " dir.wf");
        sys.close();
        sys = null;

        sys = TestSystem.start(dir.resolve("sys"));
        register("tcp://127.0.0.1:" + glider.port());
        ClientSocketHandler again = sys.login("alice");
        assertThat(ok(again, "?queue " + mb)).contains("dir.wf").contains("alice");
        event(VehicleEvent.SURFACED);
        assertThat(await(again, "?receipts " + mb, WorkflowEndToEndTest::ended)).contains("result: DONE");
        assertThat(ok(again, "?queue " + mb)).contains("empty");
    }

    @Test
    void twoUsersWorkflowsRunOneAfterTheOtherEachWithItsReceipt() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler bob = sys.login("bob");
        upload(alice, "a.wf", "send dir\nsend \"type GLIDER.CFG\"\n");
        upload(bob, "b.wf", "send dir\n");
        ok(alice, "?queue add " + mb + " a.wf");
        ok(bob, "?queue add " + mb + " b.wf");
        assertThat(ok(bob, "?queue " + mb)).containsSubsequence("a.wf", "b.wf");
        event(VehicleEvent.SURFACED);
        String both = await(alice, "?receipts " + mb, r -> count(r, "result: DONE") == 2);
        assertThat(both).containsSubsequence("'a.wf' of alice", "result: DONE", "'b.wf' of bob", "result: DONE");
        assertThat(ok(alice, "?queue " + mb)).contains("empty");
    }

    @Test
    void aStepThatNeverSeesItsPromptTimesOutAndHoldsTheHeadOfTheQueue() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "wait.wf", "send dir\nwait-for 'Glider .* at surface' timeout=2s\nsend dir\n");
        upload(alice, "next.wf", "send dir\n");
        ok(alice, "?queue add " + mb + " wait.wf");
        ok(alice, "?queue add " + mb + " next.wf");
        event(VehicleEvent.SURFACED);
        String failed = await(alice, "?receipts " + mb, WorkflowEndToEndTest::ended);
        assertThat(failed).contains("result: FAILED").contains("no line matching 'Glider .* at surface' within 2 s");
        String queue = ok(alice, "?queue " + mb);
        assertThat(queue).containsSubsequence("wait.wf", "failed at step 2/3", "next.wf", "queued");
        event(VehicleEvent.DIVED);

        // next call: it retries the failed step, and this time the vehicle says it
        event(VehicleEvent.SURFACED);
        await(alice, "?queue " + mb, q -> q.contains("running step 2/3"));
        line("Glider ru29 at surface.");
        String done = await(alice, "?receipts " + mb, r -> count(r, "result: DONE") == 2);
        assertThat(done).contains("(resumed at step 2)");
        assertThat(ok(alice, "?queue " + mb)).contains("empty");
    }

    @Test
    void aCallCutMidWorkflowResumesAtTheCutStep() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "cut.wf", "send dir\nwait-for PROCEED timeout=30s\nymodem:get MISSION1.LOG all\n");
        ok(alice, "?queue add " + mb + " cut.wf");
        event(VehicleEvent.SURFACED);
        await(alice, "?queue " + mb, q -> q.contains("running step 2/3"));
        event(VehicleEvent.DIVED);
        String cut = await(alice, "?receipts " + mb, WorkflowEndToEndTest::ended);
        assertThat(cut).contains("result: CUT").contains("the call ended (DIVED)");
        assertThat(ok(alice, "?queue " + mb)).contains("cut at step 2/3");

        event(VehicleEvent.SURFACED);
        await(alice, "?queue " + mb, q -> q.contains("running step 2/3"));
        line("PROCEED");
        String done = await(alice, "?receipts " + mb, r -> r.contains("result: DONE"));
        assertThat(done).contains("(resumed at step 2)").contains("/MISSION1.LOG");
        assertThat(Files.readAllBytes(sys.downloaded("MISSION1.LOG")))
                .isEqualTo(Files.readAllBytes(glider.directory().resolve("MISSION1.LOG")));
    }

    @Test
    void anOperatorTakingTheLockPausesTheWorkflowAndReleasingResumesIt() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        ClientSocketHandler bob = sys.login("bob");
        upload(alice, "long.wf", "send dir\nwait-for STEP2 timeout=30s\nsend dir\n");
        ok(alice, "?queue add " + mb + " long.wf");
        event(VehicleEvent.SURFACED);
        await(alice, "?queue " + mb, q -> q.contains("running step 2/3"));
        // the workflow holds the lock as alice: bob's command is refused, but bob may take the lock over
        assertThat(bob.call(mb, "dir", Priority.NORMAL, T, null).footer().errorCode()).isEqualTo(ErrorCode.MAILBOX_LOCKED);
        assertThat(ok(bob, "?lock " + mb + " 120")).contains("locked by bob");
        line("STEP2");
        await(alice, "?queue " + mb, q -> q.contains("paused before step 3/3"));
        assertThat(bob.call(mb, "dir", Priority.NORMAL, T, null).status()).isEqualTo(Status.OK);
        assertThat(ok(alice, "?receipts " + mb)).contains("result: RUNNING");
        ok(bob, "?unlock " + mb);
        String done = await(alice, "?receipts " + mb, WorkflowEndToEndTest::ended);
        assertThat(done).contains("result: DONE").contains("step 3/3");
    }

    @Test
    void cancelInTheMiddleOfAGetStopsItAndTheLineIsBackAtThePrompt() throws Exception {
        start();
        byte[] big = new byte[16 * 1024 * 1024];
        new Random(4).nextBytes(big);
        Files.write(glider.directory().resolve("HUGE.LOG"), big);
        ClientSocketHandler alice = sys.login("alice");
        long id = alice.nextId();
        java.util.concurrent.CompletableFuture<OutgoingServerMessage> progressSeen = new java.util.concurrent.CompletableFuture<>();
        java.util.concurrent.CompletableFuture<OutgoingServerMessage> get = alice.send(
                org.ripv.messages.Header.request(id, mb, "ymodem:get HUGE.LOG", Priority.NORMAL), progressSeen::complete);
        progressSeen.get(60, java.util.concurrent.TimeUnit.SECONDS);
        OutgoingServerMessage c = cmd(alice, "?cancel " + id);
        assertThat(c.status()).as(c.footer().replyText()).isEqualTo(Status.OK);
        assertThat(c.footer().replyText()).contains("to stop #" + id);
        OutgoingServerMessage r = get.get(60, java.util.concurrent.TimeUnit.SECONDS);
        assertThat(r.footer().errorCode()).as(r.footer().replyText()).isEqualTo(ErrorCode.CANCELLED);
        assertThat(r.footer().replyText()).contains("cancelled by alice").contains("HUGE.LOG");
        try (var all = Files.walk(sys.downloadDir())) {
            assertThat(all.filter(p -> p.getFileName().toString().contains("HUGE")).toList()).isEmpty();
        }
        // CAN CAN reached the vehicle: it is back at its prompt and answers the next command
        OutgoingServerMessage dir = alice.call(mb, "dir", Priority.NORMAL, T, null);
        assertThat(dir.status()).as(dir.footer().replyText()).isEqualTo(Status.OK);
        assertThat(dir.footer().replyText()).contains("HUGE.LOG").contains("MISSION1.LOG");
    }

    @Test
    void aWorkflowQueuedDuringACallRunsInItAndAQuickRecallResumesIt() throws Exception {
        start();
        ClientSocketHandler alice = sys.login("alice");
        event(VehicleEvent.SURFACED); // nothing queued: nothing runs
        upload(alice, "late.wf", "send dir\nwait-for PROCEED timeout=30s\nsend dir\n");
        assertThat(ok(alice, "?queue add " + mb + " late.wf")).contains("the vehicle is on a call: it runs now");
        await(alice, "?queue " + mb, q -> q.contains("running step 2/3"));
        // the call drops and the vehicle calls again at once, while the last call's run winds up
        event(VehicleEvent.DIVED);
        event(VehicleEvent.SURFACED);
        await(alice, "?receipts " + mb, r -> r.contains("result: CUT"));
        await(alice, "?queue " + mb, q -> q.contains("running step 2/3"));
        line("PROCEED");
        String done = await(alice, "?receipts " + mb, r -> r.contains("result: DONE"));
        assertThat(done).contains("(resumed at step 2)").contains("step 3/3");
        assertThat(ok(alice, "?queue " + mb)).contains("empty");
    }

    @Test
    void aWorkflowQueuedWhileDivedRunsWhenTheSimulatorCallsIn() throws Exception {
        // no test hook here: the SerialPortServer's listen:// link publishes SURFACED when the glider calls
        sys = TestSystem.start(dir.resolve("sys"));
        sys.user("alice", "operators");
        LinkSettings link = LinkSettings.defaults("listen://127.0.0.1:0").withIdleTimeout(Duration.ofSeconds(1))
                .withYmodem(SerialEndToEndTest.YMODEM);
        serial = SerialPortServer.withCalls("localhost", List.of(new org.ripv.services.serial.VehicleLink(link,
                org.ripv.services.serial.CallSettings.defaults().withName("ru29"))), null, false, dir.resolve("work"));
        sys.register(serial);
        mb = "<SerialPortServer>::<localhost>ru29";
        ClientSocketHandler alice = sys.login("alice");
        upload(alice, "call.wf", "send dir expect=MISSION1.LOG\nymodem:get *.LOG\n");
        assertThat(ok(alice, "?queue add " + mb + " call.wf")).contains("it runs when the vehicle calls");

        glider = new GliderSimulator(dir.resolve("glider"), Duration.ofSeconds(1), SerialEndToEndTest.YMODEM);
        glider.call("127.0.0.1", serial.listenPort("ru29"), "ru29", Duration.ofSeconds(2), Duration.ofSeconds(20));
        String receipt = await(alice, "?receipts " + mb, WorkflowEndToEndTest::ended);
        assertThat(receipt).contains("result: DONE");
        Matcher m = FILE.matcher(receipt);
        int n = 0;
        while (m.find()) {
            String name = m.group(1).substring(m.group(1).indexOf('/') + 1);
            assertThat(m.group(3)).isEqualTo(sha256(Files.readAllBytes(glider.directory().resolve(name))));
            n++;
        }
        assertThat(n).isEqualTo(2); // MISSION1.LOG and MISSION2.LOG
        assertThat(ok(alice, "?queue " + mb)).contains("empty");
    }
}
