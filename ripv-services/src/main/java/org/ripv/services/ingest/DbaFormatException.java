package org.ripv.services.ingest;

/** A DBA file that is not what its header promises: says which line, and why. */
public final class DbaFormatException extends Exception {
    private static final long serialVersionUID = 1L;
    private final long line;

    public DbaFormatException(long line, String reason) {
        super("line " + line + ": " + reason);
        this.line = line;
    }

    /** The 1-based line the problem is on. */
    public long line() {
        return line;
    }
}
