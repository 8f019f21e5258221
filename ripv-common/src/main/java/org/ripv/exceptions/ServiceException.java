package org.ripv.exceptions;

import org.ripv.messages.ErrorCode;

/**
 * Thrown by a command handler to answer with a specific error code; its message goes to the
 * operator, so quote the bad value and say what to do.
 */
public class ServiceException extends Exception {
    private static final long serialVersionUID = 1L;
    private final ErrorCode code;

    public ServiceException(ErrorCode code, String message) {
        super(message);
        this.code = code;
    }

    public ServiceException(ErrorCode code, String message, Throwable cause) {
        super(message, cause);
        this.code = code;
    }

    public ErrorCode code() {
        return code;
    }
}
