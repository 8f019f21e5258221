package org.ripv.server.http;

import static org.ripv.server.http.Pages.html;
import static org.ripv.server.http.Pages.send;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Objects;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Supplier;
import java.util.regex.Pattern;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's web page (thesis 4.1.2 and appendix D, SPEC §7), on the JDK's HTTP server:
 * <ul>
 *   <li>{@code GET /} — what this server is (the status text), links to the client, the upload form;</li>
 *   <li>{@code GET /ripv-client.jar} — the client jar, or 404 saying the server has none configured;</li>
 *   <li>{@code GET /ripv-client.jnlp} — a JNLP file for Web Start launchers (OpenWebStart) that
 *       points at the jar on the host the browser used;</li>
 *   <li>{@code POST /upload} — {@code multipart/form-data} files into the server's upload
 *       directory, with the CGI script's rules: plain names only (no slashes or backslashes, no
 *       leading dot), and a size limit per request. If any file breaks a rule, <em>none</em> of
 *       the request's files is saved. Files are written to hidden temporary files and moved into
 *       place only when all of them have arrived.</li>
 * </ul>
 *
 * <pre>{@code
 * LandingPage page = new LandingPage(new InetSocketAddress(8080), uploadDir, 256L << 20,
 *         Path.of("ripv-client.jar"), () -> "RIPVServer on deslab: client port 4444, 3 services");
 * page.start();   // returns at once; page.port() is bound
 * page.stop();
 * }</pre>
 */
public final class LandingPage implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(LandingPage.class);
    /** Multipart boundaries and headers on top of the files themselves. */
    static final long FORM_OVERHEAD = FormUpload.FORM_OVERHEAD;
    private static final Pattern SAFE_HOST = Pattern.compile("[A-Za-z0-9.\\-]{1,253}(:\\d{1,5})?|\\[[0-9A-Fa-f:.]{2,45}](:\\d{1,5})?");

    /**
     * How the page is set up.
     *
     * @param bind           address and port to listen on (port 0: any free port)
     * @param uploadDir      where the upload form stores files (the server's upload directory)
     * @param maxUploadBytes the most one form submission may upload, all files together
     * @param clientJar      the client jar to offer, or null
     * @param status         one or more lines saying what this server is (name, ports, services)
     * @param clientPort     the RIPV client port the JNLP client should connect to, or 0 to let it ask
     * @param access         who may upload after logging in on the page; null: no uploads at all (the default)
     * @param tls            serve HTTPS with this context; null: plain HTTP
     */
    public record Options(InetSocketAddress bind, Path uploadDir, long maxUploadBytes, Path clientJar,
                          Supplier<String> status, int clientPort, WebAccess access, javax.net.ssl.SSLContext tls) {
        /** Without uploads, over plain HTTP. */
        public Options(InetSocketAddress bind, Path uploadDir, long maxUploadBytes, Path clientJar,
                       Supplier<String> status, int clientPort) {
            this(bind, uploadDir, maxUploadBytes, clientJar, status, clientPort, null, null);
        }

        public Options {
            Objects.requireNonNull(bind, "bind");
            Objects.requireNonNull(uploadDir, "uploadDir");
            if (maxUploadBytes <= 0) {
                throw new IllegalArgumentException("the upload limit must be positive, got " + maxUploadBytes);
            }
            status = status == null ? () -> "RIPVServer" : status;
            if (clientPort < 0 || clientPort > 65535) {
                throw new IllegalArgumentException("client port " + clientPort + " is outside 0-65535");
            }
        }
    }

    private final Options options;
    private final WebLogin web;
    private final FormUpload form;
    private HttpServer http;
    private ExecutorService pool;

    public LandingPage(Options options) {
        this.options = Objects.requireNonNull(options, "options");
        this.web = new WebLogin(options.access(), options.tls() != null);
        this.form = new FormUpload(options.uploadDir(), options.maxUploadBytes(), web);
    }

    /** As {@link #LandingPage(Options)} without a client port in the JNLP. */
    public LandingPage(InetSocketAddress bind, Path uploadDir, long maxUploadBytes, Path clientJar, Supplier<String> status) {
        this(new Options(bind, uploadDir, maxUploadBytes, clientJar, status, 0));
    }

    /** Binds and starts serving; returns at once. */
    public synchronized void start() throws IOException {
        if (http != null) {
            return;
        }
        Files.createDirectories(options.uploadDir());
        HttpServer s;
        if (options.tls() != null) {
            com.sun.net.httpserver.HttpsServer https = com.sun.net.httpserver.HttpsServer.create(options.bind(), 32);
            https.setHttpsConfigurator(new com.sun.net.httpserver.HttpsConfigurator(options.tls()));
            s = https;
        } else {
            s = HttpServer.create(options.bind(), 32);
        }
        AtomicInteger n = new AtomicInteger();
        pool = Executors.newFixedThreadPool(4, r -> {
            Thread t = new Thread(r, "ripv-http-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        s.setExecutor(pool);
        s.createContext("/", this::handle);
        s.start();
        http = s;
        log.info("landing page on {}://{}:{}/{}", scheme(), options.bind().getHostString(), port(),
                options.access() == null ? " (uploads off)" : " (uploads after log-in)");
    }

    /** The bound port. */
    public synchronized int port() {
        if (http == null) {
            throw new IllegalStateException("the landing page is not started");
        }
        return http.getAddress().getPort();
    }

    /** Stops serving and releases the port and threads. */
    public synchronized void stop() {
        if (http != null) {
            http.stop(0);
            pool.shutdownNow();
            http = null;
        }
    }

    @Override
    public void close() {
        stop();
    }

    private void handle(HttpExchange ex) throws IOException {
        try (ex) {
            String path = ex.getRequestURI().getPath();
            String method = ex.getRequestMethod().toUpperCase(Locale.ROOT);
            switch (path) {
                case "/", "/index.html" -> {
                    if (get(ex, method)) {
                        send(ex, 200, "text/html; charset=utf-8", index(ex));
                    }
                }
                case "/ripv-client.jar" -> {
                    if (get(ex, method)) {
                        jar(ex, method);
                    }
                }
                case "/ripv-client.jnlp" -> {
                    if (get(ex, method)) {
                        send(ex, 200, "application/x-java-jnlp-file", jnlp(ex));
                    }
                }
                case "/upload" -> {
                    if (!"POST".equals(method)) {
                        ex.getResponseHeaders().set("Allow", "POST");
                        send(ex, 405, "text/plain; charset=utf-8", "use POST with multipart/form-data (the form on /)\n");
                    } else {
                        WebSessions.Session session = web.uploader(ex, form::drainAndFail);
                        if (session != null) {
                            form.upload(ex, session);
                        }
                    }
                }
                case "/login" -> web.login(ex, method);
                default -> send(ex, 404, "text/plain; charset=utf-8", "no page " + path + " here; see /\n");
            }
        } catch (IOException | RuntimeException e) {
            log.warn("HTTP {} {} failed: {}", ex.getRequestMethod(), ex.getRequestURI(), e.toString());
        }
    }

    private static boolean get(HttpExchange ex, String method) throws IOException {
        if ("GET".equals(method) || "HEAD".equals(method)) {
            return true;
        }
        ex.getResponseHeaders().set("Allow", "GET, HEAD");
        send(ex, 405, "text/plain; charset=utf-8", method + " is not allowed here; use GET\n");
        return false;
    }

    private String scheme() {
        return options.tls() == null ? "http" : "https";
    }

    private String index(HttpExchange ex) {
        boolean jar = options.clientJar() != null && Files.isRegularFile(options.clientJar());
        String host = host(ex);
        String hostOnly = host.replaceFirst(":\\d+$", "");
        String connect = hostOnly + (options.clientPort() > 0 ? ":" + options.clientPort() : "");
        return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>RIPV server</title>\n"
                + "<style>body{font-family:sans-serif;max-width:46em;margin:2em auto;line-height:1.4}"
                + "pre{background:#f4f4f4;padding:.6em}code{background:#f4f4f4}</style></head><body>\n"
                + "<h1>RIPV — Remote Interaction Planning and Visualization</h1>\n"
                + "<h2>This server</h2>\n<pre id=\"status\">" + html(options.status().get()) + "</pre>\n"
                + "<h2>The operator client</h2>\n"
                + (jar ? "<p><a id=\"jar\" href=\"/ripv-client.jar\">Download ripv-client.jar</a> and run "
                + "<code>java -jar ripv-client.jar client " + html(connect) + "</code> (Java 17 or newer), or open "
                + "<a id=\"jnlp\" href=\"/ripv-client.jnlp\">ripv-client.jnlp</a> with OpenWebStart.</p>\n"
                : "<p>This server offers no client jar for download (none was configured). Build one with "
                + "<code>mvn -DskipTests package</code>; it is <code>ripv-client/target/ripv-client.jar</code>.</p>\n")
                + "<p>Without a display, use the command-line client: <code>ripv cli --server " + html(connect)
                + " --user USER --password-file FILE</code>.</p>\n"
                + web.uploadSection(ex, options.maxUploadBytes()) + "</body></html>\n";
    }

    private void jar(HttpExchange ex, String method) throws IOException {
        Path jar = options.clientJar();
        if (jar == null || !Files.isRegularFile(jar)) {
            send(ex, 404, "text/plain; charset=utf-8", jar == null
                    ? "this server offers no client jar: it was started without one\n"
                    : "the client jar " + jar.getFileName() + " is not there; build it with mvn -DskipTests package\n");
            return;
        }
        long size = Files.size(jar);
        ex.getResponseHeaders().set("Content-Type", "application/java-archive");
        ex.getResponseHeaders().set("Content-Disposition", "attachment; filename=\"ripv-client.jar\"");
        if ("HEAD".equals(method)) {
            ex.sendResponseHeaders(200, -1);
            return;
        }
        ex.sendResponseHeaders(200, size);
        try (OutputStream out = ex.getResponseBody()) {
            Files.copy(jar, out);
        }
    }

    private String jnlp(HttpExchange ex) {
        String host = host(ex);
        String hostOnly = host.replaceFirst(":\\d+$", "");
        String codebase = scheme() + "://" + host + "/";
        String server = hostOnly + (options.clientPort() > 0 ? ":" + options.clientPort() : "");
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<jnlp spec=\"1.0+\" codebase=\"" + xml(codebase) + "\" href=\"ripv-client.jnlp\">\n"
                + "  <information>\n"
                + "    <title>RIPV Client</title>\n"
                + "    <vendor>RIPV</vendor>\n"
                + "    <description>The RIPV operator client for " + xml(server) + "</description>\n"
                + "  </information>\n"
                + "  <security><all-permissions/></security>\n"
                + "  <resources>\n"
                + "    <j2se version=\"17+\"/>\n"
                + "    <jar href=\"ripv-client.jar\" main=\"true\"/>\n"
                + "  </resources>\n"
                + "  <application-desc main-class=\"org.ripv.client.ClientMain\">\n"
                + "    <argument>client</argument>\n"
                + "    <argument>" + xml(server) + "</argument>\n"
                + "  </application-desc>\n"
                + "</jnlp>\n";
    }

    /** The Host the browser used, if it looks like a host; else the address we listen on. */
    private String host(HttpExchange ex) {
        String h = ex.getRequestHeaders().getFirst("Host");
        if (h != null && SAFE_HOST.matcher(h).matches()) {
            return h;
        }
        InetSocketAddress local = ex.getLocalAddress();
        String a = local.getAddress().getHostAddress();
        return (a.indexOf(':') >= 0 ? "[" + a + "]" : a) + ":" + local.getPort();
    }

    private static String xml(String s) {
        return html(s).replace("'", "&apos;");
    }
}
