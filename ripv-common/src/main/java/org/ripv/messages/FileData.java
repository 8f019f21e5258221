package org.ripv.messages;

import java.util.Objects;

/**
 * A file, or a chunk of one: {@code data} holds bytes {@code offset .. offset+data.length} of a
 * file of {@code total} bytes. A service hands files to the server this way; the server hands
 * them to clients in chunks so that no frame is large.
 */
public record FileData(String name, long offset, long total, byte[] data) implements Result {
    public FileData {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(data, "data");
        if (offset < 0 || total < 0 || offset + data.length > total) {
            throw new IllegalArgumentException("chunk " + offset + "+" + data.length + " outside a file of " + total);
        }
    }

    /** A whole file. */
    public static FileData whole(String name, byte[] data) {
        return new FileData(name, 0, data.length, data);
    }

    public boolean isLast() {
        return offset + data.length == total;
    }

    @Override
    public String toString() {
        return "FileData[" + name + " " + offset + "+" + data.length + "/" + total + "]";
    }
}
