package org.ripv.launch;

/**
 * The range checks launchers make on numeric options and settings, worded once: picocli parses a
 * number but knows no bounds, and each launcher used to spell its own "must be at least" and
 * "is outside" lines. Each check throws {@link IllegalArgumentException} quoting the name and the
 * bad value; the launcher reports it as its {@code Error:} line.
 */
public final class OptionChecks {
    private OptionChecks() {}

    /** Refuses {@code value} below {@code min}: "--max-clients must be at least 1, got 0". */
    public static void atLeast(String name, long value, long min) {
        if (value < min) {
            throw new IllegalArgumentException(name + " must be at least " + min + ", got " + value);
        }
    }

    /** Refuses {@code value} outside {@code min}..{@code max}: "baud 7 is outside 50–4000000". */
    public static void within(String name, long value, long min, long max) {
        if (value < min || value > max) {
            throw new IllegalArgumentException(name + " " + value + " is outside " + min + "–" + max);
        }
    }
}
