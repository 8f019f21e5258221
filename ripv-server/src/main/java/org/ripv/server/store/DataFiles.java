package org.ripv.server.store;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.Locale;
import org.ripv.files.PrivateFiles;

/**
 * Owner-only directories and files written whole: a temporary file, then an atomic move; and the
 * file-name-safe keys the data directory uses for MailBoxes. Shared by the embedded store and
 * the tests that look at its files.
 */
public final class DataFiles {
    private DataFiles() {}

    /** An owner-only directory, and every directory made on the way owner-only too (workflows/ of workflows/queues). */
    public static Path directory(Path dir) throws IOException {
        PrivateFiles.createDirectories(dir);
        ownerOnly(dir, "rwx------");
        return dir;
    }

    /**
     * Makes a tree RIPV kept before files were owner-only whatever the umask owner-only: every
     * directory 0700 and file 0600 (issue 23, item 13: transcripts were 0644 in 0755 folders, the
     * audit log 0644, workflows/ 0755). Symbolic links are left alone.
     */
    public static void tighten(Path root) throws IOException {
        if (!Files.isDirectory(root, LinkOption.NOFOLLOW_LINKS) || PrivateFiles.isShared(root)) {
            return; // a shared folder (/tmp) holds others' files: never walked
        }
        try (var all = Files.walk(root)) {
            for (Path p : (Iterable<Path>) all::iterator) {
                if (!Files.isSymbolicLink(p)) {
                    ownerOnly(p, Files.isDirectory(p) ? "rwx------" : "rw-------");
                }
            }
        }
    }

    /** Replaces a file's text at once, owner-only: queues and subscriptions name users, addresses and URLs. */
    public static void write(Path file, String text) throws IOException {
        PrivateFiles.replace(file, text);
    }

    /** Writes a new file; never replaces one. */
    public static void create(Path file, String text) throws IOException {
        if (Files.exists(file)) {
            throw new FileAlreadyExistsException(file.toString());
        }
        write(file, text);
    }

    private static void ownerOnly(Path p, String mode) {
        if (PrivateFiles.isShared(p)) {
            return; // never a shared folder such as /tmp (PrivateFiles.restrict says why)
        }
        try {
            Files.setPosixFilePermissions(p, PosixFilePermissions.fromString(mode));
        } catch (UnsupportedOperationException | IOException e) {
            // not a POSIX file system (Windows): the data directory's own ACL applies
        }
    }

    /** A file-name-safe key for a MailBox address: readable letters plus a hash, so that none collide. */
    public static String key(String mailbox) {
        StringBuilder b = new StringBuilder();
        for (char c : mailbox.toCharArray()) {
            b.append(Character.isLetterOrDigit(c) || c == '-' || c == '.' ? c : '_');
            if (b.length() >= 60) {
                break;
            }
        }
        return b.toString().toLowerCase(Locale.ROOT) + "-" + sha256(mailbox.getBytes(StandardCharsets.UTF_8)).substring(0, 12);
    }

    public static String sha256(byte[] data) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(data));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }
}
