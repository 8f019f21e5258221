package org.ripv.messages;

import java.util.Locale;

/** The three inbox priorities of a MailBox (thesis figure 5.2): higher runs first. */
public enum Priority {
    NORMAL(1), PRIORITY(2), URGENT(3);

    private final int level;

    Priority(int level) {
        this.level = level;
    }

    /** 1 Normal, 2 Priority, 3 Urgent, as in the thesis. */
    public int level() {
        return level;
    }

    /** Parses "normal", "priority", "urgent" or 1–3. */
    public static Priority parse(String text) {
        String t = text == null ? "" : text.trim().toLowerCase(Locale.ROOT);
        switch (t) {
            case "1": case "normal": return NORMAL;
            case "2": case "priority": return PRIORITY;
            case "3": case "urgent": return URGENT;
            default:
                throw new IllegalArgumentException(
                        "unknown priority '" + text + "': use normal, priority or urgent");
        }
    }
}
