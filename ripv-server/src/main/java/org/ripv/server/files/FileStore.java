package org.ripv.server.files;

import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Properties;
import java.util.concurrent.ConcurrentHashMap;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.FileListing;
import org.ripv.naming.MailboxAddress;
import org.slf4j.LoggerFactory;

/**
 * The server's upload directory (files from clients) and download directory (files from
 * services). Every write goes to a temporary file first and is moved into place whole, so a
 * failed or partial transfer never looks complete; names follow {@link FileNames}.
 *
 * <ul>
 *   <li>An upload never replaces a file silently ({@link UploadMode}): without a mode an existing
 *       name is refused ({@link FileExistsException}), {@code keep} picks a free name.</li>
 *   <li>Each MailBox's downloads live in a folder of their own, {@code download/HANDLE/NAME}, so one
 *       vehicle cannot replace another's files; their names are listed as {@code HANDLE/NAME}.</li>
 *   <li>Who uploaded each file is remembered ({@code upload/.owners}) for the per-user quota.</li>
 *   <li>Directories and files are owner-only (0700/0600).</li>
 * </ul>
 */
public final class FileStore {
    private static final String PARTIAL = ".partial";
    private static final String OWNERS = ".owners";
    /** How many {@code NAME(n).ext} a keep tries before giving up. */
    private static final int MAX_KEEP = 1000;

    private final Path uploadDir;
    private final Path downloadDir;
    private final long maxUpload;
    /** Chunked uploads in progress, by client id and name. */
    private final Map<String, Upload> uploads = new ConcurrentHashMap<>();
    /** Upload name to the user who stored it. */
    private final Properties owners = new Properties();

    private record Upload(String user, long total, long received, UploadMode mode) {}

    public FileStore(Path uploadDir, Path downloadDir, long maxUpload) throws IOException {
        this.uploadDir = PrivateFiles.createDirectories(uploadDir).toRealPath();
        this.downloadDir = PrivateFiles.createDirectories(downloadDir).toRealPath();
        this.maxUpload = maxUpload;
        PrivateFiles.restrict(this.uploadDir);
        PrivateFiles.restrict(this.downloadDir);
        PrivateFiles.createDirectories(this.uploadDir.resolve(PARTIAL));
        PrivateFiles.createDirectories(this.downloadDir.resolve(PARTIAL));
        clean(this.uploadDir.resolve(PARTIAL));
        clean(this.downloadDir.resolve(PARTIAL));
        Path o = this.uploadDir.resolve(OWNERS);
        if (Files.exists(o)) {
            try (Reader r = Files.newBufferedReader(o, StandardCharsets.UTF_8)) {
                owners.load(r);
            }
        }
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

    /**
     * The result of one chunk: how much has arrived, whether the file is now complete, and the
     * name it was stored under (differs from the asked name after a {@code keep}).
     */
    public record ChunkResult(long received, long total, boolean complete, String storedAs) {}

    /** {@link #uploadChunk(String, String, String, long, long, byte[], UploadMode, long)} refusing a taken name, no quota. */
    public ChunkResult uploadChunk(String clientId, String name, long offset, long total, byte[] data) throws IOException {
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
    public ChunkResult uploadChunk(String clientId, String user, String name, long offset, long total, byte[] data,
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
            long used = usedBy(user, key) + (mode == UploadMode.REPLACE && user.equals(owners.getProperty(name))
                    ? -sizeOrZero(uploadPath(name)) : 0);
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
                return new ChunkResult(received, total, true, stored);
            } finally {
                Files.deleteIfExists(part);
            }
        }
        uploads.put(key, new Upload(user, total, received, mode));
        return new ChunkResult(received, total, false, name);
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
    public synchronized List<String> storeWhole(String user, Map<String, Path> files, long quota) throws IOException {
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
        stored.forEach(name -> owners.setProperty(name, user));
        saveOwners();
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
            case REPLACE -> Files.move(part, parentMade(uploadPath(name)), StandardCopyOption.REPLACE_EXISTING,
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
        if (user != null && !user.isEmpty()) {
            owners.setProperty(stored, user);
        } else {
            owners.remove(stored);
        }
        saveOwners();
        return stored;
    }

    /** Puts {@code part} in the upload directory as {@code name} unless that exists; false if it does. */
    private boolean linkInto(Path part, String name) throws IOException {
        Path target = parentMade(uploadPath(name));
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
        for (String name : owners.stringPropertyNames()) {
            if (user.equals(owners.getProperty(name))) {
                used += sizeOrZero(uploadPathOrNull(name));
            }
        }
        for (Map.Entry<String, Upload> e : uploads.entrySet()) {
            if (!e.getKey().equals(exceptKey) && e.getValue().user().equals(user)) {
                used += e.getValue().total();
            }
        }
        return used;
    }

    /** Bytes {@code user} holds in the upload directory. */
    public long usage(String user) {
        return usedBy(user, "");
    }

    /** Who stored an upload, or empty when unknown (put there by hand). */
    public String owner(String name) {
        return owners.getProperty(name, "");
    }

    private static long sizeOrZero(Path p) {
        if (p == null) {
            return 0;
        }
        try {
            return Files.size(p);
        } catch (IOException e) {
            return 0;
        }
    }

    private void saveOwners() throws IOException {
        Path tmp = PrivateFiles.createTempFile(uploadDir.resolve(PARTIAL), "owners-", ".tmp");
        try (Writer w = Files.newBufferedWriter(tmp, StandardCharsets.UTF_8)) {
            owners.store(w, "who uploaded each file (for the upload quota)");
        }
        Files.move(tmp, uploadDir.resolve(OWNERS), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    /** Drops an unfinished upload. */
    public void abort(String clientId, String name) throws IOException {
        uploadPath(name);
        uploads.remove(clientId + "/" + name);
        Files.deleteIfExists(partOf(clientId, name));
    }

    /** Whether a download folder belongs to a MailBox (one a service has registered, marked by {@link #adopt}). */
    public boolean isMailboxFolder(String folder) {
        return Files.isRegularFile(downloadDir.resolve(FileNames.check(folder)).resolve(OWNER_FILE));
    }

    /** Where an unfinished upload grows: one flat folder, so a to-vehicle name's slashes become '~'. */
    private Path partOf(String clientId, String name) {
        return uploadDir.resolve(PARTIAL).resolve(clientId + "-" + name.replace('/', '~'));
    }

    /**
     * Where an upload name points: a plain NAME in the upload directory, or a to-vehicle file
     * ({@code to-vehicle/FOLDER/NAME}, {@link ToVehicleFolder}); anything else is refused.
     */
    public Path uploadPath(String name) {
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

    private static Path parentMade(Path p) throws IOException {
        PrivateFiles.createDirectories(p.getParent());
        return p;
    }

    /**
     * The files waiting in a MailBox's to-vehicle folder, oldest first, as {@code to-vehicle/FOLDER/NAME}.
     */
    public List<String> toVehiclePending(String mailbox) throws IOException {
        String folder = folderFor(mailbox);
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
    public synchronized String toVehicleSent(String name, String receipt) throws IOException {
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
        Path tmp = PrivateFiles.createTempFile(uploadDir.resolve(PARTIAL), "receipt-", ".tmp");
        try {
            Files.writeString(tmp, receipt, StandardCharsets.UTF_8);
            Files.move(tmp, sent.resolve(stored + ".receipt"), StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
        Files.move(from, sent.resolve(stored), StandardCopyOption.ATOMIC_MOVE);
        String sentName = ToVehicleFolder.DIR + "/" + n.folder() + "/" + ToVehicleFolder.SENT + "/" + stored;
        // sent files leave the uploader's quota: ?delete cannot reach sent/, the receipt names who it was
        if (owners.remove(name) != null) {
            saveOwners();
        }
        return sentName;
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

    /**
     * Deletes a stored file: a plain NAME from the upload directory, a {@code FOLDER/NAME} (as
     * {@code ?dlfiles} lists it) from the download directory. Returns where it was.
     */
    public synchronized String delete(String name) throws IOException {
        if (ToVehicleFolder.isToVehicle(name)) {
            Path p = uploadPath(name);
            if (!Files.deleteIfExists(p)) {
                throw new NoSuchFileException("no file '" + name + "' waiting in the to-vehicle folder (?ulfiles lists them)");
            }
            if (owners.remove(name) != null) {
                saveOwners();
            }
            return "to-vehicle folder";
        }
        if (name.indexOf('/') >= 0) {
            Path p = downloadPath(name);
            if (!Files.deleteIfExists(p)) {
                throw new NoSuchFileException("no file '" + name + "' in the download directory (?dlfiles lists them)");
            }
            return "download directory";
        }
        Path p = uploadDir.resolve(FileNames.check(name));
        if (!Files.deleteIfExists(p)) {
            throw new NoSuchFileException("no file '" + name + "' in the upload directory (?ulfiles lists them);"
                    + " a download is named FOLDER/NAME as ?dlfiles lists it");
        }
        if (owners.remove(name) != null) {
            saveOwners();
        }
        return "upload directory";
    }

    /** Reads a whole uploaded file, for attaching to a command. */
    public byte[] readUpload(String name) throws IOException {
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

    /**
     * Stores a file that came from a service's MailBox in that MailBox's own folder of the
     * download directory, replacing an earlier file of the same name from the same MailBox only.
     *
     * @param mailbox the MailBox's whole address ({@code <SerialPortServer>::<glider-pc>ttyV0}): its
     *                folder is {@link #folderFor} it, so two services with the same handle never share one
     * @return the name the file is listed and fetched by: {@code FOLDER/NAME}
     */
    public String storeDownload(String mailbox, String name, byte[] data) throws IOException {
        FileNames.check(name);
        String f = folderFor(mailbox);
        Path dir = adopt(mailbox);
        Path tmp = PrivateFiles.createTempFile(downloadDir.resolve(PARTIAL), "dl-", ".part");
        try {
            Files.write(tmp, data);
            Files.move(tmp, dir.resolve(name), StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
            return f + "/" + name;
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /** The file in each MailBox's folder that names the MailBox (hidden from listings). */
    static final String OWNER_FILE = ".mailbox";

    /**
     * A MailBox's folder of the download directory: {@code HANDLE@HOST@SERVICE}
     * ({@code ttyUSB0@glider-pc1@SerialPortServer}), unique to the whole address (issue 23, item 4:
     * folders named by the handle alone were shared by two glider PCs' {@code ttyUSB0}). A name
     * that had to be changed to be a file name (a character replaced, cut to length) ends in a
     * hash of the whole address, so it stays unique.
     */
    public static String folderFor(String mailbox) {
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
    public void adoptAll(List<String> mailboxes) {
        for (String mb : mailboxes) {
            try {
                adopt(mb);
            } catch (IOException | RuntimeException e) {
                LoggerFactory.getLogger(FileStore.class).warn("could not make the download folder of {}: {}", mb, e.toString());
            }
        }
    }

    /**
     * The MailBox's folder, made if need be and marked with its address. A folder from before
     * folders were per address ({@code download/HANDLE/}, no mark) is moved here the first time
     * its MailBox is seen — at the service's registration or its first download.
     */
    public synchronized Path adopt(String mailbox) throws IOException {
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
                LoggerFactory.getLogger(FileStore.class).warn("moved download/{}/ (from before each MailBox's folder"
                        + " was unique to its address) to download/{}/ for {}; if two services had a MailBox {}, their files"
                        + " were mixed there before this version", old.getFileName(), dir.getFileName(), mailbox, handle);
            }
        }
        PrivateFiles.createDirectories(dir);
        Path mark = dir.resolve(OWNER_FILE);
        if (!Files.exists(mark)) {
            Path tmp = PrivateFiles.createTempFile(downloadDir.resolve(PARTIAL), "mb-", ".part");
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
    public Optional<String> mailboxOf(String downloadName) throws IOException {
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
     * Reads up to {@code length} bytes of a downloaded file from {@code offset}; returns {total, bytes}.
     * The name is {@code FOLDER/NAME} as {@code ?dlfiles} lists it, or a plain NAME when only one
     * folder holds it.
     */
    public Object[] readDownload(String name, long offset, int length) throws IOException {
        Path p = downloadPath(name);
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
                if (folder.equals(PARTIAL)) {
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

    /** The upload directory, and the files waiting in each to-vehicle folder as {@code to-vehicle/FOLDER/NAME}. */
    public FileListing listUploads() throws IOException {
        FileListing plain = list(uploadDir, false);
        Path tv = uploadDir.resolve(ToVehicleFolder.DIR);
        if (!Files.isDirectory(tv)) {
            return plain;
        }
        List<FileListing.Entry> entries = new ArrayList<>(plain.files());
        for (FileListing.Entry e : list(tv, true).files()) {
            entries.add(new FileListing.Entry(ToVehicleFolder.DIR + "/" + e.name(), e.size(), e.modified()));
        }
        entries.sort(Comparator.comparing(FileListing.Entry::name));
        return new FileListing(plain.directory(), entries);
    }

    /** The download directory: files of each MailBox's folder as {@code FOLDER/NAME}, and any loose files. */
    public FileListing listDownloads() throws IOException {
        return list(downloadDir, true);
    }

    private static FileListing list(Path dir, boolean folders) throws IOException {
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

    private static void clean(Path dir) throws IOException {
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir)) {
            for (Path p : ds) {
                Files.deleteIfExists(p);
            }
        }
    }
}
