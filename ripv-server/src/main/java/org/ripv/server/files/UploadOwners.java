package org.ripv.server.files;

import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Collection;
import java.util.List;
import java.util.Properties;
import org.ripv.files.PrivateFiles;

/**
 * Who stored each upload ({@code upload/.owners}), for the per-user quota and for who may drop a
 * refused typed workflow. Every change is written through a temporary file and an atomic move.
 */
final class UploadOwners {
    private static final String OWNERS = ".owners";

    private final Path uploadDir;
    private final Properties owners = new Properties();

    UploadOwners(Path uploadDir) throws IOException {
        this.uploadDir = uploadDir;
        Path o = uploadDir.resolve(OWNERS);
        if (Files.exists(o)) {
            try (Reader r = Files.newBufferedReader(o, StandardCharsets.UTF_8)) {
                owners.load(r);
            }
        }
    }

    /** Who stored an upload, or empty when unknown (put there by hand). */
    synchronized String of(String name) {
        return owners.getProperty(name, "");
    }

    /** The uploads {@code user} stored. */
    synchronized List<String> namesOf(String user) {
        return owners.stringPropertyNames().stream().filter(n -> user.equals(owners.getProperty(n))).toList();
    }

    /** Records {@code user} as the owner of each name; an empty or null user forgets them. */
    synchronized void set(Collection<String> names, String user) throws IOException {
        for (String name : names) {
            if (user != null && !user.isEmpty()) {
                owners.setProperty(name, user);
            } else {
                owners.remove(name);
            }
        }
        save();
    }

    /** Forgets a name that left the upload directory. */
    synchronized void remove(String name) throws IOException {
        if (owners.remove(name) != null) {
            save();
        }
    }

    private void save() throws IOException {
        Path tmp = PrivateFiles.createTempFile(uploadDir.resolve(FileStore.PARTIAL), "owners-", ".tmp");
        try (Writer w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
            owners.store(w, "who uploaded each file (for the upload quota)");
        }
        Files.move(tmp, uploadDir.resolve(OWNERS), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
