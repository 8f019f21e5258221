package org.ripv.server.web;

import static org.ripv.server.web.Pages.html;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.io.Content;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.IO;

/**
 * What the landing page always was (thesis 4.1.2, SPEC §7) — {@code GET /}: what this server is
 * (ports, certificate fingerprint, service names), the client jar and a JNLP for Web Start
 * launchers — now with the web console's log-in form.
 */
final class LandingHandler extends Handler.Abstract {
    private static final Pattern SAFE_HOST = Pattern.compile("[A-Za-z0-9.\\-]{1,253}(:\\d{1,5})?|\\[[0-9A-Fa-f:.]{2,45}](:\\d{1,5})?");

    private final Supplier<String> status;
    private final Path clientJar;
    private final int clientPort;
    private final boolean tls;
    private final WebSessions sessions;
    private final boolean logins;
    private final long maxUploadBytes;

    /** @param maxUploadBytes the upload form's limit, or 0 when the page takes no uploads */
    LandingHandler(Supplier<String> status, Path clientJar, int clientPort, boolean tls, WebSessions sessions, boolean logins,
                   long maxUploadBytes) {
        this.maxUploadBytes = maxUploadBytes;
        this.status = status;
        this.clientJar = clientJar;
        this.clientPort = clientPort;
        this.tls = tls;
        this.sessions = sessions;
        this.logins = logins;
    }

    @Override
    public boolean handle(Request request, Response response, Callback callback) throws Exception {
        String path = Request.getPathInContext(request);
        if (!path.equals("/") && !path.equals("/index.html") && !path.equals("/ripv-client.jar") && !path.equals("/ripv-client.jnlp")) {
            return false;
        }
        if (!"GET".equals(request.getMethod()) && !"HEAD".equals(request.getMethod())) {
            response.getHeaders().put(HttpHeader.ALLOW, "GET, HEAD");
            Pages.send(response, callback, 405, "text/plain; charset=utf-8", request.getMethod() + " is not allowed here; use GET\n");
            return true;
        }
        switch (path) {
            case "/ripv-client.jar" -> jar(request, response, callback);
            case "/ripv-client.jnlp" -> Pages.send(response, callback, 200, "application/x-java-jnlp-file", jnlp(request));
            default -> Pages.send(response, callback, 200, "text/html; charset=utf-8", index(request));
        }
        return true;
    }

    private String index(Request request) {
        boolean jar = clientJar != null && Files.isRegularFile(clientJar);
        String hostOnly = host(request).replaceFirst(":\\d+$", "");
        String connect = hostOnly + (clientPort > 0 ? ":" + clientPort : "");
        WebSessions.Session s = sessions.find(request);
        String console;
        if (!logins) {
            console = "<p id=\"console-off\">This server's web console is off.</p>\n";
        } else if (s != null) {
            console = "<p>Logged in as <strong id=\"who\">" + html(s.user) + "</strong>. <a id=\"fleet\" href=\"/fleet.html\">Open the fleet</a></p>\n"
                    + "<form method=\"post\" action=\"/logout\"><input type=\"hidden\" name=\"csrf\" value=\"" + s.csrf
                    + "\"><button type=\"submit\">Log out</button></form>\n" + uploadForm(s);
        } else {
            console = "<form id=\"login\" class=\"card\" method=\"post\" action=\"/login\">\n"
                    + "<p><label for=\"user\">User</label><input id=\"user\" name=\"user\" autocomplete=\"username\" required></p>\n"
                    + "<p><label for=\"password\">Password</label><input id=\"password\" name=\"password\" type=\"password\""
                    + " autocomplete=\"current-password\" required></p>\n"
                    + "<p><button type=\"submit\">Log in</button></p></form>\n";
        }
        return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
                + "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>RIPV server</title>"
                + "<link rel=\"stylesheet\" href=\"/ripv.css\"></head><body><main>\n"
                + "<h1>RIPV — Remote Interaction Planning and Visualization</h1>\n"
                + "<h2>Web console</h2>\n" + console
                + "<h2>This server</h2>\n<pre id=\"status\">" + html(status.get()) + "</pre>\n"
                + "<h2>The operator client</h2>\n"
                + (jar ? "<p><a id=\"jar\" href=\"/ripv-client.jar\">Download ripv-client.jar</a> and run "
                + "<code>java -jar ripv-client.jar client " + html(connect) + "</code> (Java 17 or newer), or open "
                + "<a id=\"jnlp\" href=\"/ripv-client.jnlp\">ripv-client.jnlp</a> with OpenWebStart.</p>\n"
                : "<p>This server offers no client jar for download (none was configured). Build one with "
                + "<code>mvn -DskipTests package</code>; it is <code>ripv-client/target/ripv-client.jar</code>.</p>\n")
                + "<p>Without a display, use the command-line client: <code>ripv cli --server " + html(connect)
                + " --user USER --password-file FILE</code>.</p>\n</main></body></html>\n";
    }

    /** The thesis's upload form (appendix D), for a logged-in user when the operator turned uploads on. */
    private String uploadForm(WebSessions.Session s) {
        if (maxUploadBytes <= 0) {
            return "";
        }
        return "<h2>Upload files to the server</h2>\n<p>Files go to the server's upload directory, where services can use them"
                + " (for example <code>ymodem:put NAME</code>). Plain file names only: no slashes or backslashes, no leading dot;"
                + " an existing file is never replaced. At most " + maxUploadBytes + " bytes per upload, all files together."
                + " If any file breaks a rule, none is saved.</p>\n"
                + "<form id=\"upload\" class=\"card\" method=\"post\" action=\"/upload?csrf=" + s.csrf + "\" enctype=\"multipart/form-data\">\n"
                + "<p><label for=\"file-1\">File</label><input id=\"file-1\" type=\"file\" name=\"file-to-upload-1\" multiple></p>\n"
                + "<p><button type=\"submit\">Upload</button></p></form>\n";
    }

    private void jar(Request request, Response response, Callback callback) throws Exception {
        if (clientJar == null || !Files.isRegularFile(clientJar)) {
            Pages.send(response, callback, 404, "text/plain; charset=utf-8", clientJar == null
                    ? "this server offers no client jar: it was started without one\n"
                    : "the client jar " + clientJar.getFileName() + " is not there; build it with mvn -DskipTests package\n");
            return;
        }
        response.setStatus(200);
        response.getHeaders().put(HttpHeader.CONTENT_TYPE, "application/java-archive");
        response.getHeaders().put("Content-Disposition", "attachment; filename=\"ripv-client.jar\"");
        response.getHeaders().put(HttpHeader.CONTENT_LENGTH, Files.size(clientJar));
        if ("HEAD".equals(request.getMethod())) {
            callback.succeeded();
            return;
        }
        try (var in = Files.newInputStream(clientJar); var out = Content.Sink.asOutputStream(response)) {
            IO.copy(in, out);
        }
        callback.succeeded();
    }

    private String jnlp(Request request) {
        String host = host(request);
        String hostOnly = host.replaceFirst(":\\d+$", "");
        String codebase = (tls ? "https" : "http") + "://" + host + "/";
        String server = hostOnly + (clientPort > 0 ? ":" + clientPort : "");
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<jnlp spec=\"1.0+\" codebase=\"" + html(codebase) + "\" href=\"ripv-client.jnlp\">\n"
                + "  <information>\n    <title>RIPV Client</title>\n    <vendor>RIPV</vendor>\n"
                + "    <description>The RIPV operator client for " + html(server) + "</description>\n  </information>\n"
                + "  <security><all-permissions/></security>\n"
                + "  <resources>\n    <j2se version=\"17+\"/>\n    <jar href=\"ripv-client.jar\" main=\"true\"/>\n  </resources>\n"
                + "  <application-desc main-class=\"org.ripv.client.ClientMain\">\n"
                + "    <argument>client</argument>\n    <argument>" + html(server) + "</argument>\n"
                + "  </application-desc>\n</jnlp>\n";
    }

    /** The Host the browser used, if it looks like a host; else the address we listen on. */
    private static String host(Request request) {
        String h = request.getHeaders().get(HttpHeader.HOST);
        if (h != null && SAFE_HOST.matcher(h).matches()) {
            return h;
        }
        String a = Request.getLocalAddr(request);
        return (a.indexOf(':') >= 0 ? "[" + a + "]" : a) + ":" + Request.getLocalPort(request);
    }
}
