package org.ripv.services.datavis;

/**
 * A data file that cannot be plotted: text in a numeric column, a ragged row, no data at all.
 * The message names the line (1-based) so the operator can fix the file.
 */
public final class DataFormatException extends Exception {
    private static final long serialVersionUID = 1L;
    private final long line;

    /**
     * @param line    the 1-based line the problem is on, or 0 when it concerns the whole file
     * @param message what is wrong, quoting the bad value
     */
    public DataFormatException(long line, String message) {
        super(line > 0 ? "line " + line + ": " + message : message);
        this.line = line;
    }

    /** The 1-based line of the problem, 0 for the whole file. */
    public long line() {
        return line;
    }
}
