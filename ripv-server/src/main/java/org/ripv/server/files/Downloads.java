package org.ripv.server.files;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.FileListing;
import org.ripv.naming.MailboxAddress;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The download directory: files from services, each MailBox's in a folder of its own
 * ({@code download/HANDLE@HOST@SERVICE/NAME}, marked with the MailBox's address), so one vehicle
 * cannot replace another's files; listed and fetched as {@code FOLDER/NAME}.
 */
final class Downloads {
    private static final Logger log = LoggerFactory.getLogger(Downloads.class);
    /** The file in each MailBox's folder that names the MailBox (hidden from listings). */
    static final String OWNER_FILE = ".mailbox";

    private final Path downloadDir;
    /** Bytes read back from the directory: what {@code ?download} and attached files cost (the data loop reads none). */
    private final AtomicLong bytesRead = new AtomicLong();

    Downloads(Path downloadDir) {
        this.downloadDir = downloadDir;
    }

    /**
     * Stores a file that came from a service's MailBox in that MailBox's own folder of the
     * download directory, replacing an earlier file of the same name from the same MailBox only.
     *
     * @param mailbox the MailBox's whole address ({@code <SerialPortServer>::<glider-pc>ttyV0}): its
     *                folder is {@link #folderFor} it, so two services with the same handle never share one
     * @return the name the file is listed and fetched by: {@code FOLDER/NAME}
     */
    String storeDownload(String mailbox, String name, byte[] data) throws IOException {
        FileNames.check(name);
        String f = folderFor(mailbox);
        Path dir = adopt(mailbox);
        Path tmp = PrivateFiles.createTempFile(downloadDir.resolve(FileStore.PARTIAL), "dl-", ".part");
        try {
            Files.write(tmp, data);
            Files.move(tmp, dir.resolve(name), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            return f + "/" + name;
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /**
     * A MailBox's folder of the download directory: {@code HANDLE@HOST@SERVICE}
     * ({@code ttyUSB0@glider-pc1@SerialPortServer}), unique to the whole address (issue 23, item 4:
     * folders named by the handle alone were shared by two glider PCs' {@code ttyUSB0}). A name
     * that had to be changed to be a file name (a character replaced, cut to length) ends in a
     * hash of the whole address, so it stays unique.
     */
    static String folderFor(String mailbox) {
        MailboxAddress a;
        try {
            a = MailboxAddress.parse(mailbox);
        } catch (RuntimeException e) {
            return folderName(mailbox);
        }
        String raw = a.handle() + "@" + a.service().host() + "@" + a.service().service();
        String clean = (part(a.handle()) + "@" + part(a.service().host()) + "@" + part(a.service().service()));
        if (clean.equals(raw) && clean.length() <= 64 && !clean.startsWith(".")) {
            return FileNames.check(clean);
        }
        String hash = HexFormat.of().formatHex(sha256(mailbox)).substring(0, 8);
        String head = clean.startsWith(".") ? "_" + clean.substring(1) : clean;
        return FileNames.check((head.length() > 55 ? head.substring(0, 55) : head) + "-" + hash);
    }

    private static String part(String s) {
        return s.replaceAll("[^A-Za-z0-9._+-]", "_");
    }

    private static byte[] sha256(String s) {
        try {
            return MessageDigest.getInstance("SHA-256").digest(s.getBytes(StandardCharsets.UTF_8));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is part of every JDK", e);
        }
    }

    /** {@link #adopt} for each MailBox a service lists as it registers; a folder that cannot be made is logged, not fatal. */
    void adoptAll(List<String> mailboxes) {
        for (String mb : mailboxes) {
            try {
                adopt(mb);
            } catch (IOException | RuntimeException e) {
                log.warn("could not make the download folder of {}: {}", mb, e.toString());
            }
        }
    }

    /**
     * The MailBox's folder, made if need be and marked with its address. A folder from before
     * folders were per address ({@code download/HANDLE/}, no mark) is moved here the first time
     * its MailBox is seen — at the service's registration or its first download.
     */
    synchronized Path adopt(String mailbox) throws IOException {
        Path dir = downloadDir.resolve(folderFor(mailbox));
        if (!Files.isDirectory(dir)) {
            String handle;
            try {
                handle = MailboxAddress.parse(mailbox).handle();
            } catch (RuntimeException e) {
                handle = null;
            }
            Path old = handle == null ? null : downloadDir.resolve(folderName(handle));
            if (old != null && !old.equals(dir) && Files.isDirectory(old) && !Files.exists(old.resolve(OWNER_FILE))) {
                Files.move(old, dir, StandardCopyOption.ATOMIC_MOVE);
                log.warn("moved download/{}/ (from before each MailBox's folder"
                        + " was unique to its address) to download/{}/ for {}; if two services had a MailBox {}, their files"
                        + " were mixed there before this version", old.getFileName(), dir.getFileName(), mailbox, handle);
            }
        }
        PrivateFiles.createDirectories(dir);
        Path mark = dir.resolve(OWNER_FILE);
        if (!Files.exists(mark)) {
            Path tmp = PrivateFiles.createTempFile(downloadDir.resolve(FileStore.PARTIAL), "mb-", ".part");
            try {
                Files.writeString(tmp, mailbox + "\n", StandardCharsets.UTF_8);
                Files.move(tmp, mark, StandardCopyOption.ATOMIC_MOVE);
            } finally {
                Files.deleteIfExists(tmp);
            }
        }
        return dir;
    }

    /**
     * The MailBox whose folder holds a download ({@code FOLDER/NAME}, or a plain name only one
     * folder holds), or empty for a loose file or a folder from before folders were per address:
     * rights on a download follow this MailBox (issue 23, item 5).
     */
    Optional<String> mailboxOf(String downloadName) throws IOException {
        Path p = downloadPath(downloadName);
        Path folder = p.getParent();
        if (folder == null || folder.equals(downloadDir)) {
            return Optional.empty();
        }
        Path mark = folder.resolve(OWNER_FILE);
        if (!Files.isRegularFile(mark)) {
            return Optional.empty();
        }
        String m = Files.readString(mark, StandardCharsets.UTF_8).strip();
        try {
            return Optional.of(MailboxAddress.parse(m).toString());
        } catch (RuntimeException e) {
            return Optional.empty();
        }
    }

    /** A MailBox handle as a folder name: {@link FileNames} rules, anything else replaced by '_'. */
    static String folderName(String handle) {
        String s = handle == null || handle.isBlank() ? "service" : handle.replaceAll("[^A-Za-z0-9._@+-]", "_");
        if (s.startsWith(".")) {
            s = "_" + s.substring(1);
        }
        return FileNames.check(s.length() > 64 ? s.substring(0, 64) : s);
    }

    /**
     * Reads up to {@code length} bytes of a downloaded file from {@code offset}; the file's size and the bytes.
     * The name is {@code FOLDER/NAME} as {@code ?dlfiles} lists it, or a plain NAME when only one
     * folder holds it.
     */
    DownloadChunk readDownload(String name, long offset, int length) throws IOException {
        Path p = downloadPath(name);
        try (InputStream in = Files.newInputStream(p)) {
            long total = Files.size(p);
            if (offset < 0 || offset > total) {
                throw new IllegalArgumentException("offset " + offset + " is outside '" + name + "' (" + total + " bytes)");
            }
            in.skipNBytes(offset);
            byte[] data = in.readNBytes((int) Math.min(length, total - offset));
            bytesRead.addAndGet(data.length);
            return new DownloadChunk(total, data);
        } catch (NoSuchFileException e) {
            throw new NoSuchFileException("no file '" + name + "' in the download directory (?dlfiles lists them)");
        }
    }

    /** Where a download name points: one folder level at most, each part a plain name. */
    private Path downloadPath(String name) throws IOException {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException("a file name is required");
        }
        int slash = name.indexOf('/');
        if (slash >= 0) {
            String folder = name.substring(0, slash);
            String file = name.substring(slash + 1);
            try {
                if (folder.equals(FileStore.PARTIAL)) {
                    throw new IllegalArgumentException("'" + name + "' is not a download");
                }
                return downloadDir.resolve(FileNames.check(folder)).resolve(FileNames.check(file));
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("a download name holds at most one slash, between a MailBox's folder and"
                        + " a plain file name (FOLDER/NAME as ?dlfiles lists it): " + e.getMessage());
            }
        }
        FileNames.check(name);
        Path top = downloadDir.resolve(name);
        if (Files.isRegularFile(top)) {
            return top;
        }
        List<String> found = new ArrayList<>();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(downloadDir, Files::isDirectory)) {
            for (Path d : ds) {
                String folder = d.getFileName().toString();
                if (!folder.startsWith(".") && Files.isRegularFile(d.resolve(name))) {
                    found.add(folder + "/" + name);
                }
            }
        }
        if (found.size() > 1) {
            found.sort(null);
            throw new IllegalArgumentException("'" + name + "' came from several MailBoxes: " + String.join(", ", found)
                    + "; name one of them");
        }
        if (found.isEmpty()) {
            throw new NoSuchFileException("no file '" + name + "' in the download directory (?dlfiles lists them)");
        }
        return downloadDir.resolve(found.get(0));
    }

    /** The download directory: files of each MailBox's folder as {@code FOLDER/NAME}, and any loose files. */
    FileListing listDownloads() throws IOException {
        return Dirs.list(downloadDir, true);
    }

    /** Whether a download folder belongs to a MailBox (one a service has registered, marked by {@link #adopt}). */
    boolean isMailboxFolder(String folder) {
        return Files.isRegularFile(downloadDir.resolve(FileNames.check(folder)).resolve(OWNER_FILE));
    }

    long bytesRead() {
        return bytesRead.get();
    }

    /** Deletes a {@code FOLDER/NAME} as {@code ?dlfiles} lists it. */
    void delete(String name) throws IOException {
        Path p = downloadPath(name);
        if (!Files.deleteIfExists(p)) {
            throw new NoSuchFileException("no file '" + name + "' in the download directory (?dlfiles lists them)");
        }
    }
}
