package org.ripv.server.web;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import javax.net.ssl.SSLContext;
import org.eclipse.jetty.http.HttpVersion;
import org.eclipse.jetty.server.ConnectionLimit;
import org.eclipse.jetty.server.DetectorConnectionFactory;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.HttpConfiguration;
import org.eclipse.jetty.server.HttpConnectionFactory;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.server.SecureRequestCustomizer;
import org.eclipse.jetty.server.Server;
import org.eclipse.jetty.server.ServerConnector;
import org.eclipse.jetty.server.SslConnectionFactory;
import org.eclipse.jetty.server.handler.ContextHandler;
import org.eclipse.jetty.server.handler.ResourceHandler;
import org.eclipse.jetty.util.Callback;
import org.eclipse.jetty.util.resource.ResourceFactory;
import org.eclipse.jetty.util.ssl.SslContextFactory;
import org.eclipse.jetty.util.thread.QueuedThreadPool;
import org.eclipse.jetty.websocket.server.WebSocketUpgradeHandler;
import org.ripv.wire.FrameCodec;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The server's HTTP port on Jetty 12: the landing page, the web console's log-in, pages and
 * WebSocket, and the upload form. Start and stop it like every running part:
 *
 * <pre>{@code
 * WebConsole web = new WebConsole(new WebConsole.Options(new InetSocketAddress(8080), uploadDir, 256L << 20,
 *         clientJar, () -> "RIPVServer on deslab", 4444, webLogins, true, tlsContext, door, codec, null));
 * web.start();   // returns at once; web.port() is bound
 * web.stop();
 * }</pre>
 *
 * Deadlines (issue 23 item 6): headers within {@link #HEADER_DEADLINE}, then no read or write may
 * wait longer than {@link #IDLE}; connections hold no thread while they wait.
 */
public final class WebConsole implements AutoCloseable {
    private static final Logger log = LoggerFactory.getLogger(WebConsole.class);
    static final Duration HEADER_DEADLINE = Duration.ofSeconds(10);
    static final Duration IDLE = Duration.ofSeconds(20);
    static final Duration SESSION_IDLE = Duration.ofMinutes(30);
    static final Duration SESSION_ABSOLUTE = Duration.ofHours(12);
    /** How often expired sessions are looked for. */
    static final Duration SWEEP = Duration.ofSeconds(10);
    /**
     * Open connections at most: well above the thousand slow ones a visitor must outlast, and room
     * for the 10,000 pages of a public outreach day (a page costs no thread: docs/web.md).
     */
    static final int MAX_CONNECTIONS = 12_288;
    /** Frames queued for a page that does not read before it is cut off. */
    static final int MAX_QUEUED_FRAMES = 2000;

    /**
     * How the console is set up.
     *
     * @param bind           address and port (port 0: any free port)
     * @param uploadDir      the server's upload directory (the upload form's target)
     * @param maxUploadBytes the most one form submission may upload
     * @param clientJar      the client jar to offer, or null
     * @param status         what this server is (name, ports, fingerprint, services)
     * @param clientPort     the client port for the JNLP and the landing text
     * @param access         log-ins; null: no web console (landing page only)
     * @param uploads        whether the upload form takes files ({@code --http-upload})
     * @param tls            serve HTTPS with this context; null: plain HTTP
     * @param door           how a page becomes a Post Office client; null with {@code access} null
     * @param codec          the client protocol's frame codec (pages are in-process clients and need no frames; kept for callers)
     * @param mapTiles       a tile URL template ({@code https://tile.example.org/{z}/{x}/{y}.png}), or null
     */
    public record Options(InetSocketAddress bind, Path uploadDir, long maxUploadBytes, Path clientJar, Supplier<String> status,
                          int clientPort, WebAccess access, boolean uploads, SSLContext tls, PostOfficeDoor door, FrameCodec codec,
                          String mapTiles) {
        public Options {
            Objects.requireNonNull(bind, "bind");
            Objects.requireNonNull(uploadDir, "uploadDir");
            if (maxUploadBytes <= 0) {
                throw new IllegalArgumentException("the upload limit must be positive, got " + maxUploadBytes);
            }
            status = status == null ? () -> "RIPVServer" : status;
            codec = codec == null ? new FrameCodec(FrameCodec.DEFAULT_MAX_FRAME) : codec;
            checkMapTiles(mapTiles);
        }
    }

    /**
     * Refuses a tile URL the map cannot use or the Content-Security-Policy could not name as one host.
     *
     * @throws IllegalArgumentException quoting the URL and saying what it needs
     */
    public static void checkMapTiles(String template) {
        if (template != null && !template.matches("https://[A-Za-z0-9.\\-]+(:\\d+)?/[^\\s\"'<>;]*\\{z}[^\\s\"'<>;]*")
                || template != null && !(template.contains("{x}") && template.contains("{y}"))) {
            throw new IllegalArgumentException("--map-tiles '" + template + "' is not an https URL with {z}, {x} and {y},"
                    + " e.g. https://tile.openstreetmap.org/{z}/{x}/{y}.png");
        }
    }

    private final Options options;
    private final WebSessions sessions = new WebSessions(SESSION_IDLE, SESSION_ABSOLUTE, System::currentTimeMillis);
    private final PushJson pushJson = new PushJson();
    private Server server;
    private ServerConnector connector;
    private ScheduledExecutorService timer;
    private volatile PublicFleet publicFleet;
    private volatile FormUploads formUploads;

    public WebConsole(Options options) {
        this.options = Objects.requireNonNull(options, "options");
    }

    /** Turns the public view on ({@code --public GLOB}): anonymous visitors get {@code /api/public}; set before {@link #start()}. */
    public WebConsole withPublicView(PublicFleet fleet) {
        this.publicFleet = fleet;
        return this;
    }

    /** Pages (WebSockets) one user may have open over all their log-ins, one log-in half of it ({@code --web-pages}). */
    public WebConsole withPagesPerUser(int n) {
        sessions.pagesPerUser(n);
        return this;
    }

    /** Where the upload form stores files (the server's FileStore, with ?upload's rules); without it the form takes none. Before {@link #start()}. */
    public WebConsole withFormUploads(FormUploads store) {
        this.formUploads = store;
        return this;
    }

    /** Binds and starts serving; returns at once. */
    public synchronized void start() throws IOException {
        if (server != null) {
            return;
        }
        Files.createDirectories(options.uploadDir());
        QueuedThreadPool pool = new QueuedThreadPool(64, 4);
        pool.setName("ripv-web");
        pool.setDaemon(true);
        Server s = new Server(pool);
        HttpConfiguration http = new HttpConfiguration();
        http.setSendServerVersion(false);
        http.setSendXPoweredBy(false);
        http.setRequestHeaderSize(8 * 1024);
        http.setIdleTimeout(IDLE.toMillis());
        ServerConnector c;
        if (options.tls() != null) {
            SecureRequestCustomizer secure = new SecureRequestCustomizer();
            secure.setSniHostCheck(false); // the server's own certificate names no host
            http.addCustomizer(secure);
            SslContextFactory.Server ssl = new SslContextFactory.Server();
            ssl.setSslContext(options.tls());
            // http:// on this port is told from TLS by its first bytes and answered with a redirect (HttpsRedirect).
            c = new ServerConnector(s, new DetectorConnectionFactory(new SslConnectionFactory(ssl, HttpVersion.HTTP_1_1.asString())),
                    new HttpConnectionFactory(http));
        } else {
            c = new ServerConnector(s, new HttpConnectionFactory(http));
        }
        c.setHost(options.bind().getAddress() == null ? null : options.bind().getAddress().getHostAddress());
        c.setPort(options.bind().getPort());
        c.setIdleTimeout(IDLE.toMillis());
        c.setAcceptQueueSize(128);
        s.addConnector(c);
        s.addBean(new ConnectionLimit(MAX_CONNECTIONS, s));
        timer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "ripv-web-deadlines");
            t.setDaemon(true);
            return t;
        });
        // An expired log-in's pages are closed within this, not only at their next request (issue 33 item 10).
        timer.scheduleWithFixedDelay(sessions::sweep, SWEEP.toMillis(), SWEEP.toMillis(), TimeUnit.MILLISECONDS);
        HeaderDeadline deadline = new HeaderDeadline(null, HEADER_DEADLINE.toMillis(), timer);
        c.addBean(deadline);
        Handler served = new SecurityHeaders(handlers(s), options.tls() != null, tileOrigin(options.mapTiles()));
        deadline.setHandler(options.tls() != null ? new HttpsRedirect(served) : served);
        s.setHandler(deadline);
        try {
            s.start();
        } catch (Exception e) {
            try {
                s.stop();
            } catch (Exception ignored) {
                // already failing
            }
            timer.shutdownNow();
            throw e instanceof IOException io ? io : new IOException(e.getMessage(), e);
        }
        server = s;
        connector = c;
        log.info("web console on {}://{}:{}/{}", options.tls() == null ? "http" : "https", options.bind().getHostString(), port(),
                options.access() == null ? " (log-ins off)" : "");
    }

    private Handler handlers(Server s) {
        boolean tls = options.tls() != null;
        Map<String, Object> settings = new LinkedHashMap<>();
        settings.put("mapTiles", options.mapTiles());
        ResourceFactory resources = ResourceFactory.of(s);
        ResourceHandler pages = new ResourceHandler();
        pages.setBaseResource(resources.newClassLoaderResource("org/ripv/server/web/static/"));
        pages.setDirAllowed(false);
        pages.setEtags(true);
        ResourceHandler webjars = new ResourceHandler();
        webjars.setBaseResource(resources.newClassLoaderResource("META-INF/resources/webjars/"));
        webjars.setDirAllowed(false);
        ContextHandler webjarContext = new ContextHandler(webjars, "/webjars");
        List<Handler> chain = new ArrayList<>();
        chain.add(new LandingHandler(options.status(), options.clientJar(), options.clientPort(), tls, sessions, options.access() != null,
                options.uploads() && options.access() != null ? options.maxUploadBytes() : 0));
        if (options.access() != null) {
            chain.add(new LoginHandler(options.access(), sessions, tls, settings));
            chain.add(new RightsHandler(options.access(), sessions));
        }
        chain.add(new UploadHandler(options.uploadDir(), options.maxUploadBytes(), options.access(),
                options.uploads() && options.access() != null, sessions, formUploads));
        chain.add(new PublicHandler(publicFleet, options.mapTiles()));
        chain.add(webjarContext);
        chain.add(pages);
        chain.add(new NotFound());
        Handler.Sequence all = new Handler.Sequence(chain);
        if (options.access() == null) {
            return all;
        }
        WebSocketUpgradeHandler ws = WebSocketUpgradeHandler.from(s, container -> {
            container.setMaxTextMessageSize(64 * 1024);
            container.setIdleTimeout(Duration.ofMinutes(10));
            // No setMaxOutgoingFrames: ConsoleSocket counts every frame it queues against
            // MAX_QUEUED_FRAMES itself, and Jetty's own count wrapped each frame's callback in two
            // more objects (issue 38: per-delivery allocation of the fan-out).
            container.addMapping("/ws", (request, response, callback) -> {
                String cross = Pages.crossOrigin(request);
                if (cross != null || request.getHeaders().get("Origin") == null) {
                    log.info("web console socket refused from {}: {}", Request.getRemoteAddr(request),
                            cross == null ? "no Origin" : cross);
                    Response.writeError(request, response, callback, 403, "WebSockets only from this server's own pages");
                    return null;
                }
                WebSessions.Session login = sessions.find(request);
                if (login == null) {
                    Response.writeError(request, response, callback, 403, "log in first");
                    return null;
                }
                String full = sessions.admitSocket(login, null);
                if (full != null) {
                    log.info("web console socket of {} refused from {}: {}", login.user, Request.getRemoteAddr(request), full);
                    Response.writeError(request, response, callback, 429, full);
                    return null;
                }
                // The browser's address, for the gate's per-address rules and the log lines.
                InetAddress from = request.getConnectionMetaData().getRemoteSocketAddress() instanceof InetSocketAddress a
                        && a.getAddress() != null ? a.getAddress() : InetAddress.getLoopbackAddress();
                return new ConsoleSocket(sessions, login, options.door(), pushJson, from);
            });
        });
        ws.setHandler(all);
        return ws;
    }

    static String tileOrigin(String template) {
        if (template == null) {
            return null;
        }
        URI u = URI.create(template.replaceAll("\\{[a-z]}", "0"));
        return u.getScheme() + "://" + u.getAuthority();
    }

    /** The last word: a plain 404 that says where to go. */
    private static final class NotFound extends Handler.Abstract.NonBlocking {
        @Override
        public boolean handle(Request request, Response response, Callback callback) {
            Pages.send(response, callback, 404, "text/plain; charset=utf-8", "no page " + Request.getPathInContext(request) + " here; see /\n");
            return true;
        }
    }

    /**
     * The permit file changed (issue 33 item 4): the sessions of {@code ended} users end (their pages
     * close); users in {@code roles} keep their sessions with the new roles.
     */
    public void usersChanged(Set<String> ended, Map<String, List<String>> roles) {
        sessions.usersChanged(ended, roles);
    }

    /** The bound port. */
    public synchronized int port() {
        if (connector == null) {
            throw new IllegalStateException("the web console is not started");
        }
        return connector.getLocalPort();
    }

    /** Stops serving, closes every page's socket, releases the port and threads. */
    public synchronized void stop() {
        if (server != null) {
            try {
                server.stop();
            } catch (Exception e) {
                log.debug("web console stop: {}", e.toString());
            }
            timer.shutdownNow();
            server = null;
            connector = null;
        }
    }

    @Override
    public void close() {
        stop();
    }
}
