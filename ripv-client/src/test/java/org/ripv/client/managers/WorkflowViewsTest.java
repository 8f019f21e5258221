package org.ripv.client.managers;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.SessionState;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;

/**
 * Issue 12's GUI models, headless: running requests and their words, a CANCELLED reply shown as
 * cancelled, ETA in SS, vehicle state kept current by pushed events, and the workflow queue,
 * refusals and receipts read from the server's answers (as docs/workflows.md shows them).
 */
class WorkflowViewsTest {
    static final String SERIAL = "<SerialPortServer>::<shore>";
    static final String RU29 = SERIAL + "ru29";

    UiThread ui;
    ClientModel model;
    GuiManager manager;

    @BeforeEach
    void setUp() {
        ui = new UiThread();
        model = new ClientModel();
        manager = new GuiManager(model, ui, (h, p) -> {
            throw new IOException("no network in this test");
        }, GuiManager.Timings.DEFAULT);
        dispatch(GuiManagerDispatchTest.reply("", "", "?services", Ids.FID_SERVICES, Status.OK, "", new ServiceList(List.of(
                new ServiceDescriptor(SERIAL, Ids.SID_SERIAL, "serial ports", "", List.of())))));
        dispatch(GuiManagerDispatchTest.reply("", "", "?mailboxes", Ids.FID_MAILBOXES, Status.OK, "", new MailboxList(List.of(
                new MailboxStatus(RU29, true, "ru29", false, "", new SessionState(SessionState.State.DIVED, 1_000_000, 41.6, -70.5,
                        3, VehicleEvent.DIVED))))));
    }

    @AfterEach
    void tearDown() {
        manager.close();
        ui.close();
    }

    void dispatch(OutgoingServerMessage reply) {
        manager.dispatch(reply);
        ui.sync();
    }

    @Test
    void aRunningRequestShowsProgressWithRateAndTimeLeftThenEnds() throws InterruptedException {
        ServiceModel m = model.service(SERIAL);
        manager.requestStarted(SERIAL, 41, "ymodem:get mission.log");
        ui.sync();
        assertThat(m.running()).singleElement().satisfies(r -> {
            assertThat(r.messageId()).isEqualTo(41);
            assertThat(r.text(r.started() + 7_000)).isEqualTo("running: ymodem:get mission.log  0:07");
        });
        manager.requestProgress(SERIAL, 41, new Progress("ymodem:get mission.log", 40 * 1024, 100 * 1024, 512));
        manager.requestProgress(SERIAL, 99, new Progress("someone else's", 1, 2, 1));
        ui.sync();
        assertThat(m.running().get(0).text(0)).isEqualTo("ymodem:get mission.log  40 KB / 100 KB  512 B/s  2:00 left");
        manager.requestStarted(SERIAL, 42, "ymodem:get *.SBD");
        manager.requestProgress(SERIAL, 42, new Progress("01230000.SBD", 10 * 1024, 20 * 1024, 1024));
        ui.sync();
        assertThat(m.running().get(1).text(0)).isEqualTo("ymodem:get *.SBD · 01230000.SBD  10 KB / 20 KB  1 KB/s  0:10 left");
        manager.requestEnded(SERIAL, 42, null);
        ui.run(() -> manager.showProgress(SERIAL, new Progress("ymodem:get mission.log", 40 * 1024, 100 * 1024, 512)));
        ui.sync(); // showProgress queues the model change behind itself on the UI thread
        assertThat(ui.get(m::serviceStatus)).isEqualTo("busy: ymodem:get mission.log (40%, ETA 2:00)");
        boolean cancelling = ui.get(() -> {
            manager.cancel(SERIAL, 41);
            return m.running().get(0).cancelling(); // the refusal comes back later, on this thread
        });
        assertThat(cancelling).isTrue();
        // Not connected: the ?cancel cannot go, so the request is not left "cancelling".
        long end = System.nanoTime() + 5_000_000_000L;
        while (ui.get(() -> m.running().get(0).cancelling()) && System.nanoTime() < end) {
            Thread.sleep(20);
        }
        assertThat(ui.get(() -> m.running().get(0).cancelling())).isFalse();
        String notice = ui.get(() -> model.notice());
        assertThat(notice).contains("?cancel 41").contains("not connected");
        manager.requestEnded(SERIAL, 41, ErrorCode.CANCELLED);
        ui.sync();
        assertThat(m.running()).isEmpty();
        assertThat(ProgressTextTestHelper.clock(3725)).isEqualTo("1:02:05");
    }

    @Test
    void aCancelledReplyReadsAsCancelledNotAsAFailure() {
        Header h = new Header(7, new IdBadge("123456", "alice"), List.of(), "", RU29, "ymodem:get big.log", Priority.NORMAL, null);
        dispatch(new OutgoingServerMessage(h, Footer.error(Ids.SID_SERIAL, ErrorCode.CANCELLED,
                "cancelled by bob: the transfer stopped after 12 blocks")));
        ServiceModel m = model.service(SERIAL);
        assertThat(m.transcript()).last().satisfies(l -> {
            assertThat(l.kind()).isEqualTo(ServiceModel.LineKind.NOTICE);
            assertThat(l.text()).isEqualTo("cancelled 'ymodem:get big.log': cancelled by bob: the transfer stopped after 12 blocks");
        });
        assertThat(model.noticeIsError()).isFalse();
        assertThat(model.notice()).contains("cancelled 'ymodem:get big.log'");
    }

    @Test
    void pushedEventsKeepTheBadgeCurrentBetweenRefreshes() {
        ServiceModel m = model.service(SERIAL);
        assertThat(m.mailboxes().get(0).session().state()).isEqualTo(SessionState.State.DIVED);
        ConsoleEntry surfaced = new ConsoleEntry(2_000_000, RU29, ConsoleEntry.Kind.EVENT, "", "Glider ru29 at surface",
                VehicleEvent.SURFACED, 41.63323, -70.53647);
        ConsoleEntry command = new ConsoleEntry(2_500_000, RU29, ConsoleEntry.Kind.COMMAND, "bob", "report ++ m_battery", null,
                null, null);
        manager.showConsole(new ConsoleBatch(RU29, List.of(surfaced, command), 0, false), true);
        ui.sync();
        SessionState s = m.mailboxes().get(0).session();
        assertThat(s.state()).isEqualTo(SessionState.State.ON_CALL);
        assertThat(s.calls()).isEqualTo(4);
        assertThat(s.lastContact()).as("a command is no contact").isEqualTo(2_000_000);
        assertThat(s.lat()).isEqualTo(41.63323);
        // The replay of a later watch repeats the SURFACED: it is not counted twice.
        manager.showConsole(new ConsoleBatch(RU29, List.of(surfaced), 0, false), false);
        ui.sync();
        assertThat(m.mailboxes().get(0).session().calls()).isEqualTo(4);
        ConsoleEntry lost = new ConsoleEntry(3_000_000, RU29, ConsoleEntry.Kind.EVENT, "", "carrier lost", VehicleEvent.LINK_LOST,
                null, null);
        manager.showConsole(new ConsoleBatch(RU29, List.of(lost), 0, false), true);
        ui.sync();
        assertThat(m.mailboxes().get(0).session().state()).isEqualTo(SessionState.State.LOST);
        assertThat(m.mailboxes().get(0).session().lastContact()).isEqualTo(2_000_000);
        assertThat(ConsoleModel.badge(m.mailboxes().get(0).session(), java.time.Instant.ofEpochMilli(2_000_000 + 12 * 60_000)))
                .isEqualTo("✕ lost · last contact 12 min ago");
        ConsoleEntry failed = new ConsoleEntry(3_100_000, RU29, ConsoleEntry.Kind.EVENT, "alice", "workflow 2 'fetch.wf': step 3/4 failed",
                VehicleEvent.WORKFLOW_FAILED, null, null);
        manager.showConsole(new ConsoleBatch(RU29, List.of(failed), 0, false), true);
        ui.sync();
        assertThat(model.notice()).isEqualTo("ru29 WORKFLOW_FAILED: workflow 2 'fetch.wf': step 3/4 failed");
        assertThat(model.noticeIsError()).isTrue();
    }

    @Test
    void theQueueListingIsReadIntoRows() {
        String text = """
                queued workflow 2 'ru29 new.wf' (4 step(s), once) for <SerialPortServer>::<shore>ru29; it runs when the vehicle calls
                3 workflow(s) queued for <SerialPortServer>::<shore>ru29, in the order they run:
                  ID  OWNER      MODE         FILE, STATE
                   1  alice      every-call   ru29-every-call.wf  6 step(s), running step 3/6  (added 2026-11-23T02:10:00Z)  [step request: ?cancel 5 010003]
                   2  bob        once         ru29 new.wf  4 step(s), failed at step 2/4, retries it on the next call: expect 'x' not found  (added 2026-11-23T02:11:00Z)
                  10  carol      once         a.wf  1 step(s), queued
                """;
        List<WorkflowModel.Entry> rows = WorkflowModel.parseListing(text);
        assertThat(rows).containsExactly(
                new WorkflowModel.Entry(1, "alice", "every-call", "ru29-every-call.wf", 6, "running step 3/6", "2026-11-23T02:10:00Z"),
                new WorkflowModel.Entry(2, "bob", "once", "ru29 new.wf", 4,
                        "failed at step 2/4, retries it on the next call: expect 'x' not found", "2026-11-23T02:11:00Z"),
                new WorkflowModel.Entry(10, "carol", "once", "a.wf", 1, "queued", ""));
        assertThat(WorkflowModel.parseListing("the queue of " + RU29 + " is empty")).isEmpty();
    }

    @Test
    void aRefusalNamesItsLineAndReason() {
        assertThat(WorkflowModel.parseRefusals("fetch.wf:7: unknown step 'ymodem:gte': steps are send, ymodem:get"))
                .containsExactly(new WorkflowModel.Refusal("fetch.wf", 7, "unknown step 'ymodem:gte': steps are send, ymodem:get"));
        assertThat(WorkflowModel.parseRefusals("fetch.wf:3: bad expect regex '(unclosed': Unclosed group near index 9 [BAD_REQUEST]"))
                .singleElement().hasToString("line 3: bad expect regex '(unclosed': Unclosed group near index 9");
        assertThat(WorkflowModel.parseRefusals("empty.wf: no steps: a workflow needs at least one step (docs/workflows.md)"))
                .singleElement().satisfies(r -> assertThat(r.line()).isZero());
        assertThat(WorkflowModel.parseRefusals("user 'olga' may not change workflow queues (no rule allows it)")).isEmpty();
        WorkflowModel w = new WorkflowModel();
        w.outcome(RU29, "mission.wf:2: ymodem:put goto_l10.ma: no such file in the upload store; upload it first", true);
        assertThat(w.queue(RU29).refusals()).singleElement().satisfies(r -> assertThat(r.line()).isEqualTo(2));
        w.outcome(RU29, "queued workflow 3 'mission.wf'", false);
        assertThat(w.queue(RU29).refusals()).as("a success clears the refusal").isEmpty();
    }

    @Test
    void receiptsAreSplitNewestFirst() {
        String text = """
                2 receipt(s) for <SerialPortServer>::<shore>ru29, oldest first

                receipt: workflow 1 'fetch.wf' of alice on <SerialPortServer>::<shore>ru29, run 1
                started: 2026-11-23T15:02:42.344Z
                step 1/1 (line 2) dir: OK in 0.0 s
                result: DONE at 2026-11-23T15:02:43.994Z (1.7 s)

                receipt: workflow 2 'mission.wf' of bob on <SerialPortServer>::<shore>ru29, run 1
                started: 2026-11-23T16:00:00Z
                step 1/2 (line 2) ymodem:put goto_l10.ma: FAILED in 3.0 s
                result: FAILED at 2026-11-23T16:00:03Z (3.0 s)
                """;
        List<WorkflowModel.Receipt> r = WorkflowModel.parseReceipts(text);
        assertThat(r).hasSize(2);
        assertThat(r.get(0)).hasToString("FAILED  workflow 2 'mission.wf' (bob), run 1");
        assertThat(r.get(1).text()).startsWith("receipt: workflow 1").endsWith("result: DONE at 2026-11-23T15:02:43.994Z (1.7 s)");
        assertThat(WorkflowModel.parseReceipts("no workflow receipts for " + RU29 + " yet")).isEmpty();
    }

    /** ProgressText's clock, through its public face. */
    static final class ProgressTextTestHelper {
        static String clock(long s) {
            return ProgressText.clock(s);
        }
    }

    @Test
    void aRunDonePastFailedStepsIsShownAsOneWithErrors() {
        List<WorkflowModel.Receipt> r = WorkflowModel.parseReceipts("""
                receipt: workflow 1 'night.wf' of alice on <SerialPortServer>::<h>ru29, run 1
                step 1/2 (line 1) ymodem:get X.mrg: FAILED (continue-on-error) in 1.0 s
                result: DONE_WITH_ERRORS at 2026-11-26T15:00:00Z (1.0 s)
                receipt: workflow 2 'ok.wf' of alice on <SerialPortServer>::<h>ru29, run 1
                result: DONE at 2026-11-26T15:01:00Z (1.0 s)
                """);
        assertThat(r).hasSize(2);
        assertThat(r.get(1).verdict()).isEqualTo("DONE_WITH_ERRORS");
        assertThat(r.get(1).hadErrors()).isTrue();
        assertThat(r.get(1).toString()).startsWith("DONE_WITH_ERRORS  workflow 1 'night.wf' (alice), run 1");
        assertThat(r.get(0).hadErrors()).isFalse();
    }
}
