package org.ripv.files;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.OpenOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileAttribute;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Set;

/**
 * Creates directories and files that only the account running RIPV can read ({@code 0700} and
 * {@code 0600}), whatever the umask. On a file system without POSIX permissions (Windows) the
 * calls fall back to the defaults, which there are per-user already.
 */
public final class PrivateFiles {
    private static final Set<PosixFilePermission> DIR = PosixFilePermissions.fromString("rwx------");
    private static final Set<PosixFilePermission> FILE = PosixFilePermissions.fromString("rw-------");

    private PrivateFiles() {}

    /** Like {@link Files#createDirectories}, each directory it creates being owner-only; returns {@code dir}. */
    public static Path createDirectories(Path dir) throws IOException {
        Path abs = dir.toAbsolutePath();
        if (Files.isDirectory(abs)) {
            return dir;
        }
        if (!posix(abs)) {
            return Files.createDirectories(dir);
        }
        Path parent = abs.getParent();
        if (parent != null && !Files.exists(parent)) {
            createDirectories(parent);
        }
        try {
            Files.createDirectory(abs, attribute(DIR));
        } catch (FileAlreadyExistsException e) {
            if (!Files.isDirectory(abs)) {
                throw e;
            }
            return dir;
        }
        restrict(abs);
        return dir;
    }

    /**
     * Makes an existing directory or file owner-only (directories 0700, files 0600). A shared
     * directory (sticky bit, as {@code /tmp}) is refused, not changed: pointed at one by mistake
     * ({@code --data /tmp}, a work folder) RIPV would lock every other user and service out of it.
     */
    public static void restrict(Path p) throws IOException {
        if (!posix(p)) {
            return;
        }
        if (isShared(p)) {
            throw new IOException(p.toAbsolutePath() + " is a shared directory (sticky bit, like /tmp): RIPV keeps its"
                    + " files owner-only and will not change it; give it a folder of its own, e.g. " + p.resolve("ripv"));
        }
        Files.setPosixFilePermissions(p, Files.isDirectory(p) ? DIR : FILE);
    }

    /** A directory with the sticky bit: many users' files side by side, never RIPV's alone. */
    public static boolean isShared(Path p) {
        try {
            return Files.isDirectory(p) && (((Integer) Files.getAttribute(p, "unix:mode")) & 01000) != 0;
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException e) {
            return false; // no unix view: nothing to protect this way
        }
    }

    /** Creates a new empty owner-only file; fails if it exists. */
    public static Path createFile(Path file) throws IOException {
        if (!posix(file)) {
            return Files.createFile(file);
        }
        Files.createFile(file, attribute(FILE));
        restrict(file);
        return file;
    }

    /** Creates an owner-only temporary file in {@code dir}. */
    public static Path createTempFile(Path dir, String prefix, String suffix) throws IOException {
        return posix(dir) ? Files.createTempFile(dir, prefix, suffix, attribute(FILE)) : Files.createTempFile(dir, prefix, suffix);
    }

    /** Opens a file for writing, creating it owner-only if it does not exist. */
    public static OutputStream newOutputStream(Path file, OpenOption... options) throws IOException {
        if (!Files.exists(file)) {
            try {
                createFile(file);
            } catch (FileAlreadyExistsException raced) {
                // someone made it meanwhile; its mode is set below
            }
        }
        restrict(file);
        return Files.newOutputStream(file, options.length == 0
                ? new OpenOption[] {StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING} : options);
    }

    /** Writes bytes to a file that is owner-only. */
    public static void write(Path file, byte[] data, OpenOption... options) throws IOException {
        try (OutputStream out = newOutputStream(file, options)) {
            out.write(data);
        }
    }

    /**
     * Replaces {@code file}'s text at once: written owner-only into a hidden {@code .NAME.tmp}
     * beside it, then moved over it (atomically where the file system can), so that a reader
     * sees the old text or the new, never half of it.
     */
    public static void replace(Path file, String text) throws IOException {
        Path tmp = file.resolveSibling("." + file.getFileName() + ".tmp");
        Files.deleteIfExists(tmp);
        createFile(tmp);
        Files.writeString(tmp, text, StandardCharsets.UTF_8);
        try {
            Files.move(tmp, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(tmp, file, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    private static FileAttribute<?>[] attribute(Set<PosixFilePermission> perms) {
        return new FileAttribute<?>[] {PosixFilePermissions.asFileAttribute(perms)};
    }

    private static boolean posix(Path p) {
        Path probe = p.toAbsolutePath();
        while (probe != null && !Files.exists(probe)) {
            probe = probe.getParent();
        }
        return probe != null && probe.getFileSystem().supportedFileAttributeViews().contains("posix");
    }
}
