package org.ripv.server.web;

import static org.ripv.server.web.Pages.html;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.UUID;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.http.MultiPart;
import org.eclipse.jetty.http.MultiPartConfig;
import org.eclipse.jetty.http.MultiPartFormData;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;
import org.ripv.files.PrivateFiles;
import org.ripv.server.files.FileExistsException;
import org.ripv.server.files.FileNames;
import org.ripv.server.files.FileTooLargeException;
import org.ripv.server.web.WebSessions.Session;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@code POST /upload}: files into the server's upload directory with the CGI script's rules
 * (thesis appendix D) and the client's: plain names only, none that exists already
 * (FILE_EXISTS), the uploader's permit for {@code ?upload NAME}, a size limit per request and
 * per log-in. Jetty's {@link MultiPartFormData} parses the form into a hidden folder; if any
 * file breaks a rule, <em>none</em> is moved into place.
 */
final class UploadHandler extends Handler.Abstract {
    private static final Logger log = LoggerFactory.getLogger(UploadHandler.class);
    /** Multipart boundaries and headers on top of the files themselves. */
    static final long FORM_OVERHEAD = 64 * 1024;
    static final int MAX_PARTS = 16;

    private final Path uploadDir;
    private final long maxUploadBytes;
    private final WebAccess access;
    private final boolean uploads;
    private final WebSessions sessions;
    private final FormUploads store;

    UploadHandler(Path uploadDir, long maxUploadBytes, WebAccess access, boolean uploads, WebSessions sessions, FormUploads store) {
        this.uploadDir = uploadDir;
        this.maxUploadBytes = maxUploadBytes;
        this.access = access;
        this.uploads = uploads && store != null;
        this.sessions = sessions;
        this.store = store;
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        if (!Request.getPathInContext(request).equals("/upload")) {
            return false;
        }
        if (!"POST".equals(request.getMethod())) {
            response.getHeaders().put(HttpHeader.ALLOW, "POST");
            Pages.send(response, callback, 405, "text/plain; charset=utf-8", "use POST with multipart/form-data (the upload form)\n");
            return true;
        }
        String refusal = refusal(request);
        if (refusal != null) {
            response.getHeaders().put(HttpHeader.CONNECTION, "close"); // the rest of the body is not read
            Pages.fail(response, callback, refusal.startsWith("413") ? 413 : 403, refusal.startsWith("413") ? "Upload too large"
                    : "Upload refused", refusal.replaceFirst("^413 ", "") + " Nothing was saved.");
            return true;
        }
        Session s = sessions.find(request);
        String type = request.getHeaders().get(HttpHeader.CONTENT_TYPE);
        String boundary = MultiPart.extractBoundary(type);
        if (type == null || !type.split(";")[0].trim().equalsIgnoreCase("multipart/form-data") || boundary == null) {
            response.getHeaders().put(HttpHeader.CONNECTION, "close");
            Pages.fail(response, callback, 400, "Not a form upload", "The upload must be sent as multipart/form-data"
                    + " (use the upload form). Nothing was saved.");
            return true;
        }
        Path parking = PrivateFiles.createDirectories(uploadDir.resolve(".ripv-form")); // 0700, as the rest
        MultiPartConfig config = new MultiPartConfig.Builder().location(parking).maxParts(MAX_PARTS)
                .maxSize(maxUploadBytes + FORM_OVERHEAD).maxPartSize(maxUploadBytes).maxMemoryPartSize(16 * 1024)
                .maxHeadersSize(8 * 1024).build();
        MultiPartFormData.from(request, request, type, config).whenComplete((parts, failure) -> {
            if (failure != null) {
                String why = String.valueOf(failure.getMessage());
                boolean big = why.toLowerCase(Locale.ROOT).contains("max");
                Pages.fail(response, callback, big ? 413 : 400, big ? "Upload too large" : "Bad form data", (big
                        ? "The files are over this server's limit of " + maxUploadBytes + " bytes per upload (" + why + ")."
                        : "The form could not be read: " + why + ".") + " None of the files were saved.");
                return;
            }
            try (parts) {
                store(request, parts, s, response, callback);
            } catch (IOException | RuntimeException e) {
                log.warn("upload failed: {}", e.toString());
                Pages.fail(response, callback, 500, "Upload failed", "The server could not store the files (" + e.getMessage()
                        + "). None of the files were saved.");
            }
        });
        return true;
    }

    /** Why this request may not upload at all (checked before its body is read), or null. */
    private String refusal(Request request) {
        if (!uploads) {
            return "This server takes no uploads through its web page (its operator turns them on with --http-upload)."
                    + " Use the RIPV client's put instead.";
        }
        Session s = sessions.find(request);
        if (s == null) {
            return "Uploads need a log-in: log in on the front page.";
        }
        String cross = Pages.crossOrigin(request);
        String token = request.getHeaders().get("X-CSRF-Token");
        if (token == null) {
            token = Request.extractQueryParameters(request).getValue("csrf");
        }
        if (cross != null || !s.csrf(token)) {
            return "The upload did not come from this server's own page (" + (cross != null ? cross : "no or a wrong CSRF token")
                    + "); reload the page and try again.";
        }
        long declared = request.getLength();
        if (declared > maxUploadBytes + FORM_OVERHEAD) {
            return "413 The upload is " + declared + " bytes; this server takes at most " + maxUploadBytes + " bytes per upload.";
        }
        return null;
    }

    private void store(Request request, MultiPartFormData.Parts parts, Session s, Response response, Callback callback) throws IOException {
        List<MultiPart.Part> files = new ArrayList<>();
        Set<String> names = new HashSet<>();
        long total = 0;
        for (MultiPart.Part part : parts) {
            String name = part.getFileName();
            if (name == null || name.isEmpty()) {
                continue;
            }
            try {
                FileNames.check(name);
            } catch (IllegalArgumentException e) {
                Pages.fail(response, callback, 400, "Filename problem", e.getMessage() + ". Files may not have forward or backward"
                        + " slashes in their names, nor begin with a dot. Rename the file and upload it again. None of the files were saved.");
                return;
            }
            if (!access.mayUpload(s.user, name)) {
                Pages.fail(response, callback, 403, "Not allowed", "User " + s.user + " may not upload " + name
                        + " (the permit file has no rule allowing ?upload for them). None of the files were saved.");
                return;
            }
            if (Files.exists(uploadDir.resolve(name))) {
                Pages.fail(response, callback, 409, "File exists", "A file named " + name + " is in the upload directory"
                        + " already (FILE_EXISTS), and the web page never replaces one. Rename yours, or delete the old one"
                        + " with ?delete. None of the files were saved.");
                return;
            }
            if (!names.add(name)) {
                Pages.fail(response, callback, 400, "Filename problem", "'" + name + "' is given twice in one upload. None of the files were saved.");
                return;
            }
            files.add(part);
            total += part.getLength();
        }
        if (files.isEmpty()) {
            Pages.fail(response, callback, 400, "No files", "The form held no files to upload.");
            return;
        }
        if (!sessions.charge(s, files.size(), total, 4 * maxUploadBytes)) {
            Pages.fail(response, callback, 429, "Too much", "This log-in has uploaded as much as one session may ("
                    + WebSessions.MAX_FILES + " files, " + 4 * maxUploadBytes + " bytes); log in again later. None of the files were saved.");
            return;
        }
        // Every file arrived and passed the form's rules: each is parked owner-only, then the store applies the client's
        // rules (quota, owners, never over another file) to all of them at once.
        List<Path> parked = new ArrayList<>();
        try {
            Map<String, Path> byName = new LinkedHashMap<>();
            for (MultiPart.Part p : files) {
                Path tmp = uploadDir.resolve(".ripv-form").resolve(UUID.randomUUID() + ".part");
                parked.add(tmp);
                p.writeTo(tmp); // inside the 0700 parking folder; owner-only before it is linked in
                PrivateFiles.restrict(tmp);
                byName.put(p.getFileName(), tmp);
            }
            List<String> stored;
            try {
                stored = store.store(s.user, byName);
            } catch (FileExistsException e) {
                discard(parked);
                Pages.fail(response, callback, 409, "File exists", e.getMessage() + " The web page never replaces a file. None of the files were saved.");
                return;
            } catch (FileTooLargeException e) {
                discard(parked);
                Pages.fail(response, callback, 413, "Over your quota", e.getMessage() + ". None of the files were saved.");
                return;
            }
            StringBuilder saved = new StringBuilder();
            for (int i = 0; i < files.size(); i++) {
                String name = files.get(i).getFileName();
                if (!stored.contains(name)) {
                    continue;
                }
                saved.append("<li>").append(html(name)).append(" (").append(files.get(i).getLength()).append(" bytes)</li>");
                log.info("web upload stored {} ({} bytes) for {} from {}", name, files.get(i).getLength(), s.user, Request.getRemoteAddr(request));
            }
            discard(parked); // the stored files are links of their own: the parked names go before the answer
            Pages.send(response, callback, 200, "text/html; charset=utf-8", Pages.page("Upload complete",
                    "<p>Saved in the server's upload directory:</p><ul id=\"saved\">" + saved + "</ul><p><a href=\"/\">Back</a></p>"));
        } finally {
            discard(parked);
        }
    }

    private static void discard(List<Path> parked) throws IOException {
        for (Path p : parked) {
            Files.deleteIfExists(p);
        }
    }
}
