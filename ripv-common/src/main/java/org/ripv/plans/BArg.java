package org.ripv.plans;

/**
 * One {@code b_arg: NAME(UNITS) VALUE # comment} line. The glider stores every b_arg as a number;
 * {@code text} keeps it as written (so a file is shown, and compared, as the pilot wrote it).
 */
public record BArg(int line, String name, String units, String text, double value, String comment) {
    /** The line as the glider reads it: {@code name(units) value}. */
    public String declaration() {
        return name + "(" + units + ") " + text;
    }
}
