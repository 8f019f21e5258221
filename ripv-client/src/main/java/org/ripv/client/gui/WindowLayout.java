package org.ripv.client.gui;

import java.awt.Rectangle;
import java.util.prefs.Preferences;

/**
 * Where the operator left the window: its bounds, whether it was maximized, the SEL divider and
 * the service tabs' quadrant dividers; kept in the client's preferences between runs.
 *
 * @param bounds    the window's bounds, or null for the first run's default
 * @param maximized whether it filled the screen
 * @param selDivider the SEL tree's divider in pixels, or -1
 * @param quadrants the tabs' dividers (columns, left column, right column) in pixels, -1 each for the default
 */
public record WindowLayout(Rectangle bounds, boolean maximized, int selDivider, int[] quadrants) {
    static final String PREFIX = "layout.";

    /** The layout saved last, or the defaults (null bounds) on a first run. */
    public static WindowLayout load(Preferences p) {
        int w = p.getInt(PREFIX + "width", -1);
        int h = p.getInt(PREFIX + "height", -1);
        Rectangle bounds = w > 200 && h > 150 ? new Rectangle(p.getInt(PREFIX + "x", 0), p.getInt(PREFIX + "y", 0), w, h) : null;
        return new WindowLayout(bounds, p.getBoolean(PREFIX + "maximized", false), p.getInt(PREFIX + "sel", -1),
                new int[] {p.getInt(PREFIX + "columns", -1), p.getInt(PREFIX + "left", -1), p.getInt(PREFIX + "right", -1)});
    }

    public void save(Preferences p) {
        if (bounds != null) {
            p.putInt(PREFIX + "x", bounds.x);
            p.putInt(PREFIX + "y", bounds.y);
            p.putInt(PREFIX + "width", bounds.width);
            p.putInt(PREFIX + "height", bounds.height);
        }
        p.putBoolean(PREFIX + "maximized", maximized);
        p.putInt(PREFIX + "sel", selDivider);
        if (quadrants != null && quadrants.length == 3) {
            p.putInt(PREFIX + "columns", quadrants[0]);
            p.putInt(PREFIX + "left", quadrants[1]);
            p.putInt(PREFIX + "right", quadrants[2]);
        }
    }

    /** The bounds, moved onto the screen if the screen shrank since they were saved. */
    Rectangle fitted(Rectangle screen) {
        if (bounds == null) {
            return null;
        }
        int w = Math.min(bounds.width, screen.width);
        int h = Math.min(bounds.height, screen.height);
        int x = Math.max(screen.x, Math.min(bounds.x, screen.x + screen.width - w));
        int y = Math.max(screen.y, Math.min(bounds.y, screen.y + screen.height - h));
        return new Rectangle(x, y, w, h);
    }
}
