package org.ripv.it;

import com.formdev.flatlaf.FlatLightLaf;
import java.util.UUID;
import java.util.prefs.Preferences;
import org.assertj.swing.core.BasicRobot;
import org.assertj.swing.edt.GuiActionRunner;
import org.assertj.swing.fixture.FrameFixture;
import org.ripv.client.gui.RIPVClient;
import org.ripv.client.managers.ClientModel;
import org.ripv.client.managers.GuiManager;

/**
 * The client's window for a test under Xvfb: its manager, the AssertJ-Swing fixture (shown) and
 * a preferences node of its own, all let go on close.
 */
record ClientWindow(GuiManager gm, RIPVClient client, FrameFixture fixture, Preferences prefs) implements AutoCloseable {

    static ClientWindow open() {
        Preferences prefs = Preferences.userRoot().node("org/ripv/test/" + UUID.randomUUID());
        // first: a robot with a new hierarchy finds only the windows made after it
        org.assertj.swing.core.Robot robot = BasicRobot.robotWithNewAwtHierarchy();
        GuiManager gm = GuiActionRunner.execute(() -> new GuiManager(new ClientModel()));
        RIPVClient client = GuiActionRunner.execute(() -> {
            FlatLightLaf.setup();
            return new RIPVClient(gm, prefs);
        });
        FrameFixture fixture = new FrameFixture(robot, client.frame());
        fixture.show();
        return new ClientWindow(gm, client, fixture, prefs);
    }

    @Override
    public void close() throws Exception {
        fixture.cleanUp();
        gm.close();
        prefs.removeNode();
    }
}
