package org.ripv.client.layout;

import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.List;
import java.util.function.Supplier;
import javax.swing.JMenuItem;
import javax.swing.KeyStroke;
import org.ripv.client.layout.QuadrantState.Quadrant;

/**
 * The View menu's items for the showing tab's quadrants: Enlarge (Ctrl+Shift+E), Maximise
 * (Ctrl+Shift+M) — each acting on the quadrant with the keyboard focus (COM when none has it),
 * and restoring when used again — and Restore (Ctrl+Shift+R).
 */
public final class QuadrantMenu {
    private QuadrantMenu() {}

    /** @param showing the showing tab's quadrants, or null when no service tab shows */
    public static List<JMenuItem> items(Supplier<Quadrants> showing) {
        JMenuItem enlarge = item("Enlarge quadrant", KeyEvent.VK_E, "enlargeQuadrant", () -> {
            Quadrants q = showing.get();
            if (q != null) {
                q.enlarge(target(q));
            }
        }, showing);
        JMenuItem maximise = item("Maximise quadrant", KeyEvent.VK_X, "maximiseQuadrant", () -> {
            Quadrants q = showing.get();
            if (q != null) {
                q.maximise(target(q));
            }
        }, showing);
        JMenuItem restore = item("Restore quadrants", KeyEvent.VK_R, "restoreQuadrants", () -> {
            Quadrants q = showing.get();
            if (q != null) {
                q.restore();
            }
        }, showing);
        enlarge.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_E, InputEvent.CTRL_DOWN_MASK | InputEvent.SHIFT_DOWN_MASK));
        maximise.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_M, InputEvent.CTRL_DOWN_MASK | InputEvent.SHIFT_DOWN_MASK));
        restore.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_R, InputEvent.CTRL_DOWN_MASK | InputEvent.SHIFT_DOWN_MASK));
        return List.of(enlarge, maximise, restore);
    }

    private static Quadrant target(Quadrants q) {
        Quadrant f = q.focused();
        if (f == null && q.state().which() != null) {
            return q.state().which();
        }
        return f == null ? Quadrant.COM : f;
    }

    private static JMenuItem item(String text, int mnemonic, String name, Runnable r, Supplier<Quadrants> showing) {
        JMenuItem i = new JMenuItem(text, mnemonic);
        i.setName(name);
        i.addActionListener(e -> r.run());
        return i;
    }
}
