package org.ripv.dac;

/** A refusal: bad input (files, metadata, QC configuration) with a message that names it and says why. */
public final class DacException extends Exception {
    private static final long serialVersionUID = 1L;

    public DacException(String message) {
        super(message);
    }

    public DacException(String message, Throwable cause) {
        super(message, cause);
    }
}
