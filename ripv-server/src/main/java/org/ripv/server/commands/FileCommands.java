package org.ripv.server.commands;

import java.io.IOException;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.function.Supplier;
import org.ripv.messages.FileData;
import org.ripv.messages.FileListing;
import org.ripv.messages.IncomingServerMessage;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.files.DownloadChunk;
import org.ripv.server.files.DownloadRights;
import org.ripv.server.files.FileStore;
import org.ripv.server.files.ToVehicleFolder;
import org.ripv.server.files.UploadMode;
import org.ripv.server.permit.PermitFile;
import org.ripv.server.permit.SecurityRefusal;
import org.ripv.server.requests.ServerReplies;

/**
 * The file commands (the upload and download directories): {@code ?dldir}, {@code ?uldir},
 * {@code ?dlfiles}, {@code ?ulfiles}, {@code ?delete}, {@code ?upload}, {@code ?upload-cancel},
 * {@code ?download}. The rights a gated command needs are checked before it runs
 * ({@link ServerCommands}); the rights on one file or folder are checked here.
 */
final class FileCommands {
    static final long MAX_DOWNLOAD_CHUNK = 1024 * 1024;

    private final FileStore files;
    private final Supplier<PermitFile> permits;

    FileCommands(FileStore files, Supplier<PermitFile> permits) {
        this.files = files;
        this.permits = permits;
    }

    OutgoingServerMessage dldir(Call c) {
        String shown = shownPath(c.request(), files.downloadDir(), "download");
        return c.ok(shown, new FileListing(shown, List.of()));
    }

    OutgoingServerMessage uldir(Call c) {
        String shown = shownPath(c.request(), files.uploadDir(), "upload");
        return c.ok(shown, new FileListing(shown, List.of()));
    }

    OutgoingServerMessage dlfiles(Call c) throws IOException {
        return listing(c, files.listDownloads(), shownPath(c.request(), files.downloadDir(), "download"));
    }

    OutgoingServerMessage ulfiles(Call c) throws IOException {
        return listing(c, files.listUploads(), shownPath(c.request(), files.uploadDir(), "upload"));
    }

    OutgoingServerMessage delete(Call c) throws IOException {
        c.expectWords(2);
        String name = c.words()[1];
        String where = files.delete(name);
        return c.ok("deleted " + name + " from the " + where, null);
    }

    OutgoingServerMessage upload(Call c) throws IOException {
        String[] w = c.words();
        if (w.length < 4 || w.length > 5 || c.request().header().attachment() == null) {
            throw new IllegalArgumentException("usage: " + c.command().usage() + " with the chunk attached");
        }
        String user = c.userName();
        long offset = Call.number(w[2], "OFFSET");
        long total = Call.number(w[3], "TOTAL");
        UploadMode mode = UploadMode.parse(w.length == 5 ? w[4] : null);
        if (mode == UploadMode.REPLACE) {
            // replacing is a right of its own (docs/permit.md): '?replace NAME' for RIPVServer
            PermitFile.Decision d = permits.get().decide(c.user(), ServerReplies.SERVICE, "", "?replace " + w[1]);
            if (!d.allowed()) {
                throw new SecurityRefusal("user '" + user + "' may not replace files in the upload directory ("
                        + d.because() + "); upload with 'keep' to store it under a new name");
            }
        }
        if (ToVehicleFolder.isToVehicle(w[1])) {
            toVehicleRight(c.user(), user, w[1]);
        }
        FileStore.ChunkResult r = files.uploadChunk(c.clientId(), user, w[1], offset, total,
                c.request().header().attachment().data(), mode, permits.get().quota(c.user()));
        String text;
        if (!r.complete()) {
            text = "received " + r.received() + " of " + r.total() + " bytes of " + w[1];
        } else if (!r.storedAs().equals(w[1])) {
            text = "stored as " + r.storedAs() + " (" + r.total() + " bytes) in the upload directory: " + w[1]
                    + " was taken and is kept as it was";
        } else {
            text = "stored " + w[1] + " (" + r.total() + " bytes) in the upload directory"
                    + (mode == UploadMode.REPLACE ? " (replace)" : "");
        }
        return c.ok(text, r.complete() ? new FileListing("upload",
                List.of(new FileListing.Entry(r.storedAs(), r.total(), System.currentTimeMillis()))) : null);
    }

    OutgoingServerMessage uploadCancel(Call c) throws IOException {
        String name = c.arg(1);
        files.abort(c.clientId(), name);
        return c.ok("dropped the unfinished upload of " + name, null);
    }

    OutgoingServerMessage download(Call c) throws IOException {
        c.expectWords(4);
        String[] w = c.words();
        DownloadRights.check(files, permits.get(), c.userName(), w[1]);
        long offset = Call.number(w[2], "OFFSET");
        int length = (int) Math.min(MAX_DOWNLOAD_CHUNK, Call.number(w[3], "LENGTH"));
        DownloadChunk chunk = files.readDownload(w[1], offset, length);
        byte[] data = chunk.data();
        long total = chunk.total();
        return c.ok("bytes " + offset + ".." + (offset + data.length) + " of " + total + " of " + w[1],
                new FileData(w[1], offset, total, data));
    }

    /**
     * The server's own directories: an absolute path only for operators and admins, who run the
     * host; everybody else sees the area's name (no server paths to ordinary users).
     */
    private static String shownPath(IncomingServerMessage request, Path dir, String area) {
        List<String> roles = request.header().roles();
        return roles.contains("operators") || roles.contains("admin") ? dir.toString() : area;
    }

    /**
     * A file for a vehicle ({@code to-vehicle/FOLDER/NAME}) needs the right {@code ?to-vehicle FOLDER}
     * (service RIPVServer, docs/permit.md), and FOLDER must be a MailBox's.
     */
    private void toVehicleRight(PermitFile.User u, String user, String name) {
        ToVehicleFolder.Name n = ToVehicleFolder.parse(name);
        PermitFile.Decision d = permits.get().decide(u, ServerReplies.SERVICE, "", "?to-vehicle " + n.folder());
        if (!d.allowed()) {
            throw new SecurityRefusal("user '" + user + "' may not put files for a vehicle in to-vehicle/" + n.folder() + " ("
                    + d.because() + "); that takes the right '?to-vehicle " + n.folder() + "' for RIPVServer");
        }
        if (!files.isMailboxFolder(n.folder())) {
            throw new IllegalArgumentException("no MailBox has the folder '" + n.folder() + "'; give the vehicle's folder"
                    + " as ?dlfiles names it (HANDLE@HOST@SERVICE)");
        }
    }

    private static OutgoingServerMessage listing(Call c, FileListing all, String shown) {
        FileListing l = new FileListing(shown, all.files());
        StringBuilder b = new StringBuilder(l.directory() + ": " + l.files().size() + " file(s)");
        for (FileListing.Entry e : l.files()) {
            b.append(String.format("%n%12d  %s  %s", e.size(), Instant.ofEpochMilli(e.modified()), e.name()));
        }
        return c.ok(b.toString(), l);
    }
}
