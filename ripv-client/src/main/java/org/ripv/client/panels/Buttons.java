package org.ripv.client.panels;

import java.awt.event.ActionListener;
import javax.swing.JButton;

/**
 * A button as every panel makes one: words, a mnemonic (Alt+key), a name tests find it by, a
 * tooltip that says what it does, and its action.
 */
public final class Buttons {
    private Buttons() {}

    public static JButton button(String text, int mnemonic, String name, String tip) {
        JButton b = new JButton(text);
        b.setMnemonic(mnemonic);
        b.setName(name);
        b.setToolTipText(tip);
        return b;
    }

    public static JButton button(String text, int mnemonic, String name, String tip, ActionListener action) {
        JButton b = button(text, mnemonic, name, tip);
        b.addActionListener(action);
        return b;
    }
}
