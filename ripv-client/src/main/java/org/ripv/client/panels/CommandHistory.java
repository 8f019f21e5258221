package org.ripv.client.panels;

import java.util.List;

/**
 * Up/Down recall over a list of sent commands, like a shell: Up walks back, Down walks forward
 * and ends on what was being typed before recall began.
 */
public final class CommandHistory {
    private List<String> entries = List.of();
    private int position;
    private String draft = "";

    /** Takes the current history (oldest first) and resets the walk to its end. */
    public void reset(List<String> history) {
        entries = List.copyOf(history);
        position = entries.size();
        draft = "";
    }

    /** The older command to show, or null at the oldest. {@code current} is what the field holds now. */
    public String up(String current) {
        if (position == 0) {
            return null;
        }
        if (position == entries.size()) {
            draft = current;
        }
        position--;
        return entries.get(position);
    }

    /** The newer command to show, the draft after the newest, or null when not recalling. */
    public String down() {
        if (position >= entries.size()) {
            return null;
        }
        position++;
        return position == entries.size() ? draft : entries.get(position);
    }
}
