package org.ripv.services.ingest;

/** A Slocum binary file that cannot be decoded: names the file, the byte offset and why. */
public class SlocumFormatException extends Exception {
    private static final long serialVersionUID = 1L;
    private final String file;
    private final long offset;

    public SlocumFormatException(String file, long offset, String reason) {
        super(file + ": byte " + offset + ": " + reason);
        this.file = file;
        this.offset = offset;
    }

    public String file() {
        return file;
    }

    /** Where in the file (0-based; of the decompressed bytes for a compressed file) the problem is. */
    public long offset() {
        return offset;
    }
}
