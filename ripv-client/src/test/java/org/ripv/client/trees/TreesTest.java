package org.ripv.client.trees;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.ClientModel.FileArea;
import org.ripv.client.managers.GuiManager;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.FileListing;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;

/** The SEL, MAM and FIM trees built from the model, headless. */
class TreesTest {
    long ids;

    OutgoingServerMessage reply(String sid, String text, Result r) {
        return new OutgoingServerMessage(Header.request(++ids, "", "?x", Priority.NORMAL).withOrigin(
                new IdBadge("123456", "a"), List.of()), new Footer(sid, Status.OK, ErrorCode.NONE, List.of(), text, r));
    }

    @Test
    void serviceTreeShowsEachVehicleWithItsBadgeUnderItsService() {
        ClientModel model = new ClientModel();
        try (GuiManager m = new GuiManager(model, Runnable::run, (h, p) -> {
            throw new IOException("offline");
        }, GuiManager.Timings.DEFAULT)) {
            List<String> picked = new ArrayList<>();
            ServiceTree tree = new ServiceTree(picked::add, (service, box) -> picked.add(service + " " + box));
            m.dispatch(reply(Ids.FID_SERVICES, "", new ServiceList(List.of(
                    new ServiceDescriptor("<S>::<h>", "888888", "serial", "", List.of()),
                    new ServiceDescriptor("<D>::<h>", "666666", "database", "DAB", List.of())))));
            long contact = java.time.Instant.now().minusSeconds(12 * 60 + 5).toEpochMilli();
            m.dispatch(reply(Ids.FID_MAILBOXES, "", new org.ripv.messages.MailboxList(List.of(
                    new MailboxStatus("<S>::<h>ru29", true, "", false, "", new org.ripv.messages.SessionState(
                            org.ripv.messages.SessionState.State.DIVED, contact, 41.6, -70.5, 3, null)),
                    new MailboxStatus("<S>::<h>ttyS1", true, "", false, ""),
                    new MailboxStatus("<D>::<h>TTY1", true, "", false, "")))));
            tree.update(model);
            assertThat(tree.services()).containsExactly("<S>::<h>", "<D>::<h>");
            assertThat(tree.vehicles("<S>::<h>")).containsExactly("ru29  ○ dived · last contact 12 min ago");
            assertThat(tree.vehicles("<D>::<h>")).as("a MailBox that never published is no vehicle").isEmpty();
            tree.setSelectionRow(2); // root, <S>, ru29
            assertThat(picked).containsExactly("<S>::<h> <S>::<h>ru29");
            assertThat(tree.selectedService()).isEqualTo("<S>::<h>");
            tree.update(model);
            assertThat(tree.selectedVehicle()).as("kept across a rebuild").isEqualTo("<S>::<h>ru29");
        }
    }

    @Test
    void serviceTreeFollowsTheServiceListAndKeepsTheSelection() {
        ClientModel model = new ClientModel();
        try (GuiManager m = new GuiManager(model, Runnable::run, (h, p) -> {
            throw new IOException("offline");
        }, GuiManager.Timings.DEFAULT)) {
            List<String> picked = new ArrayList<>();
            ServiceTree tree = new ServiceTree(picked::add);
            m.dispatch(reply(Ids.FID_SERVICES, "", new ServiceList(List.of(
                    new ServiceDescriptor("<A>::<h>", "100001", "first", "", List.of()),
                    new ServiceDescriptor("<B>::<h>", "100002", "second", "DAB", List.of())))));
            tree.update(model);
            assertThat(tree.services()).containsExactly("<A>::<h>", "<B>::<h>");
            tree.setSelectionRow(2);
            assertThat(picked).containsExactly("<B>::<h>");
            m.dispatch(reply(Ids.FID_SERVICES, "", new ServiceList(List.of(
                    new ServiceDescriptor("<B>::<h>", "100002", "second", "DAB", List.of()),
                    new ServiceDescriptor("<C>::<h>", "100003", "third", "", List.of())))));
            tree.update(model);
            assertThat(tree.services()).containsExactly("<B>::<h>", "<C>::<h>");
            assertThat(tree.selectedService()).isEqualTo("<B>::<h>");
            assertThat(picked).as("rebuilding does not count as the operator picking").hasSize(1);
        }
    }

    @Test
    void mailboxTreeShowsHandlesAndTheirState() {
        List<String> picked = new ArrayList<>();
        MailboxTree tree = new MailboxTree("<S>::<h>", picked::add);
        tree.update(List.of(new MailboxStatus("<S>::<h>ttyS0", true, "", false, ""),
                new MailboxStatus("<S>::<h>ttyS1", false, "no carrier", true, "bob")), "<S>::<h>ttyS1");
        assertThat(tree.handles()).containsExactly("ttyS0", "ttyS1");
        assertThat(tree.getSelectionPath().getLastPathComponent().toString())
                .isEqualTo("ttyS1  (not available)  [busy]  [locked by bob]");
        assertThat(picked).isEmpty();
        tree.pick("ttyS0");
        assertThat(picked).containsExactly("<S>::<h>ttyS0");
    }

    @Test
    void fileTreeListsBothDirectories() {
        ClientModel model = new ClientModel();
        try (GuiManager m = new GuiManager(model, Runnable::run, (h, p) -> {
            throw new IOException("offline");
        }, GuiManager.Timings.DEFAULT)) {
            m.dispatch(reply(Ids.FID_ULDIR, "/srv/up", null));
            m.dispatch(reply(Ids.FID_ULFILES, "", new FileListing("/srv/up", List.of(
                    new FileListing.Entry("glider.bin", 2_500_000, 0)))));
            m.dispatch(reply(Ids.FID_DLFILES, "", new FileListing("/srv/down", List.of(
                    new FileListing.Entry("a.log", 10, 0), new FileListing.Entry("b.jpg", 2048, 0)))));
            FileTree tree = new FileTree();
            tree.update(model);
            assertThat(tree.names(FileArea.UPLOAD)).containsExactly("glider.bin");
            assertThat(tree.names(FileArea.DOWNLOAD)).containsExactly("a.log", "b.jpg");
            tree.select(FileArea.DOWNLOAD, "b.jpg");
            assertThat(tree.selectedFile().entry().size()).isEqualTo(2048);
            tree.update(model);
            assertThat(tree.selectedFile().entry().name()).as("kept across a refresh").isEqualTo("b.jpg");
            assertThat(FileTree.size(2_500_000)).isEqualTo("2.4 MB");
            assertThat(FileTree.size(10)).isEqualTo("10 B");
        }
    }
}
