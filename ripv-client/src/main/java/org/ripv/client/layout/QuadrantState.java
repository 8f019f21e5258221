package org.ripv.client.layout;

import java.util.Objects;

/**
 * Which quadrant of a service tab is enlarged or maximised, and the divider positions to go back
 * to. Enlarging gives a quadrant {@link #ENLARGED} of the tab's width and of its column's height
 * (the others stay visible, smaller); maximising shows it alone; restoring puts the dividers back
 * where the operator had them. Doing the same again restores; the other action switches.
 */
public final class QuadrantState {
    /** The share of the width and height an enlarged quadrant gets. */
    public static final double ENLARGED = 0.75;

    /** The four quadrants, by where they sit. */
    public enum Quadrant {
        COM(0, 0), FOURTH(0, 1), MAM(1, 0), FIM(1, 1);

        private final int column;
        private final int row;

        Quadrant(int column, int row) {
            this.column = column;
            this.row = row;
        }

        public boolean left() {
            return column == 0;
        }

        public boolean top() {
            return row == 0;
        }
    }

    /** How the tab is laid out. */
    public enum Mode { NORMAL, ENLARGED, MAXIMISED }

    /**
     * Divider positions as fractions of the split panes' sizes: the columns', the left column's
     * and the right column's; -1 for "leave it" (a tab without a fourth panel has no left split).
     */
    public record Dividers(double columns, double left, double right) {}

    private Mode mode = Mode.NORMAL;
    private Quadrant which;
    private Dividers saved;

    public Mode mode() {
        return mode;
    }

    /** The enlarged or maximised quadrant, or null. */
    public Quadrant which() {
        return which;
    }

    /**
     * Enlarges {@code q} (or restores, when it is the one enlarged already).
     *
     * @param now     the dividers as they are, remembered for the restore when coming from normal
     * @param spanned whether the quadrant spans both rows (COM in a tab without a fourth panel)
     * @return the dividers to apply
     */
    public Dividers enlarge(Quadrant q, Dividers now, boolean spanned) {
        Objects.requireNonNull(q, "q");
        if (mode == Mode.ENLARGED && which == q) {
            return restore();
        }
        if (mode == Mode.NORMAL) {
            saved = now;
        }
        mode = Mode.ENLARGED;
        which = q;
        double columns = q.left() ? ENLARGED : 1 - ENLARGED;
        double row = q.top() ? ENLARGED : 1 - ENLARGED;
        return new Dividers(columns, q.left() && !spanned ? row : -1, q.left() ? -1 : row);
    }

    /**
     * Maximises {@code q} (or restores, when it is the one maximised already).
     *
     * @return true when {@code q} is now maximised, false when the tab is back to its quadrants
     */
    public boolean maximise(Quadrant q, Dividers now) {
        Objects.requireNonNull(q, "q");
        if (mode == Mode.MAXIMISED && which == q) {
            restore();
            return false;
        }
        if (mode == Mode.NORMAL) {
            saved = now;
        }
        mode = Mode.MAXIMISED;
        which = q;
        return true;
    }

    /** Back to the quadrants as the operator had them; the dividers to apply (null: none saved). */
    public Dividers restore() {
        mode = Mode.NORMAL;
        which = null;
        Dividers d = saved;
        saved = null;
        return d;
    }
}
