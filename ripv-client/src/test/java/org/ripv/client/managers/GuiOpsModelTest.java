package org.ripv.client.managers;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.Progress;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;

/** The operator fixes in the GUI's models, headless: status bar, SS during transfers, history per MailBox, rate and ETA. */
class GuiOpsModelTest {
    static final String SERIAL = "<SerialPortServer>::<glider-host>";
    static final String BOX_A = SERIAL + "ru29";
    static final String BOX_B = SERIAL + "ru30";

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
                new MailboxStatus(BOX_A, true, "", false, ""), new MailboxStatus(BOX_B, true, "", false, "")))));
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

    @Test
    void theStatusBarShowsTheLatestMessageOnlyAndALaterSuccessReplacesAnError() {
        dispatch(GuiManagerDispatchTest.reply("", BOX_A, "dir", Ids.SID_SERIAL, Status.ERROR, "no such file\nsecond line", null));
        assertThat(model.noticeIsError()).isTrue();
        assertThat(model.notice()).doesNotContain("\n").endsWith(" …").contains("no such file");
        assertThat(model.noticeDetail()).contains("second line");
        dispatch(GuiManagerDispatchTest.reply("", BOX_A, "dir", Ids.SID_SERIAL, Status.OK, "MISSION1.LOG  2048", null));
        assertThat(model.noticeIsError()).as("no stale red error after a success").isFalse();
        assertThat(model.notice()).contains("MISSION1.LOG");
    }

    @Test
    void serviceStatusSaysBusyWhileATransferRuns() {
        ui.execute(() -> manager.selectMailbox(SERIAL, BOX_A));
        ui.sync();
        ServiceModel m = model.service(SERIAL);
        assertThat(m.serviceStatus()).isEqualTo("available");
        dispatch(GuiManagerDispatchTest.reply("", BOX_A, "ymodem:get MISSION1.LOG", Ids.SID_SERIAL, Status.PROGRESS, "",
                new Progress("ymodem:get MISSION1.LOG", 1024, 4096, 512)));
        assertThat(m.serviceStatus()).startsWith("busy: ymodem:get MISSION1.LOG").contains("25%");
        dispatch(GuiManagerDispatchTest.reply("", BOX_A, "ymodem:get MISSION1.LOG", Ids.SID_SERIAL, Status.OK, "got it", null));
        assertThat(m.serviceStatus()).isEqualTo("available");
    }

    @Test
    void eachMailboxKeepsItsOwnCommandHistory() {
        ui.execute(() -> {
            manager.selectMailbox(SERIAL, BOX_A);
            manager.sendCommand(SERIAL, "dir");
            manager.selectMailbox(SERIAL, BOX_B);
            manager.sendCommand(SERIAL, "type LOG.TXT");
        });
        ui.sync();
        ServiceModel m = model.service(SERIAL);
        assertThat(m.history()).containsExactly("type LOG.TXT");
        ui.execute(() -> manager.selectMailbox(SERIAL, BOX_A));
        ui.sync();
        assertThat(m.history()).containsExactly("dir");
    }

    @Test
    void transfersShowRateAndTimeLeft() {
        AtomicLong now = new AtomicLong(0);
        Transfer t = new Transfer(1, Transfer.Direction.UPLOAD, "plan.ma", Path.of("plan.ma"), -1, now::get);
        t.progress(0, 4 * 1024 * 1024);
        now.set(2_000_000_000L);
        t.progress(1024 * 1024, 4 * 1024 * 1024);
        assertThat(t.rate()).isEqualTo(512 * 1024.0);
        assertThat(t.etaSeconds()).isEqualTo(6);
        assertThat(t.progressText()).isEqualTo("25%  1.0 MB / 4.0 MB  512 KB/s  0:06 left");
        t.finish(Transfer.State.DONE, "uploaded");
        assertThat(t.etaSeconds()).isEqualTo(-1);
        assertThat(t.progressText()).isEqualTo("done");
    }

    @Test
    void aRefusedNameIsAskedAboutOnce() {
        Transfer t = new Transfer(2, Transfer.Direction.UPLOAD, "plan.ma", Path.of("plan.ma"), 10);
        assertThat(t.claimQuestion()).isFalse();
        t.nameTaken(true);
        assertThat(t.claimQuestion()).isTrue();
        assertThat(t.claimQuestion()).as("the other tabs' FIM panels do not ask again").isFalse();
    }
}
