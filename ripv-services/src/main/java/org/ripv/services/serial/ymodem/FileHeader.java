package org.ripv.services.serial.ymodem;

/**
 * What YMODEM's block 0 says about a file.
 *
 * @param name          the file name (no directory)
 * @param length        its length in bytes, or -1 when the sender did not say
 * @param mtimeSeconds  modification time in seconds since 1970, or 0 when not given
 * @param mode          Unix mode bits, or 0 when not given
 */
public record FileHeader(String name, long length, long mtimeSeconds, int mode) {
}
