package org.ripv.server.web;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * Where the upload form's files go: the server's own store, by the rules {@code ?upload} keeps
 * (the user's quota, who owns each file, owner-only modes, never over an existing file), so the
 * form and the client's chunks obey one rule (issue 33 item 5).
 */
public interface FormUploads {
    /**
     * Stores the form's files (parked on disk, by asked name) for {@code user}, all or none.
     *
     * @return the names stored
     * @throws org.ripv.server.files.FileExistsException   a name is taken
     * @throws org.ripv.server.files.FileTooLargeException over the upload limit or the user's quota
     */
    List<String> store(String user, Map<String, Path> parked) throws IOException;
}
