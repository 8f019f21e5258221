package org.ripv.exceptions;

import org.ripv.messages.ErrorCode;

/** A handler's resource failed (a serial link dropped, a database went away). Thesis: HandlerException. */
public class HandlerException extends ServiceException {
    private static final long serialVersionUID = 1L;

    public HandlerException(String message, Throwable cause) {
        super(ErrorCode.DEVICE_ERROR, message, cause);
    }

    public HandlerException(String message) {
        super(ErrorCode.DEVICE_ERROR, message);
    }
}
