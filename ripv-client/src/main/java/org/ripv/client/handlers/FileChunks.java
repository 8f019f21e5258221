package org.ripv.client.handlers;

import java.io.IOException;
import java.io.InputStream;
import java.net.ProtocolException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.List;
import org.ripv.messages.Attachment;
import org.ripv.messages.FileData;
import org.ripv.messages.Header;
import org.ripv.messages.IdBadge;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Priority;
import org.ripv.messages.Status;

/**
 * A file moved over a client connection in chunks of {@link ClientSocketHandler#CHUNK}:
 * {@code ?upload NAME OFFSET TOTAL} with each chunk attached, {@code ?download NAME OFFSET LENGTH}
 * into a temporary file moved into place at the end, so an interrupted download never looks whole.
 */
final class FileChunks {
    private static final int CHUNK = ClientSocketHandler.CHUNK;

    private FileChunks() {}

    /** {@link ClientSocketHandler#upload(Path, String, String, TransferListener)}. */
    static OutgoingServerMessage upload(ClientSocketHandler client, Path local, String remoteName, String mode,
                                        TransferListener listener) throws IOException, RipvErrorException {
        String suffix = mode == null || mode.isBlank() ? "" : " " + mode;
        long total = Files.size(local);
        listener = listener == null ? TransferListener.NONE : listener;
        try (InputStream file = Files.newInputStream(local)) {
            long offset = 0;
            OutgoingServerMessage last = null;
            do {
                byte[] chunk = file.readNBytes((int) Math.min(CHUNK, total - offset));
                Header h = new Header(client.nextId(), new IdBadge("000000", ""), List.of(), "", "",
                        "?upload " + remoteName + " " + offset + " " + total + suffix, Priority.NORMAL,
                        new Attachment(remoteName, chunk));
                last = client.await(client.send(h, null), Duration.ofMinutes(2));
                if (last.status() == Status.ERROR) {
                    throw new RipvErrorException(last);
                }
                offset += chunk.length;
                if (!listener.progress(offset, total)) {
                    client.call("", "?upload-cancel " + remoteName, Priority.NORMAL, Duration.ofSeconds(30), null);
                    throw new IOException("upload of " + remoteName + " cancelled");
                }
            } while (offset < total);
            return last;
        }
    }

    /** {@link ClientSocketHandler#download(String, Path, TransferListener)}. */
    static Path download(ClientSocketHandler client, String name, Path localDir, TransferListener listener)
            throws IOException, RipvErrorException {
        listener = listener == null ? TransferListener.NONE : listener;
        localDir = localDir.toAbsolutePath().normalize(); // a bare "." has no parent to compare with
        Files.createDirectories(localDir);
        // a download is listed as FOLDER/NAME (the MailBox it came from): saved locally as NAME
        int slash = name.lastIndexOf('/');
        String folder = slash < 0 ? "x" : name.substring(0, slash);
        if (folder.isEmpty() || folder.contains("/") || folder.equals("..") || folder.equals(".")) {
            throw new IOException("refusing to write '" + name + "' outside " + localDir);
        }
        Path target = localDir.resolve(name.substring(slash + 1)).normalize();
        if (!localDir.equals(target.getParent())) {
            throw new IOException("refusing to write '" + name + "' outside " + localDir);
        }
        Path tmp = Files.createTempFile(localDir, ".ripv-", ".part");
        try (var file = Files.newOutputStream(tmp)) {
            long offset = 0;
            long total;
            do {
                OutgoingServerMessage r = client.call("", "?download " + name + " " + offset + " " + CHUNK, Priority.NORMAL,
                        Duration.ofMinutes(2), null);
                if (r.status() == Status.ERROR) {
                    throw new RipvErrorException(r);
                }
                if (!(r.footer().result() instanceof FileData chunk) || chunk.offset() != offset) {
                    throw new ProtocolException("the server sent no chunk at offset " + offset + " of " + name);
                }
                file.write(chunk.data());
                offset += chunk.data().length;
                total = chunk.total();
                if (!listener.progress(offset, total)) {
                    throw new IOException("download of " + name + " cancelled");
                }
                if (chunk.data().length == 0 && offset < total) {
                    throw new ProtocolException("the server sent an empty chunk of " + name);
                }
            } while (offset < total);
        } catch (IOException | RipvErrorException | RuntimeException e) {
            Files.deleteIfExists(tmp);
            throw e;
        }
        Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        return target;
    }
}
