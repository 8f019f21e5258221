package org.ripv.services.serial.ymodem;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A file for a {@link YmodemSender}: its name and length for block 0 and a way to read it.
 *
 * @param name          the plain file name the receiver will use
 * @param length        exact length in bytes
 * @param mtimeSeconds  modification time (seconds since 1970) or 0
 * @param mode          Unix mode bits or 0
 * @param source        opens the content; read once per transfer
 */
public record SendFile(String name, long length, long mtimeSeconds, int mode, Source source) {

    /** Opens a file's content. */
    @FunctionalInterface
    public interface Source {
        InputStream open() throws IOException;
    }

    public SendFile {
        FileNames.requirePlain(name);
        if (length < 0) {
            throw new IllegalArgumentException("negative length " + length + " for '" + name + "'");
        }
    }

    public static SendFile of(String name, byte[] data) {
        return new SendFile(name, data.length, 0, 0, () -> new ByteArrayInputStream(data));
    }

    public static SendFile of(Path path) throws IOException {
        return new SendFile(path.getFileName().toString(), Files.size(path),
                Files.getLastModifiedTime(path).toMillis() / 1000, 0100644, () -> Files.newInputStream(path));
    }
}
