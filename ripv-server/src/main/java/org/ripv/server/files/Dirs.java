package org.ripv.server.files;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.FileListing;

/** What the upload and download directories do alike: list, clean, make a parent, size a file. */
final class Dirs {
    private Dirs() {}

    /** The files of {@code dir} (hidden ones left out) and, with {@code folders}, of its folders as {@code FOLDER/NAME}. */
    static FileListing list(Path dir, boolean folders) throws IOException {
        List<FileListing.Entry> entries = new ArrayList<>();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir)) {
            for (Path p : ds) {
                String n = p.getFileName().toString();
                if (n.startsWith(".")) {
                    continue;
                }
                BasicFileAttributes a = Files.readAttributes(p, BasicFileAttributes.class);
                if (a.isRegularFile()) {
                    entries.add(new FileListing.Entry(n, a.size(), a.lastModifiedTime().toMillis()));
                } else if (folders && a.isDirectory()) {
                    try (DirectoryStream<Path> inner = Files.newDirectoryStream(p)) {
                        for (Path q : inner) {
                            String m = q.getFileName().toString();
                            BasicFileAttributes b = Files.readAttributes(q, BasicFileAttributes.class);
                            if (!m.startsWith(".") && b.isRegularFile()) {
                                entries.add(new FileListing.Entry(n + "/" + m, b.size(), b.lastModifiedTime().toMillis()));
                            }
                        }
                    }
                }
            }
        }
        entries.sort(Comparator.comparing(FileListing.Entry::name));
        return new FileListing(dir.toString(), entries);
    }

    /** Empties a directory of files (the unfinished transfers a stopped server left). */
    static void clean(Path dir) throws IOException {
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir)) {
            for (Path p : ds) {
                Files.deleteIfExists(p);
            }
        }
    }

    static Path parentMade(Path p) throws IOException {
        PrivateFiles.createDirectories(p.getParent());
        return p;
    }

    static long sizeOrZero(Path p) {
        if (p == null) {
            return 0;
        }
        try {
            return Files.size(p);
        } catch (IOException e) {
            return 0;
        }
    }
}
