package org.ripv.client.managers;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.SessionState;
import org.ripv.messages.Status;
import org.ripv.messages.VehicleEvent;

/**
 * The model the window renders, headless: it opens on the first vehicle (not on whichever service
 * registered first), its SS line and the vehicle's badge say the same state after every event, and
 * the calls are counted once, for this run of the vehicle's service.
 */
class FirstVehicleModelTest {
    static final String VIS = "<DataVisServer>::<localhost>";
    static final String DB = "<DatabaseServer>::<localhost>";
    static final String SERIAL = "<SerialPortServer>::<localhost>";
    static final String SIM = SERIAL + "sim01";

    /** The console's last sequence number (the server's, in a real run). */
    static long seq = System.currentTimeMillis() * 1000;

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
        // The DataVisServer registered first, as it often does in the demo.
        dispatch(GuiManagerDispatchTest.reply("", "", "?services", Ids.FID_SERVICES, Status.OK, "", new ServiceList(List.of(
                new ServiceDescriptor(VIS, Ids.SID_DATAVIS, "plots", "DAV", List.of("vis:")),
                new ServiceDescriptor(DB, Ids.SID_DATABASE, "vehicle database", "DAB", List.of()),
                new ServiceDescriptor(SERIAL, Ids.SID_SERIAL, "serial ports", "", List.of())))));
    }

    @AfterEach
    void tearDown() {
        manager.close();
        ui.close();
    }

    void dispatch(org.ripv.messages.OutgoingServerMessage reply) {
        manager.dispatch(reply);
        ui.sync();
    }

    void mailboxes(MailboxStatus... boxes) {
        dispatch(GuiManagerDispatchTest.reply("", "", "?mailboxes", Ids.FID_MAILBOXES, Status.OK, "", new MailboxList(List.of(boxes))));
    }

    void push(ConsoleEntry e) {
        // numbered as the server numbers what it pushes: events of one millisecond are still two events
        ConsoleEntry numbered = e.withSeq(++seq);
        dispatch(GuiManagerDispatchTest.reply("", "", "?watch " + e.mailbox(), Ids.FID_CONSOLE, Status.OK, "",
                new ConsoleBatch(e.mailbox(), List.of(numbered), 0, false)));
    }

    static MailboxStatus sim(SessionState.State state, int calls, String detail) {
        return new MailboxStatus(SIM, state == SessionState.State.ON_CALL, detail, false, "",
                new SessionState(state, System.currentTimeMillis() - 1000, 41.6, -70.5, calls, null, seq));
    }

    String badge() {
        MailboxStatus m = model.service(SERIAL).mailboxes().stream().filter(b -> b.address().equals(SIM)).findFirst().orElseThrow();
        return ConsoleModel.badge(m.session(), Instant.now());
    }

    @Test
    void theWindowOpensOnTheFirstVehicleWithItsMailBoxTheTarget() {
        assertThat(model.opening()).as("nothing known yet").isEmpty();
        mailboxes(new MailboxStatus(VIS + "TTY1", true, "built-in worker", false, ""),
                new MailboxStatus(DB + "TTY1", true, "embedded Derby", false, ""),
                new MailboxStatus(SERIAL + "ttyS0", true, "a plain port", false, ""),
                sim(SessionState.State.ON_CALL, 1, "on call since 15:36:40 UTC (caller 127.0.0.1:42174)"));
        assertThat(model.opening()).isEqualTo(SERIAL);
        assertThat(model.service(SERIAL).target()).as("the vehicle, not the plain port listed first").isEqualTo(SIM);
        // Chosen once: a later list does not take the user's tab away.
        mailboxes(new MailboxStatus(VIS + "TTY1", true, "", false, ""), sim(SessionState.State.DIVED, 1, ""));
        assertThat(model.opening()).isEqualTo(SERIAL);
    }

    @Test
    void theStatusLineAndTheBadgeSayTheSameStateAfterEveryEvent() {
        mailboxes(sim(SessionState.State.ON_CALL, 1, "on call since 15:36:40 UTC (caller 127.0.0.1:42174)"));
        assertThat(model.service(SERIAL).serviceStatus()).isEqualTo("available (on call, 1 call this run)");
        assertThat(badge()).startsWith("● on call");

        // The glider dives: the event arrives before the next ?mailboxes, whose detail still says "on call".
        push(ConsoleEntry.event(SIM, VehicleEvent.DIVED, "the caller hung up", null, null));
        assertThat(badge()).startsWith("○ dived");
        assertThat(model.service(SERIAL).serviceStatus()).isEqualTo("not available (dived, 1 call this run)")
                .doesNotContain("on call");

        push(ConsoleEntry.event(SIM, VehicleEvent.SURFACED, "call 2 (caller 127.0.0.1:42180)", 41.6, -70.5));
        assertThat(badge()).startsWith("● on call");
        assertThat(model.service(SERIAL).serviceStatus()).isEqualTo("available (on call, 2 calls this run)");
    }

    @Test
    void theCallCountIsSaidOnceAndTheServicesDetailDoesNotRepeatIt() {
        // The server's count (this run of the service) is the one count; the detail's call words are left out.
        mailboxes(sim(SessionState.State.DIVED, 3, "not on a call (dived at 15:37:10 UTC (the caller hung up)); waiting for calls"));
        String ss = model.service(SERIAL).serviceStatus();
        assertThat(ss).isEqualTo("not available (dived, 3 calls this run)");
        assertThat(ss.split("call", -1)).as("one count in one line").hasSize(2);
    }

    @Test
    void onACallButNotTakingCommandsTheServiceSaysWhy() {
        mailboxes(new MailboxStatus(SIM, false, "submerged", false, "",
                new SessionState(SessionState.State.ON_CALL, System.currentTimeMillis() - 1000, null, null, 1, null)));
        assertThat(model.service(SERIAL).serviceStatus()).isEqualTo("not available (on call, 1 call this run; submerged)");
    }
}
