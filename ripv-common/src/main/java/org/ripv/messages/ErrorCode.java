package org.ripv.messages;

/**
 * Why a request failed. Travels in the {@link Footer} beside a message that quotes the bad
 * value and says what to do; the GUI shows it, the CLI prints {@code Error: ...}.
 */
public enum ErrorCode {
    NONE(0),
    BAD_REQUEST(400),
    NOT_LOGGED_IN(401),
    FORBIDDEN(403),
    UNKNOWN_COMMAND(404),
    UNKNOWN_MAILBOX(405),
    UNKNOWN_SERVICE(406),
    MAILBOX_LOCKED(409),
    TOO_LARGE(413),
    BAD_FILE_NAME(422),
    /** A file of that name is in the store already: nothing is replaced unless asked, with rights. */
    FILE_EXISTS(423),
    /** The request was cancelled ({@code ?cancel}) before or while it ran; the text says by whom. */
    CANCELLED(499),
    NOT_AVAILABLE(503),
    TIMEOUT(504),
    SERVICE_GONE(502),
    DEVICE_ERROR(520),
    TRANSFER_FAILED(521),
    DATABASE_ERROR(530),
    WORKER_ERROR(540),
    INTERNAL(500);

    private final int number;

    ErrorCode(int number) {
        this.number = number;
    }

    /** A stable number for scripts and logs. */
    public int number() {
        return number;
    }
}
