package org.ripv.server.files;

import java.util.Locale;

/**
 * What an upload does when its name is taken ({@code ?upload NAME OFFSET TOTAL [replace|keep]}):
 * nothing is ever replaced unless asked.
 */
public enum UploadMode {
    /** No mode given: an existing name is refused with FILE_EXISTS. */
    REFUSE,
    /** {@code replace}: the existing file is replaced (needs the permit right {@code ?replace NAME}). */
    REPLACE,
    /** {@code keep}: both are kept; the new one is stored under a free name such as {@code NAME(1).ext}. */
    KEEP;

    /** {@code replace}, {@code keep}, or null for REFUSE. */
    public static UploadMode parse(String word) {
        if (word == null) {
            return REFUSE;
        }
        return switch (word.toLowerCase(Locale.ROOT)) {
            case "replace" -> REPLACE;
            case "keep" -> KEEP;
            default -> throw new IllegalArgumentException("upload mode '" + word + "' is not replace or keep");
        };
    }
}
