package org.ripv.server.web;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import org.ripv.messages.ChartData;
import org.ripv.messages.FileBundle;
import org.ripv.messages.FileData;
import org.ripv.messages.ImageResult;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.messages.Result;

/**
 * A reply or console push as the pages read it: {@code {"type":"reply"|"push", "id", "status",
 * "error", "text", "result": {"kind": "ConsoleBatch", ...}}}. Results are the protocol's own
 * records, written by Jackson; file bytes stay on the server (the page is told the name and size),
 * except the chunks of a {@code ?download} the page asked for ({@link FileChunks}); a plot's
 * numbers come along for the page's own chart.
 */
final class WebReplies {
    private final ObjectMapper json = new ObjectMapper();

    String toJson(OutgoingServerMessage m) {
        ObjectNode n = json.createObjectNode();
        long id = m.header().messageId();
        n.put("type", id == 0 ? "push" : "reply");
        n.put("id", id);
        n.put("mailbox", m.header().mailboxAddress());
        n.put("status", m.footer().status().name());
        n.put("error", m.footer().errorCode().name());
        n.put("text", m.footer().replyText());
        Result r = m.footer().result();
        if (r != null) {
            ObjectNode result = json.valueToTree(FileChunks.carriesBytes(m) ? FileChunks.Chunk.of((FileData) r) : summary(r));
            result.put("kind", r.getClass().getSimpleName());
            n.set("result", result);
        }
        try {
            return json.writeValueAsString(n);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("a reply could not be written as JSON", e);
        }
    }

    private static Object summary(Result r) {
        if (r instanceof FileData f) {
            return new FileSummary(f.name(), f.total());
        }
        if (r instanceof ImageResult i) {
            return new Picture(i.name(), i.jpeg().length, i.chart());
        }
        if (r instanceof FileBundle b) {
            return new Files(b.files().stream().map(f -> new FileSummary(f.name(), f.total())).toList());
        }
        return r;
    }

    /** A file the reply carried, without its bytes. */
    record FileSummary(String name, long bytes) {}

    /** A plot without its JPEG, with the numbers it was drawn from (null from Octave or MATLAB) for the page's chart. */
    record Picture(String name, long bytes, ChartData chart) {}

    /** The files a bundle carried, without their bytes. */
    record Files(List<FileSummary> files) {}
}
