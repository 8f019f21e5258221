package org.ripv.client.gui;

import java.util.Locale;
import java.util.Map;
import java.util.prefs.Preferences;
import javax.swing.UIManager;
import com.formdev.flatlaf.FlatDarkLaf;
import com.formdev.flatlaf.FlatLaf;
import com.formdev.flatlaf.FlatLightLaf;

/** The window's look: FlatLaf light or dark, remembered in the client's preferences (key {@value #KEY}). */
public enum Theme {
    LIGHT, DARK;

    static final String KEY = "theme";

    /** The theme last chosen, light when none was. */
    public static Theme saved(Preferences prefs) {
        try {
            return valueOf(prefs.get(KEY, LIGHT.name()).toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            return LIGHT;
        }
    }

    /** Installs the look and feel; before the window exists, or followed by {@link #applyToOpenWindows()}. */
    public void install() {
        // Underline every mnemonic all the time, not only while Alt is held: keyboard users see them.
        FlatLaf.setGlobalExtraDefaults(Map.of("Component.hideMnemonics", "false"));
        if (this == DARK) {
            FlatDarkLaf.setup();
        } else {
            FlatLightLaf.setup();
        }
    }

    /** Switches a running window to this theme and remembers it. On the event thread. */
    public void choose(Preferences prefs) {
        install();
        applyToOpenWindows();
        prefs.put(KEY, name());
    }

    static void applyToOpenWindows() {
        FlatLaf.updateUI();
    }

    /** Whether this theme is the one installed. */
    public boolean installed() {
        return UIManager.getLookAndFeel() instanceof FlatLaf f && f.isDark() == (this == DARK);
    }
}
