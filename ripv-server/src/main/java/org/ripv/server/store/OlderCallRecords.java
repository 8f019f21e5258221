package org.ripv.server.store;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Whose call records they are, for records kept before the store wrote {@code KEY.mailbox} beside
 * them: the file's KEY is a one-way digest of the MailBox's address, so the address is found among
 * the MailBoxes the transcripts hold (every vehicle that called has a transcript, each of whose
 * lines names its MailBox) as the one whose key is KEY. Bounded: the first 4 KiB of one file per
 * transcript folder, at most {@link #MAX_FOLDERS} folders.
 */
final class OlderCallRecords {
    /** Transcript folders looked into at most: more vehicles than a server serves. */
    static final int MAX_FOLDERS = 20_000;
    /** A transcript line's {@code "mailbox"} comes right after its time: the head of the first line is enough. */
    private static final int HEAD_BYTES = 4096;
    private static final JsonFactory JSON = new JsonFactory();

    private OlderCallRecords() {}

    /**
     * The MailBox of each of {@code keys} (call-record file keys without a {@code .mailbox}) found
     * in the transcript folders under {@code transcripts}: key to address. Keys not found are left out.
     */
    static Map<String, String> owners(Path transcripts, Set<String> keys) throws IOException {
        Map<String, String> found = new HashMap<>();
        if (keys.isEmpty() || !Files.isDirectory(transcripts)) {
            return found;
        }
        int folders = 0;
        try (DirectoryStream<Path> dirs = Files.newDirectoryStream(transcripts, Files::isDirectory)) {
            for (Path dir : dirs) {
                if (++folders > MAX_FOLDERS || found.size() == keys.size()) {
                    break;
                }
                List<Path> files = FileTranscripts.files(dir);
                String mailbox = files.isEmpty() ? null : mailboxOf(files.get(0));
                if (mailbox != null) {
                    String key = DataFiles.key(mailbox);
                    if (keys.contains(key)) {
                        found.put(key, mailbox);
                    }
                }
            }
        }
        return found;
    }

    /** The {@code "mailbox"} of the file's first line, or null when its head does not name one. */
    static String mailboxOf(Path transcriptFile) {
        byte[] head;
        try (InputStream in = Files.newInputStream(transcriptFile)) {
            head = in.readNBytes(HEAD_BYTES);
        } catch (IOException e) {
            return null;
        }
        String text = new String(head, StandardCharsets.UTF_8);
        int nl = text.indexOf('\n');
        // A head cut inside the line is still read up to the cut: the parser stops there with an error.
        try (JsonParser p = JSON.createParser(nl >= 0 ? text.substring(0, nl) : text)) {
            if (p.nextToken() != JsonToken.START_OBJECT) {
                return null;
            }
            for (JsonToken t = p.nextToken(); t == JsonToken.FIELD_NAME; t = p.nextToken()) {
                String field = p.currentName();
                JsonToken value = p.nextToken();
                if ("mailbox".equals(field)) {
                    return value == JsonToken.VALUE_STRING && p.getText().length() <= 1000 ? p.getText() : null;
                }
                p.skipChildren();
            }
        } catch (IOException e) {
            return null; // not JSON, or "mailbox" lies past the head
        }
        return null;
    }
}
