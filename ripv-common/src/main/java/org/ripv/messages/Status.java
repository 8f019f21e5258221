package org.ripv.messages;

/** A reply's status: zero or more PROGRESS replies, then exactly one OK or ERROR. */
public enum Status {
    OK, ERROR, PROGRESS;

    /** True for OK and ERROR: the request has been answered. */
    public boolean isFinal() {
        return this != PROGRESS;
    }
}
