package org.ripv.server.http;

import com.sun.net.httpserver.HttpExchange;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.Map;

/**
 * The landing page's log-in for uploads ({@code --http-upload}): the form, the session it starts,
 * the CSRF check of an upload, and the upload section of the front page. Without a
 * {@link WebAccess} there is no log-in and no upload at all.
 */
final class WebLogin {
    /** Answers a refused request (reading what the client still sends, so it sees the answer). */
    interface Refuse {
        void refuse(HttpExchange ex, int status, String title, String text) throws IOException;
    }

    private final WebAccess access;
    private final boolean secure;
    private final WebSessions sessions = new WebSessions();

    /** @param access null: no uploads;  @param secure true over HTTPS (the cookie is then Secure) */
    WebLogin(WebAccess access, boolean secure) {
        this.access = access;
        this.secure = secure;
    }

    boolean mayUpload(WebSessions.Session s, String fileName) {
        return access.mayUpload(s.user, fileName);
    }

    boolean charge(WebSessions.Session s, int files, long bytes, long maxBytes) {
        return sessions.charge(s, files, bytes, maxBytes);
    }

    /** The logged-in visitor an upload comes from, or null after answering why not. */
    WebSessions.Session uploader(HttpExchange ex, Refuse refuse) throws IOException {
        if (access == null) {
            refuse.refuse(ex, 403, "Uploads are off", "This server takes no uploads through its web page (its operator"
                    + " turns them on with --http-upload). Use the RIPV client's put instead. Nothing was saved.");
            return null;
        }
        WebSessions.Session s = sessions.find(ex);
        if (s == null) {
            refuse.refuse(ex, 403, "Log in first", "Uploads need a log-in: use the log-in form on /login. Nothing was saved.");
            return null;
        }
        String query = ex.getRequestURI().getRawQuery();
        if (query == null || !java.security.MessageDigest.isEqual(("csrf=" + s.csrf).getBytes(StandardCharsets.UTF_8),
                query.getBytes(StandardCharsets.UTF_8))) {
            refuse.refuse(ex, 403, "Form expired", "The upload did not come from this server's own form (no or a wrong"
                    + " CSRF token); reload / and try again. Nothing was saved.");
            return null;
        }
        return s;
    }

    /** GET: the log-in form; POST: checks the password with the server's limits and starts a session. */
    void login(HttpExchange ex, String method) throws IOException {
        if (access == null) {
            Pages.send(ex, 404, "text/plain; charset=utf-8", "this server takes no uploads through its web page, so there is no log-in\n");
            return;
        }
        if ("GET".equals(method) || "HEAD".equals(method)) {
            Pages.send(ex, 200, "text/html; charset=utf-8", Pages.page("Log in to upload",
                    "<form id=\"login\" method=\"post\" action=\"/login\"><p>User <input name=\"user\" autocomplete=\"username\"></p>"
                    + "<p>Password <input name=\"password\" type=\"password\" autocomplete=\"current-password\"></p>"
                    + "<p><input type=\"submit\" value=\"Log in\"></p></form>"));
            return;
        }
        if (!"POST".equals(method)) {
            ex.getResponseHeaders().set("Allow", "GET, POST");
            Pages.send(ex, 405, "text/plain; charset=utf-8", method + " is not allowed here\n");
            return;
        }
        byte[] body = ex.getRequestBody().readNBytes(4096);
        Map<String, String> f = formFields(new String(body, StandardCharsets.UTF_8));
        String user = f.getOrDefault("user", "");
        char[] password = f.getOrDefault("password", "").toCharArray();
        WebAccess.Result r = access.login(user, password, ex.getRemoteAddress().getAddress().getHostAddress());
        if (r.user() == null) {
            Pages.fail(ex, 403, "Log-in refused", r.refusal());
            return;
        }
        WebSessions.Session s = sessions.create(r.user());
        ex.getResponseHeaders().add("Set-Cookie", WebSessions.cookie(s, secure));
        ex.getResponseHeaders().set("Location", "/");
        Pages.send(ex, 303, "text/html; charset=utf-8", Pages.page("Logged in", "<p>Logged in as " + Pages.html(r.user())
                + ". <a href=\"/\">Back</a></p>"));
    }

    private static Map<String, String> formFields(String body) {
        Map<String, String> m = new java.util.HashMap<>();
        for (String pair : body.split("&")) {
            String[] kv = pair.split("=", 2);
            if (kv.length == 2) {
                try {
                    m.put(java.net.URLDecoder.decode(kv[0], StandardCharsets.UTF_8), java.net.URLDecoder.decode(kv[1], StandardCharsets.UTF_8));
                } catch (IllegalArgumentException ignored) {
                    // a malformed field is no field
                }
            }
        }
        return m;
    }

    String uploadSection(HttpExchange ex, long maxUploadBytes) {
        if (access == null) {
            return "<h2>Upload files to the server</h2>\n<p id=\"upload-off\">This page takes no uploads (the operator turns"
                    + " them on with <code>--http-upload</code>). Use the client's <code>put</code>.</p>\n";
        }
        WebSessions.Session s = sessions.find(ex);
        if (s == null) {
            return "<h2>Upload files to the server</h2>\n<p><a id=\"login\" href=\"/login\">Log in</a> to upload files"
                    + " (the same users and rights as the client).</p>\n";
        }
        return "<h2>Upload files to the server</h2>\n"
                + "<p>Logged in as " + Pages.html(s.user) + ". Files go to the server's upload directory, where services can use"
                + " them (for example <code>vis:NAME</code> or <code>ymodem:put NAME</code>). Plain file names only: no slashes or "
                + "backslashes, no leading dot; an existing file is never replaced. At most " + maxUploadBytes
                + " bytes per upload, all files together. If any file breaks a rule, none is saved.</p>\n"
                + "<form id=\"upload\" method=\"post\" action=\"/upload?csrf=" + s.csrf + "\" enctype=\"multipart/form-data\">\n"
                + "<p><input type=\"file\" name=\"file-to-upload-1\"><br><input type=\"file\" name=\"file-to-upload-2\"><br>"
                + "<input type=\"file\" name=\"file-to-upload-3\"></p>\n"
                + "<p><input type=\"submit\" value=\"Upload\"></p></form>\n";
    }
}
