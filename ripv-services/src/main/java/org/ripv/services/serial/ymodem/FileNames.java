package org.ripv.services.serial.ymodem;

/** Checks file names that come off a link or from an operator before they touch a directory. */
public final class FileNames {
    private FileNames() {
    }

    /**
     * Returns {@code name} if it is a plain file name: not empty, at most 255 characters, no
     * slash or backslash, no leading dot, no control characters.
     *
     * @throws IllegalArgumentException quoting the name and why it was refused
     */
    public static String requirePlain(String name) {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException("empty file name");
        }
        if (name.length() > 255) {
            throw new IllegalArgumentException("file name '" + name.substring(0, 40) + "…' is longer than 255 characters");
        }
        if (name.indexOf('/') >= 0 || name.indexOf('\\') >= 0) {
            throw new IllegalArgumentException("file name '" + name + "' contains a slash; give a plain name");
        }
        if (name.startsWith(".")) {
            throw new IllegalArgumentException("file name '" + name + "' starts with a dot");
        }
        if (name.chars().anyMatch(c -> c < 0x20 || c == 0x7F)) {
            throw new IllegalArgumentException("file name '" + name.replaceAll("\\p{Cntrl}", "?") + "' contains control characters");
        }
        return name;
    }

    /** The last element of a path a sender put in block 0 (lrzsz may send a directory part). */
    public static String baseName(String sent) {
        String s = sent.replace('\\', '/');
        int slash = s.lastIndexOf('/');
        return slash >= 0 ? s.substring(slash + 1) : s;
    }
}
