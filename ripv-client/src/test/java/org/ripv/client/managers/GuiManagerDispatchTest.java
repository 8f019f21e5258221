package org.ripv.client.managers;

import static org.assertj.core.api.Assertions.assertThat;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.ClientModel.Kind;
import org.ripv.client.managers.ServiceModel.LineKind;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.ImageResult;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Progress;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.SessionInfo;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;
import org.ripv.messages.UpdateCount;

/**
 * Every SID and FID of Appendix B reaches its panel's model. Headless: the UI executor runs
 * changes on the test thread, and replies are handed to {@link GuiManager#dispatch} as the
 * socket's reader thread would.
 */
class GuiManagerDispatchTest {
    static final String SERIAL = "<SerialPortServer>::<glider-host>";
    static final String DB = "<DatabaseServer>::<db-host>";
    static final String VIS = "<DataVisServer>::<vis-host>";
    static final String CLOCK = "<ClockService>::<clock-host>";

    UiThread ui;
    ClientModel model;
    GuiManager manager;
    List<ClientModel.Change> changes;

    @BeforeEach
    void setUp() {
        ui = new UiThread();
        model = new ClientModel();
        manager = new GuiManager(model, ui, (h, p) -> {
            throw new IOException("no network in this test");
        }, GuiManager.Timings.DEFAULT);
        changes = java.util.Collections.synchronizedList(new ArrayList<>());
        model.addListener(changes::add);
        dispatch(reply("", "", "?services", Ids.FID_SERVICES, Status.OK, "", new ServiceList(List.of(
                new ServiceDescriptor(SERIAL, Ids.SID_SERIAL, "serial ports", "", List.of()),
                new ServiceDescriptor(DB, Ids.SID_DATABASE, "vehicle database", "DAB", List.of()),
                new ServiceDescriptor(VIS, Ids.SID_DATAVIS, "plots", "DAV", List.of("vis:")),
                new ServiceDescriptor(CLOCK, "100100", "clock", "", List.of())))));
    }

    @AfterEach
    void tearDown() {
        manager.close();
        ui.close();
    }

    /** As the socket's reader thread does; then waits until the model changes have run. */
    void dispatch(OutgoingServerMessage reply) {
        manager.dispatch(reply);
        ui.sync();
    }

    static long ids = 1000;

    static OutgoingServerMessage reply(String destination, String mailbox, String body, String sid, Status status,
                                       String text, Result result) {
        Header h = new Header(++ids, new IdBadge("123456", "alice"), List.of(), destination, mailbox, body,
                Priority.NORMAL, null);
        Footer f = status == Status.ERROR ? Footer.error(sid, ErrorCode.FORBIDDEN, text)
                : new Footer(sid, status, ErrorCode.NONE, List.of(), text, result);
        return new OutgoingServerMessage(h, f);
    }

    @Test
    void servicesReplyFillsTheServiceList() {
        assertThat(model.serviceNames()).containsExactly(SERIAL, DB, VIS, CLOCK);
        assertThat(model.service(DB).panel()).isEqualTo("DAB");
        assertThat(model.service(VIS).panel()).isEqualTo("DAV");
        assertThat(model.service(SERIAL).panel()).isEmpty();
    }

    @Test
    void servicesThatVanishAreDroppedAndOthersKeepTheirState() {
        ui.run(() -> model.service(SERIAL).append(LineKind.REPLY, "kept"));
        changes.clear();
        dispatch(reply("", "", "?services", Ids.FID_SERVICES, Status.OK, "", new ServiceList(List.of(
                new ServiceDescriptor(SERIAL, Ids.SID_SERIAL, "serial ports", "", List.of())))));
        assertThat(model.serviceNames()).containsExactly(SERIAL);
        assertThat(model.service(SERIAL).transcriptText()).contains("kept");
        assertThat(changes).contains(new ClientModel.Change(Kind.SERVICES, null));

        changes.clear();
        dispatch(reply("", "", "?services", Ids.FID_SERVICES, Status.OK, "", new ServiceList(List.of(
                new ServiceDescriptor(SERIAL, Ids.SID_SERIAL, "serial ports", "", List.of())))));
        assertThat(changes).as("an unchanged list repaints nothing").isEmpty();
    }

    @Test
    void mailboxesGoToTheirOwnServiceAndTheFirstBecomesTheTarget() {
        dispatch(reply("", "", "?mailboxes", Ids.FID_MAILBOXES, Status.OK, "", new MailboxList(List.of(
                new MailboxStatus(SERIAL + "ttyV0", true, "simulator", false, ""),
                new MailboxStatus(SERIAL + "ttyV1", false, "no carrier", false, ""),
                new MailboxStatus(DB + "TTY1", true, "", false, "")))));
        assertThat(model.service(SERIAL).mailboxes()).extracting(MailboxStatus::address)
                .containsExactly(SERIAL + "ttyV0", SERIAL + "ttyV1");
        assertThat(model.service(DB).mailboxes()).hasSize(1);
        assertThat(model.service(VIS).mailboxes()).isEmpty();
        assertThat(model.service(SERIAL).target()).isEqualTo(SERIAL + "ttyV0");
        assertThat(model.service(SERIAL).serviceStatus()).startsWith("available");
        assertThat(changes).contains(new ClientModel.Change(Kind.MAILBOXES, SERIAL));
    }

    @Test
    void statusUpdatesTheServiceStatusLabel() {
        dispatch(reply("", "", "?mailboxes", Ids.FID_MAILBOXES, Status.OK, "", new MailboxList(List.of(
                new MailboxStatus(SERIAL + "ttyV0", true, "", false, "")))));
        dispatch(reply("", "", "?status", Ids.FID_STATUS, Status.OK, "", new MailboxStatus(
                SERIAL + "ttyV0", false, "submerged", false, "bob")));
        assertThat(model.service(SERIAL).serviceStatus()).isEqualTo("not available (submerged), locked by bob");
        assertThat(model.service(SERIAL).mailboxes().get(0).lockedBy()).isEqualTo("bob");
    }

    @Test
    void lockAndUnlockRepliesUpdateTheStatusToo() {
        dispatch(reply("", "", "?mailboxes", Ids.FID_MAILBOXES, Status.OK, "", new MailboxList(List.of(
                new MailboxStatus(SERIAL + "ttyV0", true, "", false, "")))));
        dispatch(reply("", "", "?lock", Ids.FID_LOCK, Status.OK, "locked", new MailboxStatus(
                SERIAL + "ttyV0", true, "", false, "alice")));
        assertThat(model.service(SERIAL).serviceStatus()).contains("locked by alice");
        dispatch(reply("", "", "?unlock", Ids.FID_UNLOCK, Status.OK, "unlocked", new MailboxStatus(
                SERIAL + "ttyV0", true, "", false, "")));
        assertThat(model.service(SERIAL).serviceStatus()).isEqualTo("available");
    }

    @Test
    void directoriesAndListingsFillTheFileTree() {
        dispatch(reply("", "", "?uldir", Ids.FID_ULDIR, Status.OK, "/srv/ripv/upload\n", null));
        dispatch(reply("", "", "?dldir", Ids.FID_DLDIR, Status.OK, "/srv/ripv/download", null));
        dispatch(reply("", "", "?ulfiles", Ids.FID_ULFILES, Status.OK, "", new FileListing("",
                List.of(new FileListing.Entry("glider.bin", 2048, 1L)))));
        dispatch(reply("", "", "?dlfiles", Ids.FID_DLFILES, Status.OK, "", new FileListing(
                "/srv/ripv/download", List.of(new FileListing.Entry("mission.log", 10, 2L),
                new FileListing.Entry("plot.jpg", 99, 3L)))));
        assertThat(model.directory(FileArea.UPLOAD).path()).isEqualTo("/srv/ripv/upload");
        assertThat(model.directory(FileArea.UPLOAD).files()).extracting(FileListing.Entry::name).containsExactly("glider.bin");
        assertThat(model.directory(FileArea.DOWNLOAD).path()).isEqualTo("/srv/ripv/download");
        assertThat(model.directory(FileArea.DOWNLOAD).files()).hasSize(2);
        assertThat(changes).contains(new ClientModel.Change(Kind.FILES, null));
    }

    @Test
    void loginAndWhoamiSetTheSession() {
        dispatch(reply("", "", "?whoami", Ids.FID_WHOAMI, Status.OK, "", new SessionInfo("123456", "alice",
                List.of("operators"), "ripv")));
        assertThat(model.session().user()).isEqualTo("alice");
        dispatch(reply("", "", "?login", Ids.FID_LOGIN, Status.OK, "", new SessionInfo("123457", "bob",
                List.of(), "ripv")));
        assertThat(model.session().user()).isEqualTo("bob");
    }

    @Test
    void transferChunksDoNotTouchThePanels() {
        changes.clear();
        dispatch(reply("", "", "?upload a 0 1", Ids.FID_UPLOAD, Status.OK, "chunk", null));
        dispatch(reply("", "", "?download a 0 1", Ids.FID_DOWNLOAD, Status.OK, "chunk", null));
        assertThat(changes).isEmpty();
    }

    @Test
    void serialTextAndProgressReachTheSerialComPanel() {
        String box = SERIAL + "ttyV0";
        dispatch(reply(SERIAL, box, "ymodem:get log.txt", Ids.SID_SERIAL, Status.PROGRESS, "receiving",
                new Progress("log.txt", 1024, 4096, 900.0)));
        assertThat(model.service(SERIAL).progress().percent()).isEqualTo(25);
        dispatch(reply(SERIAL, box, "ymodem:get log.txt", Ids.SID_SERIAL, Status.OK, "received 1 file",
                new FileListing("/srv/dl", List.of(new FileListing.Entry("log.txt", 4096, 1L)))));
        assertThat(model.service(SERIAL).progress()).isNull();
        assertThat(model.service(SERIAL).transcriptText()).contains("received 1 file").contains("log.txt  4096 bytes");
        dispatch(reply("", box, "dir", Ids.SID_SERIAL, Status.OK, "LOG.TXT 4096\nC:\\>", null));
        assertThat(model.service(SERIAL).transcriptText()).contains("LOG.TXT 4096");
        assertThat(model.service(DB).transcript()).isEmpty();
    }

    @Test
    void databaseTablesOpenANewDabTabAndUpdatesReportTheirCount() {
        TableResult t = new TableResult("SELECT * FROM MISSION", List.of("MISSIONID", "NAME"),
                List.of("INTEGER", "VARCHAR"), List.<String[]>of(new String[] {"1", "first"}), false);
        dispatch(reply(DB, DB + "TTY1", "SELECT * FROM MISSION", Ids.SID_DATABASE, Status.OK, "", t));
        dispatch(reply(DB, DB + "TTY1", "UPDATE MISSION SET NAME='x'", Ids.SID_DATABASE, Status.OK, "",
                new UpdateCount(3)));
        assertThat(model.service(DB).tables()).containsExactly(t);
        assertThat(model.service(DB).transcriptText()).contains("1 row(s)").contains("3 row(s) changed");
        assertThat(changes).contains(new ClientModel.Change(Kind.TABLES, DB));
    }

    @Test
    void datavisImagesReachTheDavPanelDecoded() throws IOException {
        BufferedImage img = new BufferedImage(40, 30, BufferedImage.TYPE_INT_RGB);
        ByteArrayOutputStream jpeg = new ByteArrayOutputStream();
        ImageIO.write(img, "jpg", jpeg);
        dispatch(reply(VIS, VIS + "TTY1", "vis:data.txt", Ids.SID_DATAVIS, Status.OK, "plotted",
                new ImageResult("data.jpg", jpeg.toByteArray())));
        ServiceModel.Picture p = model.service(VIS).picture();
        assertThat(p.result().name()).isEqualTo("data.jpg");
        assertThat(p.image().getWidth()).isEqualTo(40);
        assertThat(changes).contains(new ClientModel.Change(Kind.IMAGE, VIS));

        dispatch(reply(VIS, VIS + "TTY1", "vis:bad", Ids.SID_DATAVIS, Status.OK, "",
                new ImageResult("bad.jpg", new byte[] {1, 2, 3})));
        assertThat(model.service(VIS).picture().image()).as("bytes that are no image").isNull();
    }

    @Test
    void anUnknownServiceSidStillReachesItsOwnComPanel() {
        dispatch(reply(CLOCK, CLOCK + "TTY1", "time", "100100", Status.OK, "2026-11-21T22:00:00Z", null));
        assertThat(model.service(CLOCK).transcriptText()).contains("2026-11-21T22:00:00Z");
    }

    @Test
    void errorsAppearInTheServicesComPanelWithTheServersMessage() {
        dispatch(reply(SERIAL, SERIAL + "ttyV0", "GO", Ids.SID_SERIAL, Status.ERROR,
                "team2 may not send 'GO' to <SerialPortServer>::<glider-host>ttyV0", null));
        assertThat(model.service(SERIAL).transcript()).last()
                .isEqualTo(new ServiceModel.Line(LineKind.ERROR, "team2 may not send 'GO' to "
                        + "<SerialPortServer>::<glider-host>ttyV0 [FORBIDDEN 403]"));
        assertThat(model.noticeIsError()).isTrue();
    }

    @Test
    void backgroundErrorsGoToTheStatusBar() {
        dispatch(reply("", "", "?dlfiles", Ids.FID_DLFILES, Status.ERROR, "no download directory", null));
        assertThat(model.notice()).contains("no download directory").contains("?dlfiles");
        assertThat(model.noticeIsError()).isTrue();
    }

    @Test
    void commandsWithoutATargetAreNotSentAndSaySo() {
        ui.run(() -> manager.sendCommand(SERIAL, "dir"));
        assertThat(model.service(SERIAL).transcript()).last().extracting(ServiceModel.Line::kind).isEqualTo(LineKind.ERROR);
        assertThat(model.service(SERIAL).history()).isEmpty();
    }

    @Test
    void priorityAndHistoryAreKeptPerService() {
        dispatch(reply("", "", "?mailboxes", Ids.FID_MAILBOXES, Status.OK, "", new MailboxList(List.of(
                new MailboxStatus(SERIAL + "ttyV0", true, "", false, "")))));
        ui.run(() -> {
            manager.setPriority(SERIAL, Priority.URGENT);
            manager.sendCommand(SERIAL, "dir");
            manager.sendCommand(SERIAL, "dir");
            manager.sendCommand(SERIAL, "type LOG.TXT");
        });
        ServiceModel m = model.service(SERIAL);
        assertThat(m.priority()).isEqualTo(Priority.URGENT);
        assertThat(m.lastAction()).isEqualTo("type LOG.TXT");
        assertThat(m.history()).containsExactly("dir", "type LOG.TXT");
        assertThat(model.service(DB).priority()).isEqualTo(Priority.NORMAL);
    }
}
