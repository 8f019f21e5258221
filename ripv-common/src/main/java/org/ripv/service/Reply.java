package org.ripv.service;

import org.ripv.messages.ErrorCode;
import org.ripv.messages.Result;
import org.ripv.messages.Status;

/** A command handler's final answer: OK with text and an optional typed result, or ERROR. */
public record Reply(Status status, ErrorCode code, String text, Result result) {
    public Reply {
        if (status == Status.PROGRESS) {
            throw new IllegalArgumentException("a final reply is OK or ERROR; send progress with Request.progress");
        }
        code = code == null ? ErrorCode.NONE : code;
        text = text == null ? "" : text;
    }

    public static Reply ok(String text) {
        return new Reply(Status.OK, ErrorCode.NONE, text, null);
    }

    public static Reply ok(String text, Result result) {
        return new Reply(Status.OK, ErrorCode.NONE, text, result);
    }

    public static Reply error(ErrorCode code, String text) {
        return new Reply(Status.ERROR, code, text, null);
    }
}
