package org.ripv.server.files;

import java.io.IOException;

/** A file over the server's size limit. */
public class FileTooLargeException extends IOException {
    private static final long serialVersionUID = 1L;

    public FileTooLargeException(String message) {
        super(message);
    }
}
