package org.ripv.server.files;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.ripv.files.PrivateFiles;
import org.ripv.messages.FileListing;

/**
 * The server's file store: the upload directory (files from clients, {@link Uploads}, with each
 * user's quota kept by {@link UploadOwners}) and the download directory (files from services, one
 * folder per MailBox, {@link Downloads}). Every write goes to a temporary file in {@code .partial/}
 * first and is moved into place whole, so a failed or partial transfer never looks complete;
 * names follow {@link FileNames}; directories and files are owner-only (0700/0600).
 *
 * <p>This class is the one door the server's parts use; it opens both directories and says which
 * of the two a name belongs to ({@link #delete}).
 */
public final class FileStore {
    /** Where unfinished transfers grow, in each directory; emptied at start. */
    static final String PARTIAL = ".partial";

    private final Path uploadDir;
    private final Path downloadDir;
    private final long maxUpload;
    private final Uploads uploads;
    private final Downloads downloads;

    public FileStore(Path uploadDir, Path downloadDir, long maxUpload) throws IOException {
        this.uploadDir = PrivateFiles.createDirectories(uploadDir).toRealPath();
        this.downloadDir = PrivateFiles.createDirectories(downloadDir).toRealPath();
        this.maxUpload = maxUpload;
        PrivateFiles.restrict(this.uploadDir);
        PrivateFiles.restrict(this.downloadDir);
        PrivateFiles.createDirectories(this.uploadDir.resolve(PARTIAL));
        PrivateFiles.createDirectories(this.downloadDir.resolve(PARTIAL));
        Dirs.clean(this.uploadDir.resolve(PARTIAL));
        Dirs.clean(this.downloadDir.resolve(PARTIAL));
        this.uploads = new Uploads(this.uploadDir, maxUpload);
        this.downloads = new Downloads(this.downloadDir);
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

    // ---- the upload directory ----

    /** {@link #uploadChunk(String, String, String, long, long, byte[], UploadMode, long)} refusing a taken name, no quota. */
    public ChunkResult uploadChunk(String clientId, String name, long offset, long total, byte[] data) throws IOException {
        return uploads.uploadChunk(clientId, name, offset, total, data);
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
        return uploads.uploadChunk(clientId, user, name, offset, total, data, mode, quota);
    }

    /**
     * Stores whole files that arrived another way (the web form) for {@code user}, with the
     * chunks' rules, all or none ({@link Uploads#storeWhole}).
     */
    public List<String> storeWhole(String user, Map<String, Path> files, long quota) throws IOException {
        return uploads.storeWhole(user, files, quota);
    }

    /** Bytes {@code user} holds in the upload directory. */
    public long usage(String user) {
        return uploads.usage(user);
    }

    /** Who stored an upload, or empty when unknown (put there by hand). */
    public String owner(String name) {
        return uploads.owner(name);
    }

    /** Drops an unfinished upload. */
    public void abort(String clientId, String name) throws IOException {
        uploads.abort(clientId, name);
    }

    /** Drops every unfinished upload of a client that went away. */
    public void abortAll(String clientId) {
        uploads.abortAll(clientId);
    }

    /** Where an upload name points: a plain NAME, or a to-vehicle file; anything else is refused. */
    public Path uploadPath(String name) {
        return uploads.uploadPath(name);
    }

    /** The files waiting in a MailBox's to-vehicle folder, oldest first, as {@code to-vehicle/FOLDER/NAME}. */
    public List<String> toVehiclePending(String mailbox) throws IOException {
        return uploads.toVehiclePending(mailbox);
    }

    /** Moves a to-vehicle file its vehicle now has into {@code sent/} with its receipt ({@link Uploads#toVehicleSent}). */
    public String toVehicleSent(String name, String receipt) throws IOException {
        return uploads.toVehicleSent(name, receipt);
    }

    /** Reads a whole uploaded file, for attaching to a command. */
    public byte[] readUpload(String name) throws IOException {
        return uploads.readUpload(name);
    }

    /** The upload directory, and the files waiting in each to-vehicle folder as {@code to-vehicle/FOLDER/NAME}. */
    public FileListing listUploads() throws IOException {
        return uploads.listUploads();
    }

    /**
     * Deletes a stored file: a plain NAME (or {@code to-vehicle/FOLDER/NAME}) from the upload
     * directory, a {@code FOLDER/NAME} (as {@code ?dlfiles} lists it) from the download directory.
     * Returns where it was.
     */
    public String delete(String name) throws IOException {
        if (!ToVehicleFolder.isToVehicle(name) && name.indexOf('/') >= 0) {
            downloads.delete(name);
            return "download directory";
        }
        return uploads.delete(name);
    }

    // ---- the download directory ----

    /**
     * Stores a file that came from a service's MailBox in that MailBox's own folder, replacing an
     * earlier file of the same name from the same MailBox only; returns its name, {@code FOLDER/NAME}.
     */
    public String storeDownload(String mailbox, String name, byte[] data) throws IOException {
        return downloads.storeDownload(mailbox, name, data);
    }

    /** A MailBox's folder of the download directory, unique to its whole address ({@link Downloads#folderFor}). */
    public static String folderFor(String mailbox) {
        return Downloads.folderFor(mailbox);
    }

    /** Makes the folder of each MailBox a service lists as it registers. */
    public void adoptAll(List<String> mailboxes) {
        downloads.adoptAll(mailboxes);
    }

    /** The MailBox's folder, made if need be and marked with its address. */
    public Path adopt(String mailbox) throws IOException {
        return downloads.adopt(mailbox);
    }

    /** Whether a download folder belongs to a MailBox (one a service has registered). */
    public boolean isMailboxFolder(String folder) {
        return downloads.isMailboxFolder(folder);
    }

    /** The MailBox whose folder holds a download, or empty: rights on a download follow it. */
    public Optional<String> mailboxOf(String downloadName) throws IOException {
        return downloads.mailboxOf(downloadName);
    }

    /**
     * Reads up to {@code length} bytes of a downloaded file from {@code offset}. The name is
     * {@code FOLDER/NAME} as {@code ?dlfiles} lists it, or a plain NAME when only one folder holds it.
     */
    public DownloadChunk readDownload(String name, long offset, int length) throws IOException {
        return downloads.readDownload(name, offset, length);
    }

    /** Bytes read back from the download directory since start ({@code ?download}, files attached to commands). */
    public long downloadBytesRead() {
        return downloads.bytesRead();
    }

    /** The download directory: files of each MailBox's folder as {@code FOLDER/NAME}, and any loose files. */
    public FileListing listDownloads() throws IOException {
        return downloads.listDownloads();
    }

    static String folderName(String handle) {
        return Downloads.folderName(handle);
    }

    static String numbered(String name, int n) {
        return Uploads.numbered(name, n);
    }
}
