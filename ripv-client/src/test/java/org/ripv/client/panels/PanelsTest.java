package org.ripv.client.panels;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.awt.Component;
import java.awt.Container;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JLabel;
import javax.swing.JTable;
import javax.swing.RowSorter;
import javax.swing.SortOrder;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.MailboxList;
import org.ripv.messages.MailboxStatus;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Result;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;
import org.ripv.messages.TableResult;

/**
 * The panels render the model headless (Swing's lightweight components need no display): the
 * four-quadrant layout per service kind, the COM labels, the DAB tabs and their sorting.
 */
class PanelsTest {
    static final String SERIAL = "<SerialPortServer>::<h>";
    static final String DB = "<DatabaseServer>::<h>";
    static final String VIS = "<DataVisServer>::<h>";

    ClientModel model;
    GuiManager manager;
    long ids;
    /** Model changes queue here and run on the test thread in {@link #drain}, as on an event thread. */
    final java.util.concurrent.LinkedBlockingQueue<Runnable> ui = new java.util.concurrent.LinkedBlockingQueue<>();

    void drain() {
        for (Runnable r = ui.poll(); r != null; r = ui.poll()) {
            r.run();
        }
    }

    @BeforeEach
    void setUp() {
        model = new ClientModel();
        manager = new GuiManager(model, ui::add, (h, p) -> {
            throw new IOException("no network here");
        }, GuiManager.Timings.DEFAULT);
        dispatch("?services", Ids.FID_SERVICES, "", "", new ServiceList(List.of(
                new ServiceDescriptor(SERIAL, Ids.SID_SERIAL, "", "", List.of()),
                new ServiceDescriptor(DB, Ids.SID_DATABASE, "", "DAB", List.of()),
                new ServiceDescriptor(VIS, Ids.SID_DATAVIS, "", "DAV", List.of("vis:")))));
    }

    @AfterEach
    void tearDown() {
        manager.close();
    }

    void dispatch(String body, String sid, String mailbox, String text, Result result) {
        manager.dispatch(new OutgoingServerMessage(new Header(++ids, new IdBadge("123456", "a"), List.of(),
                "", mailbox, body, Priority.NORMAL, null),
                new Footer(sid, Status.OK, ErrorCode.NONE, List.of(), text, result)));
        drain();
    }

    static javax.swing.JSplitPane split(java.awt.Container c, String name) {
        for (Component k : c.getComponents()) {
            if (k instanceof javax.swing.JSplitPane s && name.equals(s.getName())) {
                return s;
            }
            if (k instanceof java.awt.Container inner) {
                javax.swing.JSplitPane s = split(inner, name);
                if (s != null) {
                    return s;
                }
            }
        }
        return null;
    }

    @Test
    void theSerialPortServersComPanelSpansBothRows() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(SERIAL), manager);
        assertThat(p.dab()).isNull();
        assertThat(p.dav()).isNull();
        javax.swing.JSplitPane columns = split(p, "columnSplit");
        assertThat(columns.getLeftComponent()).as("COM alone on the left, both rows").isSameAs(p.com());
        javax.swing.JSplitPane right = split(p, "rightSplit");
        assertThat(columns.getRightComponent()).isSameAs(right);
        assertThat(right.getTopComponent()).isSameAs(p.mam());
        assertThat(right.getBottomComponent()).isSameAs(p.fim());
        assertThat(split(p, "leftSplit")).isNull();
    }

    @Test
    void theDatabaseServerGetsFourResizableQuadrantsWithDabBottomLeft() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(DB), manager);
        assertThat(p.dav()).isNull();
        javax.swing.JSplitPane left = split(p, "leftSplit");
        assertThat(left.getTopComponent()).isSameAs(p.com());
        assertThat(left.getBottomComponent()).isSameAs(p.dab());
        javax.swing.JSplitPane right = split(p, "rightSplit");
        assertThat(right.getTopComponent()).isSameAs(p.mam());
        assertThat(right.getBottomComponent()).isSameAs(p.fim());
        assertThat(split(p, "columnSplit").getLeftComponent()).isSameAs(left);
        p.dividers(new int[] {700, 300, 250});
        assertThat(p.dividers()).containsExactly(700, 300, 250);
    }

    @Test
    void theDataVisServerGetsTheImagePanel() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(VIS), manager);
        assertThat(p.dav()).isNotNull();
        assertThat(p.dab()).isNull();
        assertThat(split(p, "leftSplit").getBottomComponent()).isSameAs(p.plot());
    }

    @Test
    void comLabelsShowTalkingToLastActionPriorityAndStatus() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(SERIAL), manager);
        dispatch("?mailboxes", Ids.FID_MAILBOXES, "", "", new MailboxList(List.of(
                new MailboxStatus(SERIAL + "ttyV0", false, "submerged", false, ""))));
        manager.setPriority(SERIAL, Priority.URGENT);
        manager.sendCommand(SERIAL, "dir");
        p.updateAll(model);
        assertThat(label(p, "talkingTo").getText()).isEqualTo(SERIAL + "ttyV0");
        assertThat(label(p, "lastAction").getText()).isEqualTo("dir");
        assertThat(label(p, "priorityLabel").getText()).isEqualTo("urgent (3)");
        assertThat(label(p, "serviceStatus").getText()).isEqualTo("not available (submerged)");
        for (String tipped : List.of("talkingTo", "lastAction", "priorityLabel", "serviceStatus")) {
            assertThat(label(p, tipped).getToolTipText()).as(tipped).isNotBlank();
        }
        assertThat(p.com().replyText()).contains("> dir");
        assertThat(p.mam().tree().handles()).containsExactly("ttyV0");
    }

    @Test
    void pickingAMailboxInTheMamTreeMakesItTheTarget() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(SERIAL), manager);
        dispatch("?mailboxes", Ids.FID_MAILBOXES, "", "", new MailboxList(List.of(
                new MailboxStatus(SERIAL + "ttyV0", true, "", false, ""),
                new MailboxStatus(SERIAL + "ttyV1", true, "", false, "bob"))));
        p.updateAll(model);
        p.mam().tree().pick("ttyV1");
        drain();
        assertThat(model.service(SERIAL).target()).isEqualTo(SERIAL + "ttyV1");
        assertThat(model.service(SERIAL).serviceStatus()).contains("locked by bob");
    }

    @Test
    void eachQueryOpensATabTitledWithItAndNumbersSortAsNumbers() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(DB), manager);
        TableResult t = new TableResult("SELECT VEHICLEID, NAME FROM VEHICLE", List.of("VEHICLEID", "NAME"),
                List.of("INTEGER", "VARCHAR"), List.<String[]>of(new String[] {"10", "glider"},
                new String[] {"9", "auv"}, new String[] {null, "unknown"}), false);
        dispatch("SELECT VEHICLEID, NAME FROM VEHICLE", Ids.SID_DATABASE, DB + "TTY1", "", t);
        String longQuery = "SELECT * FROM MISSION WHERE STARTT > '2001-01-01' ORDER BY STARTT DESC";
        dispatch(longQuery, Ids.SID_DATABASE, DB + "TTY1", "", new TableResult(longQuery, List.of("X"),
                List.of("VARCHAR"), List.of(), true));
        p.updateAll(model);
        DatabasePanel dab = p.dab();
        assertThat(dab.tabs().getTabCount()).isEqualTo(2);
        assertThat(dab.tabs().getTitleAt(0)).isEqualTo("SELECT VEHICLEID, NAME FROM VEHICLE");
        assertThat(dab.tabs().getTitleAt(1)).hasSize(40).endsWith("...");
        assertThat(dab.tabs().getToolTipTextAt(1)).isEqualTo(longQuery);
        assertThat(dab.tabs().getSelectedIndex()).as("the newest answer is in front").isEqualTo(1);

        dab.tabs().setSelectedIndex(0);
        JTable table = dab.selectedTable();
        table.getRowSorter().setSortKeys(List.of(new RowSorter.SortKey(0, SortOrder.ASCENDING)));
        List<Object> ids = new ArrayList<>();
        for (int r = 0; r < table.getRowCount(); r++) {
            ids.add(table.getValueAt(r, 0) == null ? null : table.getValueAt(r, 0).toString());
        }
        // 9 before 10: numeric, not text, order (NULL first).
        assertThat(ids).containsExactly(null, "9", "10");

        manager.closeTable(DB, 0);
        drain();
        p.updateAll(model);
        assertThat(dab.tabs().getTabCount()).isEqualTo(1);
        assertThat(dab.tabs().getToolTipTextAt(0)).isEqualTo(longQuery);
    }

    @Test
    void theDavPanelShowsTheLatestPlotAndScalesIt() throws IOException {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service(VIS), manager);
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(800, 600, java.awt.image.BufferedImage.TYPE_INT_RGB);
        java.io.ByteArrayOutputStream jpeg = new java.io.ByteArrayOutputStream();
        javax.imageio.ImageIO.write(img, "jpg", jpeg);
        dispatch("vis:data.dat", Ids.SID_DATAVIS, VIS + "TTY1", "plotted",
                new org.ripv.messages.ImageResult("data.jpg", jpeg.toByteArray()));
        p.updateAll(model);
        ImagePanel dav = p.dav();
        assertThat(dav.image().getWidth()).isEqualTo(800);
        // Fit into a 400x400 view: the width decides.
        p.setSize(1200, 900);
        dav.setSize(420, 460);
        javax.swing.JScrollPane scroll = (javax.swing.JScrollPane) dav.getComponent(0);
        scroll.setSize(400, 400);
        scroll.getViewport().setSize(400, 400);
        scroll.getViewport().setExtentSize(new java.awt.Dimension(400, 400));
        assertThat(dav.currentScale()).isEqualTo(0.5);
        assertThat(find(dav, "fitButton")).isInstanceOf(javax.swing.JToggleButton.class);
    }

    @Test
    void csvQuotesWhatNeedsQuotingAndTsvFollowsTheViewOrder() {
        TableResult t = new TableResult("q", List.of("A", "B"), List.of("VARCHAR", "INTEGER"), List.<String[]>of(
                new String[] {"plain", "2"}, new String[] {"has,comma", "1"}, new String[] {"say \"hi\"", null},
                new String[] {"two\nlines", "3"}), false);
        assertThat(TableText.csv(t)).isEqualTo("A,B\r\nplain,2\r\n\"has,comma\",1\r\n\"say \"\"hi\"\"\",\r\n\"two\nlines\",3\r\n");
        JTable table = new JTable(new DatabasePanel.ResultModel(t));
        table.setAutoCreateRowSorter(true);
        table.getRowSorter().setSortKeys(List.of(new RowSorter.SortKey(1, SortOrder.DESCENDING)));
        table.setRowSelectionInterval(0, 1);
        assertThat(TableText.tsv(table, t.columns())).isEqualTo("A\tB\ntwo lines\t3\nplain\t2\n");
    }

    @Test
    void commandHistoryRecallsLikeAShell() {
        CommandHistory h = new CommandHistory();
        h.reset(List.of("dir", "type LOG.TXT"));
        assertThat(h.up("half-typed")).isEqualTo("type LOG.TXT");
        assertThat(h.up("type LOG.TXT")).isEqualTo("dir");
        assertThat(h.up("dir")).isNull();
        assertThat(h.down()).isEqualTo("type LOG.TXT");
        assertThat(h.down()).isEqualTo("half-typed");
        assertThat(h.down()).isNull();
        h.reset(List.of());
        assertThat(h.up("")).isNull();
    }

    @Test
    void hostPortParsesWhatOperatorsType() {
        assertThat(HostPort.parse("glider.example.org", 4444)).isEqualTo(new HostPort("glider.example.org", 4444));
        assertThat(HostPort.parse(" localhost:5555 ", 4444)).isEqualTo(new HostPort("localhost", 5555));
        assertThat(HostPort.parse("[::1]:4445", 4444)).isEqualTo(new HostPort("::1", 4445));
        assertThat(HostPort.parse("::1", 4444)).isEqualTo(new HostPort("::1", 4444));
        assertThatThrownBy(() -> HostPort.parse("host:http", 4444)).hasMessageContaining("'http'");
        assertThatThrownBy(() -> HostPort.parse("host:70000", 4444)).hasMessageContaining("70000");
        assertThatThrownBy(() -> HostPort.parse("  ", 4444)).hasMessageContaining("host");
        // A server list (an active server and its standby) stays whole for the connection to try in turn.
        assertThat(HostPort.parse("a.example.org, b.example.org:4445", 4444)).isEqualTo(new HostPort("a.example.org:4444,b.example.org:4445", 4444));
        assertThat(HostPort.parse("a,b", 4444).toString()).isEqualTo("a:4444,b:4444");
        assertThatThrownBy(() -> HostPort.parse("a,b:http", 4444)).hasMessageContaining("'b:http'");
    }

    static JLabel label(Container root, String name) {
        Component c = find(root, name);
        assertThat(c).as("a component named " + name).isInstanceOf(JLabel.class);
        return (JLabel) c;
    }

    @Test
    void comShowsEachRunningRequestWithItsCancelButton() {
        ComPanel com = new ComPanel(DB, manager);
        manager.requestStarted(DB, 17, "SELECT COUNT(*) FROM reading");
        manager.requestStarted(DB, 18, "SELECT 1");
        manager.requestProgress(DB, 18, new org.ripv.messages.Progress("rows", 50, 200, 25));
        drain();
        com.update(model.service(DB));
        assertThat(com.runningTexts()).hasSize(2);
        assertThat(com.runningTexts().get(0)).startsWith("running: SELECT COUNT(*) FROM reading  0:0");
        assertThat(com.runningTexts().get(1)).isEqualTo("SELECT 1 · rows  50 B / 200 B  25 B/s  0:06 left");
        javax.swing.JButton cancel = (javax.swing.JButton) find(com, "cancel-17");
        assertThat(cancel.isEnabled()).isTrue();
        cancel.doClick(); // marks at once; the (offline) refusal waits in the UI queue
        com.update(model.service(DB));
        assertThat(model.service(DB).running().get(0).cancelling()).isTrue();
        assertThat(cancel.getText()).isEqualTo("Cancelling…");
        assertThat(cancel.isEnabled()).as("one ?cancel per request").isFalse();
        manager.requestEnded(DB, 17, ErrorCode.CANCELLED);
        manager.requestEnded(DB, 18, null);
        drain();
        com.update(model.service(DB));
        assertThat(com.runningTexts()).isEmpty();
        assertThat(find(com, "running").isVisible()).isFalse();
    }

    static Component find(Container root, String name) {
        for (Component c : root.getComponents()) {
            if (name.equals(c.getName())) {
                return c;
            }
            if (c instanceof Container k) {
                Component f = find(k, name);
                if (f != null) {
                    return f;
                }
            }
        }
        return null;
    }
}
