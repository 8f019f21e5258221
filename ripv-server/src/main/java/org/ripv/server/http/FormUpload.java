package org.ripv.server.http;

import static org.ripv.server.http.Pages.fail;
import static org.ripv.server.http.Pages.html;
import static org.ripv.server.http.Pages.page;
import static org.ripv.server.http.Pages.send;

import com.sun.net.httpserver.HttpExchange;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.ripv.server.files.FileNames;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code POST /upload}: {@code multipart/form-data} files into the server's upload directory, with
 * the CGI script's rules (thesis appendix D): plain names only, none that exists already, the
 * uploader's permit, a size limit per request and per log-in. If any file breaks a rule,
 * <em>none</em> of the request's files is saved: they arrive in hidden temporary files and are
 * moved into place only when all of them have.
 */
final class FormUpload {
    private static final Logger log = LoggerFactory.getLogger(FormUpload.class);
    /** Multipart boundaries and headers on top of the files themselves. */
    static final long FORM_OVERHEAD = 64 * 1024;

    private final Path uploadDir;
    private final long maxUploadBytes;
    private final WebLogin web;

    FormUpload(Path uploadDir, long maxUploadBytes, WebLogin web) {
        this.uploadDir = uploadDir;
        this.maxUploadBytes = maxUploadBytes;
        this.web = web;
    }

    void upload(HttpExchange ex, WebSessions.Session session) throws IOException {
        String boundary = MultipartStream.boundary(ex.getRequestHeaders().getFirst("Content-Type"));
        if (boundary == null) {
            drainAndFail(ex, 400, "Not a form upload", "The upload must be sent as multipart/form-data (use the form on the front page).");
            return;
        }
        long limit = maxUploadBytes;
        String declared = ex.getRequestHeaders().getFirst("Content-Length");
        if (declared != null) {
            try {
                if (Long.parseLong(declared.trim()) > limit + FORM_OVERHEAD) {
                    // Refuse before reading: the CGI's $MAXIMUMUPLOAD.
                    fail(ex, 413, "Upload too large", "The upload is " + declared.trim() + " bytes; this server takes at most "
                            + limit + " bytes per upload. None of the files were saved.");
                    return;
                }
            } catch (NumberFormatException e) {
                drainAndFail(ex, 400, "Bad request", "Content-Length '" + declared + "' is not a number.");
                return;
            }
        }
        Path dir = uploadDir;
        if (!Files.isDirectory(dir) || !Files.isWritable(dir)) {
            drainAndFail(ex, 500, "Bad directory", "The server's upload directory"
                    + " does not exist or is not writable; tell the server's administrator. None of the files were saved.");
            return;
        }
        List<Pending> pending = new ArrayList<>();
        try {
            MultipartStream form = new MultipartStream(ex.getRequestBody(), boundary);
            long total = 0;
            Set<String> names = new HashSet<>();
            for (MultipartStream.Part part = form.next(); part != null; part = form.next()) {
                if (!part.isFile() || part.fileName().isEmpty()) {
                    form.copyBody(OutputStream.nullOutputStream(), FORM_OVERHEAD, "a form field");
                    continue;
                }
                String name = part.fileName();
                try {
                    FileNames.check(name);
                } catch (IllegalArgumentException e) {
                    throw new Refused(400, "Filename problem", e.getMessage()
                            + ". Files may not have forward or backward slashes in their names, nor begin with a dot. "
                            + "Rename the file on your computer and upload it again.");
                }
                if (!web.mayUpload(session, name)) {
                    throw new Refused(403, "Not allowed", "User " + session.user + " may not upload " + name
                            + " (the permit file has no rule allowing ?upload for them).");
                }
                if (Files.exists(dir.resolve(name))) {
                    throw new Refused(409, "File exists", "A file named " + name + " is in the upload directory"
                            + " already, and this page never replaces one. Rename yours, or ask an operator.");
                }
                if (!names.add(name)) {
                    throw new Refused(400, "Filename problem", "'" + name + "' is given twice in one upload.");
                }
                Path tmp = Files.createTempFile(dir, ".ripv-form-", ".part");
                pending.add(new Pending(name, tmp, 0));
                long size;
                try (OutputStream out = Files.newOutputStream(tmp)) {
                    size = form.copyBody(out, limit - total, "'" + name + "'");
                } catch (MultipartStream.TooLargeException e) {
                    throw new Refused(413, "Upload too large", "The files are over this server's limit of " + limit
                            + " bytes per upload (at " + name + ").");
                }
                total += size;
                pending.set(pending.size() - 1, new Pending(name, tmp, size));
            }
            if (pending.isEmpty()) {
                throw new Refused(400, "No files", "The form held no files to upload.");
            }
            if (!web.charge(session, pending.size(), total, 4 * limit)) {
                throw new Refused(429, "Too much", "This log-in has uploaded as much as one session may ("
                        + WebSessions.MAX_FILES + " files, " + 4 * limit + " bytes); log in again later.");
            }
            // Every file arrived and passed the rules: now, and only now, put them in place (never over another).
            StringBuilder saved = new StringBuilder();
            for (Pending p : pending) {
                try {
                    Files.move(p.tmp(), dir.resolve(p.name()));
                } catch (java.nio.file.FileAlreadyExistsException e) {
                    throw new Refused(409, "File exists", "A file named " + p.name() + " arrived meanwhile; nothing of it was replaced.");
                }
                saved.append("<li>").append(html(p.name())).append(" (").append(p.size()).append(" bytes)</li>");
                log.info("landing page upload stored {} ({} bytes) for {} from {}", p.name(), p.size(), session.user, ex.getRemoteAddress());
            }
            pending.clear();
            send(ex, 200, "text/html; charset=utf-8", page("Upload complete",
                    "<p>Saved in the server's upload directory:</p><ul id=\"saved\">" + saved + "</ul><p><a href=\"/\">Back</a></p>"));
        } catch (Refused r) {
            // Clean up before answering, so the browser never sees a half-done upload directory.
            deleteAll(pending);
            log.info("landing page upload refused: {}", r.getMessage());
            drainAndFail(ex, r.status, r.title, r.getMessage() + (r.getMessage().contains("None of the files") ? ""
                    : " None of the files were saved."));
        } catch (MultipartStream.MalformedException e) {
            deleteAll(pending);
            drainAndFail(ex, 400, "Bad form data", e.getMessage() + ". None of the files were saved.");
        } finally {
            deleteAll(pending);
        }
    }

    /** A file of the form received into a hidden temporary file, not yet moved into place. */
    private record Pending(String name, Path tmp, long size) {}

    private static void deleteAll(List<Pending> pending) throws IOException {
        for (Pending p : pending) {
            Files.deleteIfExists(p.tmp());
        }
        pending.clear();
    }

    /** A rule the upload broke. */
    private static final class Refused extends IOException {
        private static final long serialVersionUID = 1L;
        final int status;
        final String title;

        Refused(int status, String title, String message) {
            super(message);
            this.status = status;
            this.title = title;
        }
    }

    /** Answers with an error, reading (a bounded amount of) what the client still sends so it sees the answer. */
    void drainAndFail(HttpExchange ex, int status, String title, String text) throws IOException {
        try (InputStream in = ex.getRequestBody()) {
            long budget = maxUploadBytes + FORM_OVERHEAD;
            byte[] b = new byte[64 * 1024];
            int r;
            while (budget > 0 && (r = in.read(b, 0, (int) Math.min(b.length, budget))) > 0) {
                budget -= r;
            }
        } catch (IOException e) {
            log.debug("while draining a refused upload: {}", e.toString());
        }
        fail(ex, status, title, text);
    }
}
