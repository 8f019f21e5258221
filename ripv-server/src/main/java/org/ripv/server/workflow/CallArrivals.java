package org.ripv.server.workflow;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.server.files.FileStore;

/**
 * What each call brought from the vehicle (the from-vehicle half of issue 24, item 3): the files
 * of the MailBox's download folder written between its SURFACED and the end of the call, listed
 * once when the call ends, so a pilot reads per call what came back.
 */
final class CallArrivals {
    private final Map<String, Long> callStarted = new ConcurrentHashMap<>();

    void surfaced(String mailbox) {
        callStarted.putIfAbsent(mailbox, System.currentTimeMillis());
    }

    /** The call ended: "this call brought 2 file(s): FOLDER/A (n bytes), …", or null when it brought none. */
    String ended(String mailbox, FileStore files) throws IOException {
        Long since = callStarted.remove(mailbox);
        if (since == null) {
            return null;
        }
        String folder = FileStore.folderFor(mailbox);
        Path dir = files.downloadDir().resolve(folder);
        if (!Files.isDirectory(dir)) {
            return null;
        }
        List<String> got = new ArrayList<>();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir)) {
            for (Path p : ds) {
                BasicFileAttributes a = Files.readAttributes(p, BasicFileAttributes.class);
                if (a.isRegularFile() && !p.getFileName().toString().startsWith(".")
                        && a.lastModifiedTime().toMillis() >= since - 1000) { // file times may be whole seconds
                    got.add(folder + "/" + p.getFileName() + " (" + a.size() + " bytes)");
                }
            }
        }
        got.sort(null);
        return got.isEmpty() ? null : "from-vehicle: this call brought " + got.size() + " file(s): " + String.join(", ", got);
    }
}
