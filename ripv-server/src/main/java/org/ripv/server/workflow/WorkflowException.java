package org.ripv.server.workflow;

/** A workflow file that cannot run: the message names the file, the line and the reason. */
public final class WorkflowException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final int line;

    WorkflowException(String file, int line, String reason) {
        super(file + (line > 0 ? ":" + line : "") + ": " + reason);
        this.line = line;
    }

    /** The line at fault (1-based), or 0 when the file as a whole is. */
    public int line() {
        return line;
    }
}
