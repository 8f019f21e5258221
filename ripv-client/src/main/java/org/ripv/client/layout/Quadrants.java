package org.ripv.client.layout;

import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.Container;
import java.awt.KeyboardFocusManager;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.util.EnumMap;
import java.util.Locale;
import java.util.Map;
import javax.swing.JComponent;
import javax.swing.JPanel;
import javax.swing.JSplitPane;
import javax.swing.SwingUtilities;
import javax.swing.border.TitledBorder;
import org.ripv.client.layout.QuadrantState.Dividers;
import org.ripv.client.layout.QuadrantState.Quadrant;

/**
 * Enlarges, maximises and restores the quadrants of one service tab (its {@code host} panel,
 * whose centre is the {@code columns} split pane holding the {@code left} and {@code right}
 * column splits). Maximising moves the quadrant's component out of its split pane into the
 * host's centre, restoring moves it back, so the quadrant keeps its state and focus. A
 * double-click on a quadrant's border (its title) maximises it or restores. On the event thread.
 */
public final class Quadrants {
    private final JPanel host;
    private final JSplitPane columns;
    private final JSplitPane left;
    private final JSplitPane right;
    private final Map<Quadrant, JComponent> parts = new EnumMap<>(Quadrant.class);
    private final QuadrantState state = new QuadrantState();

    /**
     * @param left null when COM spans the left column (no fourth panel)
     */
    public Quadrants(JPanel host, JSplitPane columns, JSplitPane left, JSplitPane right, JComponent com, JComponent fourth,
                     JComponent mam, JComponent fim) {
        this.host = host;
        this.columns = columns;
        this.left = left;
        this.right = right;
        parts.put(Quadrant.COM, com);
        if (fourth != null) {
            parts.put(Quadrant.FOURTH, fourth);
        }
        parts.put(Quadrant.MAM, mam);
        parts.put(Quadrant.FIM, fim);
        for (Map.Entry<Quadrant, JComponent> e : parts.entrySet()) {
            Quadrant q = e.getKey();
            MouseAdapter twice = new MouseAdapter() {
                @Override
                public void mouseClicked(MouseEvent ev) {
                    // Only the quadrant's own area (its titled border), not its children's clicks.
                    if (ev.getClickCount() == 2 && SwingUtilities.isLeftMouseButton(ev)) {
                        maximise(q);
                    }
                }
            };
            e.getValue().addMouseListener(twice);
            // A quadrant made of cards (DAV: chart or picture) has its titles one level down.
            for (Component child : e.getValue().getComponents()) {
                if (child instanceof JComponent j && j.getBorder() instanceof TitledBorder) {
                    j.addMouseListener(twice);
                }
            }
        }
    }

    public QuadrantState state() {
        return state;
    }

    /** The quadrant holding the keyboard focus, or null. */
    public Quadrant focused() {
        Component owner = KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
        for (Map.Entry<Quadrant, JComponent> e : parts.entrySet()) {
            if (owner != null && SwingUtilities.isDescendingFrom(owner, e.getValue())) {
                return e.getKey();
            }
        }
        return null;
    }

    /** Enlarges the quadrant (or restores); a maximised one is first put back. */
    public void enlarge(Quadrant q) {
        if (!parts.containsKey(q)) {
            return;
        }
        unmaximise();
        Dividers d = state.enlarge(q, now(), q == Quadrant.COM && left == null);
        apply(d);
        parts.get(q).requestFocusInWindow();
    }

    /** Shows the quadrant alone (or restores). */
    public void maximise(Quadrant q) {
        if (!parts.containsKey(q)) {
            return;
        }
        Component focus = KeyboardFocusManager.getCurrentKeyboardFocusManager().getFocusOwner();
        if (state.mode() == QuadrantState.Mode.MAXIMISED && state.which() == q) {
            restore();
            if (focus != null && focus.isShowing()) {
                focus.requestFocusInWindow();
            }
            return;
        }
        boolean wasEnlarged = state.mode() == QuadrantState.Mode.ENLARGED;
        Dividers before = wasEnlarged ? state.restore() : null;
        if (before != null) {
            apply(before);
        }
        unmaximise();
        if (state.maximise(q, now())) {
            JComponent c = parts.get(q);
            Container parent = c.getParent();
            if (parent instanceof JSplitPane s) {
                boolean first = s.getLeftComponent() == c;
                JPanel hole = new JPanel();
                hole.setName("maximised-" + q.name().toLowerCase(Locale.ROOT));
                if (first) {
                    s.setLeftComponent(hole);
                } else {
                    s.setRightComponent(hole);
                }
            }
            host.remove(columns);
            host.add(c, BorderLayout.CENTER);
        }
        host.revalidate();
        host.repaint();
        if (focus != null && focus.isShowing()) {
            focus.requestFocusInWindow();
        } else {
            parts.get(q).requestFocusInWindow();
        }
    }

    /** Back to the four quadrants as they were. */
    public void restore() {
        unmaximise();
        Dividers d = state.restore();
        if (d != null) {
            apply(d);
        }
        host.revalidate();
        host.repaint();
    }

    /** If a quadrant is shown alone, puts it back in its split pane (the state is left to the caller). */
    private void unmaximise() {
        for (Map.Entry<Quadrant, JComponent> e : parts.entrySet()) {
            JComponent c = e.getValue();
            if (c.getParent() == host) {
                host.remove(c);
                put(e.getKey(), c);
                host.add(columns, BorderLayout.CENTER);
            }
        }
        if (state.mode() == QuadrantState.Mode.MAXIMISED) {
            state.restore();
        }
    }

    private void put(Quadrant q, JComponent c) {
        if (q == Quadrant.COM && left == null) {
            columns.setLeftComponent(c);
        } else if (q.left()) {
            if (q.top()) {
                left.setTopComponent(c);
            } else {
                left.setBottomComponent(c);
            }
        } else if (q.top()) {
            right.setTopComponent(c);
        } else {
            right.setBottomComponent(c);
        }
    }

    private Dividers now() {
        return new Dividers(fraction(columns), left == null ? -1 : fraction(left), fraction(right));
    }

    private static double fraction(JSplitPane s) {
        int size = s.getOrientation() == JSplitPane.HORIZONTAL_SPLIT ? s.getWidth() : s.getHeight();
        size -= s.getDividerSize();
        return size <= 0 ? -1 : Math.max(0, Math.min(1, (double) s.getDividerLocation() / size));
    }

    private void apply(Dividers d) {
        if (d == null) {
            return;
        }
        set(columns, d.columns());
        if (left != null) {
            set(left, d.left());
        }
        set(right, d.right());
    }

    private static void set(JSplitPane s, double f) {
        if (f >= 0) {
            s.setDividerLocation(f);
        }
    }
}
