package org.ripv.server.web;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Base64;
import org.ripv.messages.Attachment;
import org.ripv.messages.FileData;
import org.ripv.messages.OutgoingServerMessage;

/**
 * File bytes between a page and the Post Office, in the chunks the CLI uses: a page uploads with
 * {@code ?upload NAME OFFSET TOTAL [replace|keep]} and the chunk in {@code "data"} (base64; the
 * server's {@code FileStore} applies FILE_EXISTS, the replace right and the quota as for every
 * client), and downloads with {@code ?download NAME OFFSET LENGTH}, whose reply then carries the
 * chunk in {@code "result.data"} (the server's {@code DownloadRights} decided first). Only a
 * server command's {@link FileData} carries bytes to the page: what a vehicle's service replies
 * with stays a name and a size, so no service can fill a page's socket.
 */
final class FileChunks {
    /** A page's chunk, raw; base64 of it must fit one WebSocket message (64 KiB). */
    static final int MAX_CHUNK = 46 * 1024;

    private FileChunks() {}

    /**
     * The chunk a page's request carries, or null.
     *
     * @throws IllegalArgumentException when {@code data} is not base64, is too large, or names no file
     */
    static Attachment attachment(JsonNode request) {
        JsonNode data = request.get("data");
        if (data == null || data.isNull()) {
            return null;
        }
        String name = request.path("file").asText("");
        if (name.isEmpty()) {
            throw new IllegalArgumentException("an upload chunk needs \"file\": the name it is stored under");
        }
        byte[] bytes = Base64.getDecoder().decode(data.asText(""));
        if (bytes.length > MAX_CHUNK) {
            throw new IllegalArgumentException("an upload chunk of " + bytes.length + " bytes is over " + MAX_CHUNK
                    + "; send the file in smaller chunks");
        }
        return new Attachment(name, bytes);
    }

    /** Whether a reply's file bytes go to the page: a chunk of {@code ?download}, which is a server command. */
    static boolean carriesBytes(OutgoingServerMessage m) {
        return m.footer().result() instanceof FileData && m.header().mailboxAddress().isEmpty() && m.header().messageId() != 0;
    }

    /** The chunk as the page reads it. */
    record Chunk(String name, long offset, long total, long bytes, String data) {
        static Chunk of(FileData f) {
            return new Chunk(f.name(), f.offset(), f.total(), f.data().length, Base64.getEncoder().encodeToString(f.data()));
        }
    }
}
