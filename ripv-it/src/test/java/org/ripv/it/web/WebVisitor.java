package org.ripv.it.web;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.charset.StandardCharsets;
import java.security.cert.X509Certificate;
import java.time.Duration;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManager;
import javax.net.ssl.X509TrustManager;

/**
 * A scripted visitor of the web console without a browser (what an attacker's script does): forms,
 * cookies, and the console WebSocket, over the server's self-signed TLS (curl -k).
 */
public final class WebVisitor {
    public final String base;
    public final HttpClient http;

    public WebVisitor(int port, boolean tls) throws Exception {
        this.base = (tls ? "https" : "http") + "://localhost:" + port;
        SSLContext ctx = SSLContext.getInstance("TLS");
        ctx.init(null, new TrustManager[] {new X509TrustManager() {
            @Override
            public void checkClientTrusted(X509Certificate[] c, String a) {
            }

            @Override
            public void checkServerTrusted(X509Certificate[] c, String a) {
            }

            @Override
            public X509Certificate[] getAcceptedIssuers() {
                return new X509Certificate[0];
            }
        }}, null);
        this.http = HttpClient.newBuilder().sslContext(ctx).connectTimeout(Duration.ofSeconds(10)).build();
    }

    public HttpResponse<String> post(String path, String type, String body, String... headers) throws Exception {
        HttpRequest.Builder b = HttpRequest.newBuilder(URI.create(base + path)).timeout(Duration.ofSeconds(30))
                .POST(HttpRequest.BodyPublishers.ofString(body));
        if (type != null) {
            b.header("Content-Type", type);
        }
        if (headers.length > 0) {
            b.headers(headers);
        }
        return http.send(b.build(), HttpResponse.BodyHandlers.ofString());
    }

    public HttpResponse<String> get(String path, String... headers) throws Exception {
        HttpRequest.Builder b = HttpRequest.newBuilder(URI.create(base + path)).timeout(Duration.ofSeconds(30));
        if (headers.length > 0) {
            b.headers(headers);
        }
        return http.send(b.build(), HttpResponse.BodyHandlers.ofString());
    }

    /** Logs in with the form; the session cookie ("ripv-session=…"), or the refused response's body as an exception. */
    public String login(String user, String password, String... headers) throws Exception {
        HttpResponse<String> r = post("/login", "application/x-www-form-urlencoded",
                "user=" + enc(user) + "&password=" + enc(password), headers);
        if (r.statusCode() != 303) {
            throw new IllegalStateException(r.statusCode() + " " + r.body());
        }
        return r.headers().firstValue("Set-Cookie").orElseThrow().split(";")[0];
    }

    /** The session's CSRF token from /api/session. */
    public String csrf(String cookie) throws Exception {
        String json = get("/api/session", "Cookie", cookie).body();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\"csrf\":\"([0-9a-f]+)\"").matcher(json);
        if (!m.find()) {
            throw new IllegalStateException("no session: " + json);
        }
        return m.group(1);
    }

    static String enc(String s) {
        return java.net.URLEncoder.encode(s, StandardCharsets.UTF_8);
    }

    /** A console WebSocket; the frames the server sends are in {@link Socket#frames}. */
    public Socket socket(String cookie, String origin) throws Exception {
        Socket s = new Socket();
        WebSocket.Builder b = http.newWebSocketBuilder().connectTimeout(Duration.ofSeconds(10)).header("Cookie", cookie);
        if (origin != null) {
            b.header("Origin", origin);
        }
        s.ws = b.buildAsync(URI.create(base.replaceFirst("^http", "ws") + "/ws"), s).get(20, TimeUnit.SECONDS);
        return s;
    }

    /** The console socket's frames as they arrive. */
    public static final class Socket implements WebSocket.Listener {
        public final BlockingQueue<String> frames = new LinkedBlockingQueue<>();
        public volatile String closed;
        public WebSocket ws;
        private final StringBuilder partial = new StringBuilder();

        @Override
        public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
            partial.append(data);
            if (last) {
                frames.add(partial.toString());
                partial.setLength(0);
            }
            webSocket.request(1);
            return null;
        }

        @Override
        public CompletionStage<?> onClose(WebSocket webSocket, int statusCode, String reason) {
            closed = statusCode + " " + reason;
            frames.add("CLOSED " + closed);
            return null;
        }

        @Override
        public void onError(WebSocket webSocket, Throwable error) {
            closed = error.toString();
            frames.add("CLOSED " + closed);
        }

        public void send(long id, String mailbox, String body, String csrf) {
            ws.sendText("{\"id\":" + id + ",\"mailbox\":" + quote(mailbox) + ",\"body\":" + quote(body) + ",\"csrf\":" + quote(csrf) + "}", true).join();
        }

        /** The next frame that contains {@code text}, within the time. */
        public String await(String text, Duration within) throws InterruptedException {
            long end = System.nanoTime() + within.toNanos();
            while (System.nanoTime() < end) {
                String f = frames.poll(Math.max(1, (end - System.nanoTime()) / 1_000_000), TimeUnit.MILLISECONDS);
                if (f != null && f.contains(text)) {
                    return f;
                }
                if (f != null && f.startsWith("CLOSED")) {
                    return f;
                }
            }
            return null;
        }

        static String quote(String s) {
            return "\"" + s.replace("\\", "\\\\").replace("\"", "\\\"") + "\"";
        }
    }
}
