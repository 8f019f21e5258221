package org.ripv.client.panels;

import java.awt.Color;
import javax.swing.UIManager;

/** Colours that must read well on the light and the dark theme. */
public final class Colors {
    private Colors() {}

    /** Red for errors: dark red on a light background, a light red on a dark one. */
    public static Color error() {
        return dark() ? new Color(0xFF7B7B) : new Color(0xB00020);
    }

    static boolean dark() {
        Color bg = UIManager.getColor("Panel.background");
        return bg != null && (bg.getRed() + bg.getGreen() + bg.getBlue()) / 3 < 128;
    }
}
