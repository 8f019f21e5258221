package org.ripv.server.files;

import java.io.IOException;

/** A file of that name is in the store already and the request did not say replace or keep (FILE_EXISTS). */
public final class FileExistsException extends IOException {
    private static final long serialVersionUID = 1L;

    public FileExistsException(String message) {
        super(message);
    }
}
