package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.it.web.WebVisitor;
import org.ripv.server.ServerConfig;

/**
 * The web console's attacks (issue 21, and issue 23 items 6 and 10): log-in CSRF, session
 * fixation, log-out, cross-site WebSocket hijacking, a forged console message, an observer's
 * command, guessing through the form, upload names and sizes, and a thousand slow connections.
 * Each failed before the web console: {@code /login} took {@code text/plain} from any origin and
 * there was no log-out; four slow connections blocked the JDK server's four threads.
 */
class WebConsoleAttackTest {
    static final String CLOCK = "<ClockService>::<localhost>TTY1";
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    static Path dir;
    static TestSystem sys;
    static WebVisitor web;
    static String origin;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        config = config.withSecurity(config.security().withHttpUpload(true));
        sys = TestSystem.start(config);
        sys.user("alice", "operators");
        sys.user("olga", "observers");
        sys.user("gus", "operators");
        sys.register(new ClockService("localhost"));
        web = new WebVisitor(sys.server().httpPort(), true);
        origin = web.base;
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void loginTakesNoTextPlainAndNoOtherOrigin() throws Exception {
        String body = "user=alice&password=" + TestSystem.PASSWORD.replace(" ", "+");
        HttpResponse<String> plain = web.post("/login", "text/plain", body);
        assertThat(plain.statusCode()).isEqualTo(415);
        assertThat(plain.body()).contains("text/plain");
        HttpResponse<String> cross = web.post("/login", "application/x-www-form-urlencoded", body, "Origin", "https://evil.example");
        assertThat(cross.statusCode()).isEqualTo(403);
        assertThat(cross.body()).contains("another origin (https://evil.example)");
        HttpResponse<String> site = web.post("/login", "application/x-www-form-urlencoded", body, "Sec-Fetch-Site", "cross-site");
        assertThat(site.statusCode()).isEqualTo(403);
        for (HttpResponse<String> r : List.of(plain, cross, site)) {
            assertThat(r.headers().firstValue("Set-Cookie")).isEmpty();
            assertThat(r.headers().firstValue("Content-Security-Policy").orElseThrow()).contains("script-src 'self'")
                    .doesNotContain("unsafe-inline");
        }
        // The same form from the server's own page logs in.
        String cookie = web.login("alice", TestSystem.PASSWORD, "Origin", origin);
        assertThat(web.get("/api/session", "Cookie", cookie).body()).contains("\"user\":\"alice\"");
    }

    @Test
    void aSessionIdSetBeforeLogInIsNotKept() throws Exception {
        String planted = "ripv-session=0123456789abcdef0123456789abcdef0123456789abcdef";
        HttpResponse<String> r = web.post("/login", "application/x-www-form-urlencoded",
                "user=alice&password=" + TestSystem.PASSWORD.replace(" ", "+"), "Cookie", planted);
        String cookie = r.headers().firstValue("Set-Cookie").orElseThrow();
        assertThat(cookie).doesNotContain(planted).contains("HttpOnly").contains("SameSite=Strict").contains("Secure");
        // The attacker's own real session, planted in the victim's browser, ends at the victim's log-in.
        String attackers = web.login("gus", TestSystem.PASSWORD);
        String victims = web.post("/login", "application/x-www-form-urlencoded", "user=alice&password="
                + TestSystem.PASSWORD.replace(" ", "+"), "Cookie", attackers).headers().firstValue("Set-Cookie").orElseThrow().split(";")[0];
        assertThat(victims).isNotEqualTo(attackers);
        assertThat(web.get("/api/session", "Cookie", attackers).statusCode()).isEqualTo(401);
        assertThat(web.get("/api/session", "Cookie", victims).body()).contains("\"user\":\"alice\"");
    }

    @Test
    void logOutNeedsTheTokenAndEndsTheSessionAndItsSockets() throws Exception {
        String cookie = web.login("alice", TestSystem.PASSWORD);
        String csrf = web.csrf(cookie);
        WebVisitor.Socket s = web.socket(cookie, origin);
        s.send(1, "", "?whoami", csrf);
        assertThat(s.await("\"id\":1", T)).contains("alice");

        HttpResponse<String> forged = web.post("/logout", "application/x-www-form-urlencoded", "csrf=wrong", "Cookie", cookie);
        assertThat(forged.statusCode()).isEqualTo(403);
        assertThat(web.get("/api/session", "Cookie", cookie).statusCode()).isEqualTo(200);

        HttpResponse<String> out = web.post("/logout", "application/x-www-form-urlencoded", "csrf=" + csrf, "Cookie", cookie);
        assertThat(out.statusCode()).isEqualTo(303);
        assertThat(out.headers().firstValue("Set-Cookie").orElseThrow()).contains("Max-Age=0");
        assertThat(web.get("/api/session", "Cookie", cookie).statusCode()).isEqualTo(401);
        assertThat(s.await("CLOSED", T)).as("the page's socket ends with the session").startsWith("CLOSED");
        assertThatThrownBy(() -> web.socket(cookie, origin)).as("no new socket on the ended session").isNotNull();
    }

    @Test
    void aWebSocketFromAnotherSiteOrWithoutOriginIsRefused() throws Exception {
        String cookie = web.login("alice", TestSystem.PASSWORD);
        assertThatThrownBy(() -> web.socket(cookie, "https://evil.example")).rootCause().hasMessageContaining("403");
        assertThatThrownBy(() -> web.socket(cookie, null)).rootCause().hasMessageContaining("403");
        assertThatThrownBy(() -> web.socket("ripv-session=nothing", origin)).rootCause().hasMessageContaining("403");
        WebVisitor.Socket ok = web.socket(cookie, origin);
        ok.send(1, "", "?ping", web.csrf(cookie));
        assertThat(ok.await("\"id\":1", T)).contains("\"status\":\"OK\"");
        // A message without the session's CSRF token ends the socket, and is never sent.
        ok.send(2, CLOCK, "time", "forged");
        assertThat(ok.await("CLOSED", T)).contains("CSRF");
    }

    @Test
    void anObserversCommandIsRefusedByTheServerAndAnOperatorsGoesThrough() throws Exception {
        String olga = web.login("olga", TestSystem.PASSWORD);
        WebVisitor.Socket s = web.socket(olga, origin);
        s.send(1, CLOCK, "time", web.csrf(olga));
        String refused = s.await("\"id\":1", T);
        assertThat(refused).contains("\"status\":\"ERROR\"").contains("FORBIDDEN");
        String alice = web.login("alice", TestSystem.PASSWORD);
        WebVisitor.Socket a = web.socket(alice, origin);
        a.send(1, CLOCK, "time", web.csrf(alice));
        assertThat(a.await("\"id\":1", T)).contains("\"status\":\"OK\"");
        assertThat(audit()).contains("web-client").contains("olga");
    }

    @Test
    void uploadsKeepTheNameRulesTheLimitAndNeverReplace() throws Exception {
        String cookie = web.login("alice", TestSystem.PASSWORD);
        String csrf = web.csrf(cookie);
        Files.writeString(sys.uploadDir().resolve("kept.txt"), "OPERATOR");
        assertThat(upload(cookie, csrf, "..\\evil.txt", "x").statusCode()).isEqualTo(400);
        HttpResponse<String> exists = upload(cookie, csrf, "kept.txt", "ATTACKER");
        assertThat(exists.statusCode()).as(exists.body()).isEqualTo(409);
        assertThat(exists.body()).contains("FILE_EXISTS");
        assertThat(Files.readString(sys.uploadDir().resolve("kept.txt"))).isEqualTo("OPERATOR");
        assertThat(upload(cookie, "wrong", "new.txt", "x").statusCode()).isEqualTo(403);
        HttpResponse<String> ok = upload(cookie, csrf, "new.txt", "hello");
        assertThat(ok.statusCode()).as(ok.body()).isEqualTo(200);
        assertThat(Files.readString(sys.uploadDir().resolve("new.txt"))).isEqualTo("hello");
        try (var files = Files.list(sys.uploadDir().resolve(".ripv-form"))) {
            assertThat(files).as("nothing left half-written").isEmpty();
        }
    }

    /** Every audit line so far (DATA/audit/DAY.log). */
    private static String audit() throws Exception {
        StringBuilder b = new StringBuilder();
        try (var days = Files.list(sys.dataDir().resolve("audit"))) {
            for (Path d : days.sorted().toList()) {
                b.append(Files.readString(d));
            }
        }
        return b.toString();
    }

    private static HttpResponse<String> upload(String cookie, String csrf, String name, String content) throws Exception {
        String b = "----ripvWeb";
        String body = "--" + b + "\r\nContent-Disposition: form-data; name=\"file\"; filename=\"" + name
                + "\"\r\nContent-Type: text/plain\r\n\r\n" + content + "\r\n--" + b + "--\r\n";
        return web.post("/upload?csrf=" + csrf, "multipart/form-data; boundary=" + b, body, "Cookie", cookie);
    }

    @Test
    void guessingThroughTheFormMeetsTheSocketsThrottle() throws Exception {
        sys.user("vic", "operators");
        int refused = 0;
        String last = "";
        for (int i = 0; i < 8; i++) {
            HttpResponse<String> r = web.post("/login", "application/x-www-form-urlencoded", "user=vic&password=guess" + i);
            assertThat(r.statusCode()).isEqualTo(403);
            last = r.body();
            refused++;
        }
        assertThat(refused).isEqualTo(8);
        assertThat(last).containsIgnoringCase("too many");
        String audit = audit();
        assertThat(audit).contains("login-failed").contains("vic").contains("web");
    }

    /**
     * Issue 23 item 6: a thousand connections that send half a request and wait do not stop a
     * visitor, and are closed at the header deadline.
     */
    @Test
    void aThousandSlowConnectionsDoNotBlockOthersAndAreCutAtTheHeaderDeadline() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("slow")).withPorts(0, 0, 0);
        config = config.withSecurity(config.security().withPlain(true));
        try (TestSystem plain = TestSystem.start(config)) {
            int port = plain.server().httpPort();
            List<Socket> slow = new ArrayList<>();
            try {
                for (int i = 0; i < 1000; i++) {
                    Socket s = new Socket(InetAddress.getLoopbackAddress(), port);
                    s.getOutputStream().write("GET / HTTP/1.1\r\nHost: localhost\r\nX-Slow: ".getBytes(StandardCharsets.US_ASCII));
                    s.getOutputStream().flush();
                    slow.add(s);
                }
                WebVisitor visitor = new WebVisitor(port, false);
                long start = System.nanoTime();
                HttpResponse<String> page = visitor.get("/");
                assertThat(page.statusCode()).isEqualTo(200);
                assertThat(page.body()).contains("RIPV");
                assertThat(Duration.ofNanos(System.nanoTime() - start)).as("served while 1,000 wait").isLessThan(Duration.ofSeconds(10));
                // The header deadline (10 s) closes them; a generous bound for a loaded machine.
                Socket first = slow.get(0);
                first.setSoTimeout(60_000);
                InputStream in = first.getInputStream();
                int r;
                try {
                    r = in.read();
                    while (r >= 0) {
                        r = in.read();
                    }
                } catch (java.net.SocketException e) {
                    r = -1; // reset: closed as well
                }
                assertThat(r).isEqualTo(-1);
                Socket lastOne = slow.get(slow.size() - 1);
                lastOne.setSoTimeout(30_000);
                try (OutputStream o = lastOne.getOutputStream()) {
                    assertThat(lastOne.getInputStream().read()).isEqualTo(-1);
                } catch (java.net.SocketException e) {
                    // reset: closed
                }
            } finally {
                for (Socket s : slow) {
                    s.close();
                }
            }
        }
    }
}
