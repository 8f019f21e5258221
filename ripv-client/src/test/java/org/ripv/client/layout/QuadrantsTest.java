package org.ripv.client.layout;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.LinkedBlockingQueue;
import javax.swing.JSplitPane;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.ripv.client.layout.QuadrantState.Dividers;
import org.ripv.client.layout.QuadrantState.Mode;
import org.ripv.client.layout.QuadrantState.Quadrant;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;
import org.ripv.client.panels.ServiceLayoutPanel;
import org.ripv.messages.ErrorCode;
import org.ripv.messages.Footer;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.Ids;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.ServiceDescriptor;
import org.ripv.messages.ServiceList;
import org.ripv.messages.Status;

/** Enlarging, maximising and restoring a tab's quadrants, headless. */
class QuadrantsTest {
    final LinkedBlockingQueue<Runnable> ui = new LinkedBlockingQueue<>();
    ClientModel model;
    GuiManager manager;

    @BeforeEach
    void setUp() {
        model = new ClientModel();
        manager = new GuiManager(model, ui::add, (h, p) -> {
            throw new IOException("no network here");
        }, GuiManager.Timings.DEFAULT);
        manager.dispatch(new OutgoingServerMessage(new Header(1, new IdBadge("123456", "a"), List.of(), "", "", "?services",
                Priority.NORMAL, null), new Footer(Ids.FID_SERVICES, Status.OK, ErrorCode.NONE, List.of(), "", new ServiceList(
                List.of(new ServiceDescriptor("<DatabaseServer>::<h>", Ids.SID_DATABASE, "", "DAB", List.of()),
                        new ServiceDescriptor("<SerialPortServer>::<h>", Ids.SID_SERIAL, "", "", List.of()))))));
        for (Runnable r = ui.poll(); r != null; r = ui.poll()) {
            r.run();
        }
    }

    @AfterEach
    void tearDown() {
        manager.close();
    }

    @Test
    void theStateEnlargesMaximisesTogglesAndRestoresTheOperatorsDividers() {
        QuadrantState s = new QuadrantState();
        Dividers mine = new Dividers(0.6, 0.4, 0.5);
        Dividers d = s.enlarge(Quadrant.FIM, mine, false);
        assertThat(d).isEqualTo(new Dividers(0.25, -1, 0.25)); // right column 75 %, bottom row 75 %
        assertThat(s.mode()).isEqualTo(Mode.ENLARGED);
        assertThat(s.enlarge(Quadrant.COM, d, false)).isEqualTo(new Dividers(0.75, 0.75, -1)); // switch: still restores to mine
        assertThat(s.enlarge(Quadrant.COM, null, false)).as("again: restore").isEqualTo(mine);
        assertThat(s.mode()).isEqualTo(Mode.NORMAL);
        assertThat(s.enlarge(Quadrant.COM, mine, true).left()).as("COM spanning both rows: no row split").isEqualTo(-1);
        s.restore();
        assertThat(s.maximise(Quadrant.MAM, mine)).isTrue();
        assertThat(s.which()).isEqualTo(Quadrant.MAM);
        assertThat(s.maximise(Quadrant.MAM, null)).isFalse();
        assertThat(s.mode()).isEqualTo(Mode.NORMAL);
    }

    @Test
    void maximisingShowsTheQuadrantAloneAndRestoringPutsEverythingBack() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service("<DatabaseServer>::<h>"), manager);
        p.setSize(1200, 800);
        p.doLayout();
        JSplitPane columns = (JSplitPane) p.getComponent(0);
        JSplitPane left = (JSplitPane) columns.getLeftComponent();
        p.quadrants().maximise(Quadrant.FOURTH);
        assertThat(p.getComponent(0)).isSameAs(p.dab());
        assertThat(p.getComponentCount()).isEqualTo(1);
        assertThat(p.quadrants().state().mode()).isEqualTo(Mode.MAXIMISED);
        p.quadrants().maximise(Quadrant.FOURTH); // again: restore
        assertThat(p.getComponent(0)).isSameAs(columns);
        assertThat(left.getBottomComponent()).isSameAs(p.dab());
        assertThat(left.getTopComponent()).isSameAs(p.com());

        // Maximise one, then another: the first goes back to its place.
        p.quadrants().maximise(Quadrant.MAM);
        p.quadrants().maximise(Quadrant.FIM);
        assertThat(p.getComponent(0)).isSameAs(p.fim());
        assertThat(((JSplitPane) columns.getRightComponent()).getTopComponent()).isSameAs(p.mam());
        p.quadrants().restore();
        assertThat(((JSplitPane) columns.getRightComponent()).getBottomComponent()).isSameAs(p.fim());
        assertThat(p.getComponent(0)).isSameAs(columns);

        // Enlarge moves the dividers; restore brings back the operator's.
        columns.setSize(1200, 800);
        columns.setDividerLocation(600);
        left.setSize(600, 800);
        left.setDividerLocation(400);
        p.quadrants().enlarge(Quadrant.COM);
        assertThat(columns.getDividerLocation()).isGreaterThan(800);
        assertThat(left.getDividerLocation()).isGreaterThan(500);
        p.quadrants().restore();
        assertThat(columns.getDividerLocation()).isBetween(590, 610);
        assertThat(left.getDividerLocation()).isBetween(390, 410);
    }

    @Test
    void aTabWithoutAFourthPanelMaximisesItsSpanningCom() {
        ServiceLayoutPanel p = new ServiceLayoutPanel(model.service("<SerialPortServer>::<h>"), manager);
        JSplitPane columns = (JSplitPane) p.getComponent(0);
        p.quadrants().maximise(Quadrant.COM);
        assertThat(p.getComponent(0)).isSameAs(p.com());
        p.quadrants().restore();
        assertThat(columns.getLeftComponent()).isSameAs(p.com());
        p.quadrants().maximise(Quadrant.FOURTH); // none here: nothing happens
        assertThat(p.getComponent(0)).isSameAs(columns);
    }
}
