package org.ripv.server.files;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.FileListing;

/**
 * The upload directory: files from clients, in chunks or whole, never over an existing name
 * unless asked ({@link UploadMode}), within each user's quota ({@link UploadOwners}), and the
 * to-vehicle folders whose files go out on a vehicle's next call ({@link ToVehicleFolder}).
 */
final class Uploads {
    /** How many {@code NAME(n).ext} a keep tries before giving up. */
    private static final int MAX_KEEP = 1000;

    private final Path uploadDir;
    private final long maxUpload;
    private final UploadOwners owners;
    /** Chunked uploads in progress, by client id and name. */
    private final Map<String, Upload> uploads = new ConcurrentHashMap<>();

    private record Upload(String user, long total, long received, UploadMode mode) {}

    Uploads(Path uploadDir, long maxUpload) throws IOException {
        this.uploadDir = uploadDir;
        this.maxUpload = maxUpload;
        this.owners = new UploadOwners(uploadDir);
    }

    /** {@link #uploadChunk(String, String, String, long, long, byte[], UploadMode, long)} refusing a taken name, no quota. */
    FileStore.ChunkResult uploadChunk(String clientId, String name, long offset, long total, byte[] data) throws IOException {
        return uploadChunk(clientId, "", name, offset, total, data, UploadMode.REFUSE, Long.MAX_VALUE);
    }

    /**
     * Appends one chunk of a client's upload. Offset 0 starts (or restarts) the file; each later
     * chunk must continue exactly where the last ended; the last chunk moves the file into place
     * as {@code mode} says.
     *
     * @param quota the most bytes {@code user} may hold in the upload directory, this file included
     * @throws FileExistsException   the name is taken and {@code mode} is REFUSE
     * @throws FileTooLargeException over the size limit or the user's quota
     */
    FileStore.ChunkResult uploadChunk(String clientId, String user, String name, long offset, long total, byte[] data,
                                   UploadMode mode, long quota) throws IOException {
        uploadPath(name);
        if (total < 0 || offset < 0 || offset + data.length > total) {
            throw new IllegalArgumentException("chunk at " + offset + " of " + data.length + " bytes does not fit a file of " + total);
        }
        if (total > maxUpload) {
            abort(clientId, name);
            throw new FileTooLargeException("'" + name + "' is " + total + " bytes; the upload limit is " + maxUpload + " bytes");
        }
        String key = clientId + "/" + name;
        Path part = partOf(clientId, name);
        if (offset == 0) {
            if (mode == UploadMode.REFUSE && Files.exists(uploadPath(name))) {
                abort(clientId, name);
                throw exists(name);
            }
            long used = usedBy(user, key) + (mode == UploadMode.REPLACE && user.equals(owners.of(name))
                    ? -Dirs.sizeOrZero(uploadPath(name)) : 0);
            if (used + total > quota) {
                abort(clientId, name);
            }
            requireQuota(user, used, total, quota, "'" + name + "'");
            PrivateFiles.write(part, data, StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE);
        } else {
            Upload have = uploads.get(key);
            if (have == null || have.received() != offset || have.total() != total) {
                throw new IllegalArgumentException("upload of '" + name + "' expected offset " + (have == null ? 0 : have.received())
                        + " but got " + offset + "; start again from 0");
            }
            Files.write(part, data, StandardOpenOption.APPEND, StandardOpenOption.WRITE);
        }
        long received = offset + data.length;
        if (received == total) {
            uploads.remove(key);
            try {
                String stored = place(part, name, mode, user);
                return new FileStore.ChunkResult(received, total, true, stored);
            } finally {
                Files.deleteIfExists(part);
            }
        }
        uploads.put(key, new Upload(user, total, received, mode));
        return new FileStore.ChunkResult(received, total, false, name);
    }

    /** The quota rule, one for the client's chunks and the web form: what a user holds plus what arrives. */
    private static void requireQuota(String user, long used, long adding, long quota, String what) throws FileTooLargeException {
        if (used + adding > quota) {
            throw new FileTooLargeException(what + " (" + adding + " bytes) would take " + user + " to " + (used + adding)
                    + " bytes in the upload directory; the quota is " + quota + " bytes (?delete old files first)");
        }
    }

    /**
     * Stores whole files that arrived another way (the web form, already on disk, by asked name) for
     * {@code user}, with the chunks' rules: names checked, never over an existing file, the user's
     * quota for them together, each remembered as theirs ({@code .owners}) and owner-only. All or none.
     *
     * @return the names stored
     * @throws FileExistsException   a name is taken (nothing stored)
     * @throws FileTooLargeException over the upload limit or the quota (nothing stored)
     */
    synchronized List<String> storeWhole(String user, Map<String, Path> files, long quota) throws IOException {
        long adding = 0;
        for (Map.Entry<String, Path> f : files.entrySet()) {
            if (Files.exists(uploadPath(f.getKey()))) {
                throw exists(f.getKey());
            }
            long size = Files.size(f.getValue());
            if (size > maxUpload) {
                throw new FileTooLargeException("'" + f.getKey() + "' is " + size + " bytes; the upload limit is " + maxUpload + " bytes");
            }
            adding += size;
        }
        requireQuota(user, usedBy(user, ""), adding, quota, files.size() == 1 ? "'" + files.keySet().iterator().next() + "'"
                : files.size() + " files");
        List<String> stored = new ArrayList<>();
        try {
            for (Map.Entry<String, Path> f : files.entrySet()) {
                PrivateFiles.restrict(f.getValue());
                if (!linkInto(f.getValue(), f.getKey())) {
                    throw exists(f.getKey());
                }
                stored.add(f.getKey());
            }
        } catch (IOException | RuntimeException e) {
            for (String name : stored) {
                Files.deleteIfExists(uploadPath(name)); // all or none
            }
            throw e;
        }
        owners.set(stored, user);
        return stored;
    }

    private static FileExistsException exists(String name) {
        return new FileExistsException("'" + name + "' is in the upload directory already; nothing was replaced."
                + " Upload again with 'replace' (needs the right) or 'keep' (stores it under a new name)");
    }

    /** Moves a finished upload into place: never over an existing file unless {@code mode} is REPLACE. */
    private synchronized String place(Path part, String name, UploadMode mode, String user) throws IOException {
        String stored = name;
        switch (mode) {
            case REPLACE -> Files.move(part, Dirs.parentMade(uploadPath(name)), StandardCopyOption.REPLACE_EXISTING,
                    StandardCopyOption.ATOMIC_MOVE);
            case REFUSE -> {
                if (!linkInto(part, name)) {
                    throw exists(name);
                }
            }
            case KEEP -> {
                int n = 0;
                while (!linkInto(part, stored)) {
                    if (++n > MAX_KEEP) {
                        throw new FileExistsException("no free name like '" + name + "' after " + MAX_KEEP + " tries");
                    }
                    stored = numbered(name, n);
                }
            }
            default -> throw new IllegalStateException(mode.toString());
        }
        owners.set(List.of(stored), user);
        return stored;
    }

    /** Puts {@code part} in the upload directory as {@code name} unless that exists; false if it does. */
    private boolean linkInto(Path part, String name) throws IOException {
        Path target = Dirs.parentMade(uploadPath(name));
        try {
            Files.createLink(target, part); // atomic: fails if the name is taken, never replaces
            return true;
        } catch (FileAlreadyExistsException e) {
            return false;
        } catch (UnsupportedOperationException e) {
            if (Files.exists(target)) {
                return false;
            }
            Files.move(part, target); // no hard links here: place() is synchronized against ourselves
            return true;
        }
    }

    /** {@code log.txt} → {@code log(1).txt}; {@code README} → {@code README(1)}. */
    static String numbered(String name, int n) {
        int dot = name.lastIndexOf('.');
        int slash = name.lastIndexOf('/');
        return dot > slash + 1 ? name.substring(0, dot) + "(" + n + ")" + name.substring(dot) : name + "(" + n + ")";
    }

    /** Bytes {@code user} holds in the upload directory plus what their other unfinished uploads will add. */
    private long usedBy(String user, String exceptKey) {
        long used = 0;
        for (String name : owners.namesOf(user)) {
            used += Dirs.sizeOrZero(uploadPathOrNull(name));
        }
        for (Map.Entry<String, Upload> e : uploads.entrySet()) {
            if (!e.getKey().equals(exceptKey) && e.getValue().user().equals(user)) {
                used += e.getValue().total();
            }
        }
        return used;
    }

    /** Bytes {@code user} holds in the upload directory. */
    long usage(String user) {
        return usedBy(user, "");
    }

    /** Who stored an upload, or empty when unknown (put there by hand). */
    String owner(String name) {
        return owners.of(name);
    }

    /** Drops an unfinished upload. */
    void abort(String clientId, String name) throws IOException {
        uploadPath(name);
        uploads.remove(clientId + "/" + name);
        Files.deleteIfExists(partOf(clientId, name));
    }

    /** Where an unfinished upload grows: one flat folder, so a to-vehicle name's slashes become '~'. */
    private Path partOf(String clientId, String name) {
        return uploadDir.resolve(FileStore.PARTIAL).resolve(clientId + "-" + name.replace('/', '~'));
    }

    /**
     * Where an upload name points: a plain NAME in the upload directory, or a to-vehicle file
     * ({@code to-vehicle/FOLDER/NAME}, {@link ToVehicleFolder}); anything else is refused.
     */
    Path uploadPath(String name) {
        if (ToVehicleFolder.isToVehicle(name)) {
            return ToVehicleFolder.parse(name).in(uploadDir);
        }
        return uploadDir.resolve(FileNames.check(name));
    }

    private Path uploadPathOrNull(String name) {
        try {
            return uploadPath(name);
        } catch (IllegalArgumentException e) {
            return null;
        }
    }

    /**
     * The files waiting in a MailBox's to-vehicle folder, oldest first, as {@code to-vehicle/FOLDER/NAME}.
     */
    List<String> toVehiclePending(String mailbox) throws IOException {
        String folder = Downloads.folderFor(mailbox);
        Path dir = uploadDir.resolve(ToVehicleFolder.DIR).resolve(folder);
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        List<Path> files = new ArrayList<>();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir, p -> Files.isRegularFile(p)
                && !p.getFileName().toString().startsWith("."))) {
            ds.forEach(files::add);
        }
        files.sort(Comparator.comparing((Path p) -> {
            try {
                return Files.getLastModifiedTime(p).toMillis();
            } catch (IOException e) {
                return 0L;
            }
        }).thenComparing(Path::toString));
        return files.stream().map(p -> ToVehicleFolder.DIR + "/" + folder + "/" + p.getFileName()).toList();
    }

    /**
     * Moves a to-vehicle file its vehicle now has into {@code sent/} (under a free name if an
     * earlier one of that name is there), with {@code receipt} beside it as {@code NAME.receipt};
     * returns the sent file's name. The receipt is written first: a file in {@code sent/} always has one.
     * The file no longer counts against its uploader's quota.
     */
    synchronized String toVehicleSent(String name, String receipt) throws IOException {
        ToVehicleFolder.Name n = ToVehicleFolder.parse(name);
        Path from = n.in(uploadDir);
        Path sent = PrivateFiles.createDirectories(from.getParent().resolve(ToVehicleFolder.SENT));
        String stored = n.file();
        for (int i = 1; Files.exists(sent.resolve(stored)) || Files.exists(sent.resolve(stored + ".receipt")); i++) {
            if (i > MAX_KEEP) {
                throw new FileExistsException("no free name like '" + n.file() + "' in " + sent + " after " + MAX_KEEP + " tries");
            }
            stored = numbered(n.file(), i);
        }
        Path tmp = PrivateFiles.createTempFile(uploadDir.resolve(FileStore.PARTIAL), "receipt-", ".tmp");
        try {
            Files.writeString(tmp, receipt, StandardCharsets.UTF_8);
            Files.move(tmp, sent.resolve(stored + ".receipt"), StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
        Files.move(from, sent.resolve(stored), StandardCopyOption.ATOMIC_MOVE);
        String sentName = ToVehicleFolder.DIR + "/" + n.folder() + "/" + ToVehicleFolder.SENT + "/" + stored;
        // sent files leave the uploader's quota: ?delete cannot reach sent/, the receipt names who it was
        owners.remove(name);
        return sentName;
    }

    /** Drops every unfinished upload of a client that went away. */
    void abortAll(String clientId) {
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
    byte[] readUpload(String name) throws IOException {
        Path p = uploadPath(name);
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

    /** The upload directory, and the files waiting in each to-vehicle folder as {@code to-vehicle/FOLDER/NAME}. */
    FileListing listUploads() throws IOException {
        FileListing plain = Dirs.list(uploadDir, false);
        Path tv = uploadDir.resolve(ToVehicleFolder.DIR);
        if (!Files.isDirectory(tv)) {
            return plain;
        }
        List<FileListing.Entry> entries = new ArrayList<>(plain.files());
        for (FileListing.Entry e : Dirs.list(tv, true).files()) {
            entries.add(new FileListing.Entry(ToVehicleFolder.DIR + "/" + e.name(), e.size(), e.modified()));
        }
        entries.sort(Comparator.comparing(FileListing.Entry::name));
        return new FileListing(plain.directory(), entries);
    }

    /** Deletes a plain NAME or a waiting {@code to-vehicle/FOLDER/NAME}; returns where it was. */
    synchronized String delete(String name) throws IOException {
        if (ToVehicleFolder.isToVehicle(name)) {
            Path p = uploadPath(name);
            if (!Files.deleteIfExists(p)) {
                throw new NoSuchFileException("no file '" + name + "' waiting in the to-vehicle folder (?ulfiles lists them)");
            }
            owners.remove(name);
            return "to-vehicle folder";
        }
        Path p = uploadDir.resolve(FileNames.check(name));
        if (!Files.deleteIfExists(p)) {
            throw new NoSuchFileException("no file '" + name + "' in the upload directory (?ulfiles lists them);"
                    + " a download is named FOLDER/NAME as ?dlfiles lists it");
        }
        owners.remove(name);
        return "upload directory";
    }
}
