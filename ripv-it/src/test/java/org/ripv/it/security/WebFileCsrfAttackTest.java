package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Base64;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.it.web.WebVisitor;
import org.ripv.server.ServerConfig;

/**
 * The web console's files and queue pages (issue 21 item 4) send {@code ?upload} chunks and
 * {@code ?queue add} over the page's WebSocket. A page of another site, or a script holding only
 * the victim's cookie, must not get either through: without the session's CSRF token the socket
 * is closed and nothing is stored or queued; a socket from another origin is never opened; a
 * chunk over the limit is refused with nothing stored. (Before the files page the socket carried
 * no file bytes at all; these keep the new door shut.)
 */
class WebFileCsrfAttackTest {
    static final String CLOCK = WebConsoleAttackTest.CLOCK;
    static final Duration T = WebConsoleAttackTest.T;

    @TempDir
    static Path dir;
    static TestSystem sys;
    static WebVisitor web;
    static String origin;

    /** The server with its upload form on, alice an operator, and the ClockService's MailBox to queue for. */
    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config.withSecurity(config.security().withHttpUpload(true))).user("alice", "operators");
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

    /** An upload chunk as the files page sends it, with the given token. */
    static void uploadChunk(WebVisitor.Socket s, long id, String name, byte[] bytes, String csrf) {
        s.ws.sendText("{\"id\":" + id + ",\"mailbox\":\"\",\"body\":\"?upload " + name + " 0 " + bytes.length + "\",\"file\":\"" + name
                + "\",\"data\":\"" + Base64.getEncoder().encodeToString(bytes) + "\"" + (csrf == null ? "" : ",\"csrf\":\"" + csrf + "\"")
                + "}", true).join();
    }

    @Test
    void anUploadChunkWithoutTheTokenStoresNothing() throws Exception {
        String cookie = web.login("alice", TestSystem.PASSWORD);
        for (String token : new String[] {null, "0123456789abcdef"}) {
            WebVisitor.Socket s = web.socket(cookie, origin);
            uploadChunk(s, 1, "planted.wf", "workflow once\nsend time\n".getBytes(StandardCharsets.UTF_8), token);
            assertThat(s.await("CLOSED", T)).as("token " + token).contains("1008").contains("CSRF");
        }
        assertThat(sys.uploadDir().resolve("planted.wf")).doesNotExist();
        // The page's own chunk, with the token, is stored: the refusal above was the token's.
        WebVisitor.Socket ok = web.socket(cookie, origin);
        uploadChunk(ok, 2, "mine.wf", "workflow once\nsend time\n".getBytes(StandardCharsets.UTF_8), web.csrf(cookie));
        assertThat(ok.await("\"id\":2", T)).contains("stored mine.wf");
        assertThat(sys.uploadDir().resolve("mine.wf")).exists();
    }

    @Test
    void aQueueAddWithoutTheTokenQueuesNothing() throws Exception {
        Files.writeString(sys.uploadDir().resolve("victim.wf"), "workflow every-call\nsend time\n");
        String cookie = web.login("alice", TestSystem.PASSWORD);
        WebVisitor.Socket s = web.socket(cookie, origin);
        s.send(1, "", "?queue add " + CLOCK + " victim.wf", "not-the-token");
        assertThat(s.await("CLOSED", T)).contains("1008");
        WebVisitor.Socket ok = web.socket(cookie, origin);
        ok.send(2, "", "?queue " + CLOCK, web.csrf(cookie));
        assertThat(ok.await("\"id\":2", T)).contains("is empty");
    }

    @Test
    void anUploadOrQueueFromAnotherOriginNeverReachesTheServer() throws Exception {
        String cookie = web.login("alice", TestSystem.PASSWORD);
        assertThatThrownBy(() -> web.socket(cookie, "https://evil.example")).rootCause().hasMessageContaining("403");
        assertThatThrownBy(() -> web.socket(cookie, "null")).rootCause().hasMessageContaining("403");
        // The upload form is a state change of its own: another site's POST is refused before its body is read.
        var r = web.post("/upload", "multipart/form-data; boundary=x", "--x\r\nContent-Disposition: form-data; name=\"file\";"
                + " filename=\"cross.wf\"\r\n\r\nworkflow once\r\n--x--\r\n", "Cookie", cookie, "Origin", "https://evil.example");
        assertThat(r.statusCode()).isEqualTo(403);
        assertThat(r.body()).contains("another origin");
        assertThat(sys.uploadDir().resolve("cross.wf")).doesNotExist();
    }

    @Test
    void aChunkOverTheLimitIsRefusedAndNothingStored() throws Exception {
        String cookie = web.login("alice", TestSystem.PASSWORD);
        WebVisitor.Socket s = web.socket(cookie, origin);
        uploadChunk(s, 1, "big.bin", new byte[47 * 1024], web.csrf(cookie));
        assertThat(s.await("\"type\"", T)).contains("\"error\"").contains("is over 47104");
        assertThat(sys.uploadDir().resolve("big.bin")).doesNotExist();
    }
}
