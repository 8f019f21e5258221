package org.ripv.messages;

import java.io.Serializable;
import java.util.List;

/** A directory listing (the server's upload or download directory, a vehicle's files). */
public record FileListing(String directory, List<Entry> files) implements Result {
    public FileListing {
        directory = directory == null ? "" : directory;
        files = files == null ? List.of() : List.copyOf(files);
    }

    /** One file: its name, size in bytes and last modification (epoch milliseconds). */
    public record Entry(String name, long size, long modified) implements Serializable {}
}
