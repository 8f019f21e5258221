package org.ripv.server.files;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.messages.FileListing;

/**
 * The server's upload directory (files from clients) and download directory (files from
 * services). Every write goes to a temporary file first and is moved into place whole, so a
 * failed or partial transfer never looks complete; names follow {@link FileNames}.
 */
public final class FileStore {
    private static final String PARTIAL = ".partial";

    private final Path uploadDir;
    private final Path downloadDir;
    private final long maxUpload;
    /** Chunked uploads in progress, by client id and name: the bytes received so far. */
    private final Map<String, Long> uploads = new ConcurrentHashMap<>();

    public FileStore(Path uploadDir, Path downloadDir, long maxUpload) throws IOException {
        this.uploadDir = Files.createDirectories(uploadDir).toRealPath();
        this.downloadDir = Files.createDirectories(downloadDir).toRealPath();
        this.maxUpload = maxUpload;
        Files.createDirectories(this.uploadDir.resolve(PARTIAL));
        Files.createDirectories(this.downloadDir.resolve(PARTIAL));
        clean(this.uploadDir.resolve(PARTIAL));
        clean(this.downloadDir.resolve(PARTIAL));
    }

    public Path uploadDir() {
        return uploadDir;
    }

    public Path downloadDir() {
        return downloadDir;
    }

    public long maxUpload() {
        return maxUpload;
    }

    /** The result of one chunk: how much has arrived, and whether the file is now complete. */
    public record ChunkResult(long received, long total, boolean complete) {}

    /**
     * Appends one chunk of a client's upload. Offset 0 starts (or restarts) the file; each later
     * chunk must continue exactly where the last ended; the last chunk moves the file into place.
     */
    public ChunkResult uploadChunk(String clientId, String name, long offset, long total, byte[] data) throws IOException {
        FileNames.check(name);
        if (total < 0 || offset < 0 || offset + data.length > total) {
            throw new IllegalArgumentException("chunk at " + offset + " of " + data.length + " bytes does not fit a file of " + total);
        }
        if (total > maxUpload) {
            abort(clientId, name);
            throw new FileTooLargeException("'" + name + "' is " + total + " bytes; the upload limit is " + maxUpload + " bytes");
        }
        String key = clientId + "/" + name;
        Path part = uploadDir.resolve(PARTIAL).resolve(clientId + "-" + name);
        if (offset == 0) {
            Files.write(part, data, StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE);
        } else {
            Long have = uploads.get(key);
            if (have == null || have != offset) {
                throw new IllegalArgumentException("upload of '" + name + "' expected offset " + (have == null ? 0 : have)
                        + " but got " + offset + "; start again from 0");
            }
            Files.write(part, data, StandardOpenOption.APPEND, StandardOpenOption.WRITE);
        }
        long received = offset + data.length;
        if (received == total) {
            uploads.remove(key);
            Files.move(part, uploadDir.resolve(name), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            return new ChunkResult(received, total, true);
        }
        uploads.put(key, received);
        return new ChunkResult(received, total, false);
    }

    /** Drops an unfinished upload. */
    public void abort(String clientId, String name) throws IOException {
        FileNames.check(name);
        uploads.remove(clientId + "/" + name);
        Files.deleteIfExists(uploadDir.resolve(PARTIAL).resolve(clientId + "-" + name));
    }

    /** Drops every unfinished upload of a client that went away. */
    public void abortAll(String clientId) {
        for (String key : List.copyOf(uploads.keySet())) {
            if (key.startsWith(clientId + "/")) {
                try {
                    abort(clientId, key.substring(clientId.length() + 1));
                } catch (IOException | IllegalArgumentException ignored) {
                    // the partial file goes at the next start anyway
                }
            }
        }
    }

    /** Reads a whole uploaded file, for attaching to a command. */
    public byte[] readUpload(String name) throws IOException {
        Path p = uploadDir.resolve(FileNames.check(name));
        try {
            long size = Files.size(p);
            if (size > maxUpload) {
                throw new FileTooLargeException("'" + name + "' is larger than the limit of " + maxUpload + " bytes");
            }
            return Files.readAllBytes(p);
        } catch (NoSuchFileException e) {
            throw new NoSuchFileException("no file '" + name + "' in the upload directory; upload it first (?ulfiles lists them)");
        }
    }

    /** Stores a file that came from a service in the download directory. */
    public Path storeDownload(String name, byte[] data) throws IOException {
        FileNames.check(name);
        Path tmp = Files.createTempFile(downloadDir.resolve(PARTIAL), "dl-", ".part");
        try {
            Files.write(tmp, data);
            return Files.move(tmp, downloadDir.resolve(name), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /** Reads up to {@code length} bytes of a downloaded file from {@code offset}; returns {total, bytes}. */
    public Object[] readDownload(String name, long offset, int length) throws IOException {
        Path p = downloadDir.resolve(FileNames.check(name));
        try (InputStream in = Files.newInputStream(p)) {
            long total = Files.size(p);
            if (offset < 0 || offset > total) {
                throw new IllegalArgumentException("offset " + offset + " is outside '" + name + "' (" + total + " bytes)");
            }
            in.skipNBytes(offset);
            byte[] data = in.readNBytes((int) Math.min(length, total - offset));
            return new Object[] {total, data};
        } catch (NoSuchFileException e) {
            throw new NoSuchFileException("no file '" + name + "' in the download directory (?dlfiles lists them)");
        }
    }

    public FileListing listUploads() throws IOException {
        return list(uploadDir);
    }

    public FileListing listDownloads() throws IOException {
        return list(downloadDir);
    }

    private static FileListing list(Path dir) throws IOException {
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
                }
            }
        }
        entries.sort(Comparator.comparing(FileListing.Entry::name));
        return new FileListing(dir.toString(), entries);
    }

    private static void clean(Path dir) throws IOException {
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir)) {
            for (Path p : ds) {
                Files.deleteIfExists(p);
            }
        }
    }
}
