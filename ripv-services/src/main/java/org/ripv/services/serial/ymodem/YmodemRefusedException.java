package org.ripv.services.serial.ymodem;

/**
 * The other end answered a transfer's start with text instead of YMODEM (a shell's "Bad command",
 * then its prompt): nothing was transferred, and the start may be tried again once the line is
 * clean (a stray byte in the vehicle's line is the usual cause).
 */
public class YmodemRefusedException extends YmodemException {
    private static final long serialVersionUID = 1L;

    public YmodemRefusedException(String message) {
        super(message);
    }
}
