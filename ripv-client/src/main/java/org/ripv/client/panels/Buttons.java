package org.ripv.client.panels;

import java.awt.FlowLayout;
import java.awt.event.ActionListener;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JPanel;

/**
 * A button as every panel makes one: words, a mnemonic (Alt+key), a name tests find it by, a
 * tooltip that says what it does, and its action; and the row the buttons stand in, spaced alike
 * under every panel.
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

    /** Buttons (with the odd label or field among them) left to right, 4 pixels apart. */
    public static JPanel row(JComponent... items) {
        JPanel row = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        for (JComponent c : items) {
            row.add(c);
        }
        return row;
    }
}
