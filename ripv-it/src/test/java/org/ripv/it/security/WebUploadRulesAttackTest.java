package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.Base64;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.it.TestSystem;
import org.ripv.it.web.WebVisitor;
import org.ripv.server.ServerConfig;

/**
 * Issue 33 item 5 (and item 10's upload modes and names): the {@code /upload} form skipped the
 * per-user {@code quota} and {@code .owners} that {@code ?upload} enforces, stored files 0644 in a
 * 0755 folder, and took names with bidirectional controls (U+202E shows {@code evil\u202Efdp.wf}
 * as {@code evilfw.pdf}). Now the form stores through the same FileStore rule as the client's chunks.
 */
class WebUploadRulesAttackTest {
    static final Duration T = Duration.ofSeconds(20);

    @TempDir
    static Path dir;
    static TestSystem sys;
    static WebVisitor web;

    @BeforeAll
    static void start() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config.withSecurity(config.security().withHttpUpload(true))).user("olga", "observers");
        sys.rules("allow olga RIPVServer * ?upload *", "allow olga RIPVServer * ?ulfiles", "quota olga 1000");
        web = new WebVisitor(sys.server().httpPort(), true);
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    static HttpResponse<String> form(String cookie, String csrf, String name, String content) throws Exception {
        String b = "----ripvWeb";
        String body = "--" + b + "\r\nContent-Disposition: form-data; name=\"file\"; filename=\"" + name
                + "\"\r\nContent-Type: text/plain\r\n\r\n" + content + "\r\n--" + b + "--\r\n";
        return web.post("/upload?csrf=" + csrf, "multipart/form-data; boundary=" + b, body, "Cookie", cookie);
    }

    @Test
    void theFormKeepsTheQuotaTheOwnersAndOwnerOnlyModes() throws Exception {
        String cookie = web.login("olga", TestSystem.PASSWORD);
        String csrf = web.csrf(cookie);
        HttpResponse<String> first = form(cookie, csrf, "first.txt", "x".repeat(800));
        assertThat(first.statusCode()).as(first.body()).isEqualTo(200);
        Path stored = sys.uploadDir().resolve("first.txt");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(stored))).isEqualTo("rw-------");
        assertThat(PosixFilePermissions.toString(Files.getPosixFilePermissions(sys.uploadDir().resolve(".ripv-form"))))
                .isEqualTo("rwx------");
        assertThat(sys.server().fileStore().owner("first.txt")).as(".owners names the uploader").isEqualTo("olga");

        HttpResponse<String> over = form(cookie, csrf, "second.txt", "y".repeat(800));
        assertThat(over.statusCode()).as(over.body()).isEqualTo(413);
        assertThat(over.body()).contains("the quota is 1000 bytes").contains("None of the files were saved");
        assertThat(sys.uploadDir().resolve("second.txt")).doesNotExist();
        try (var parked = Files.list(sys.uploadDir().resolve(".ripv-form"))) {
            assertThat(parked).as("nothing left half-written").isEmpty();
        }
    }

    @Test
    void aNameWithABidiControlIsRefused() throws Exception {
        String cookie = web.login("olga", TestSystem.PASSWORD);
        String csrf = web.csrf(cookie);
        WebVisitor.Socket s = web.socket(cookie, web.base);
        for (String name : new String[] {"evil\u202Efdp.wf", "a\u2066b.wf", "c\u0085d.wf"}) {
            byte[] bytes = "workflow once\n".getBytes(StandardCharsets.UTF_8);
            s.ws.sendText("{\"id\":1,\"mailbox\":\"\",\"body\":\"?upload " + name + " 0 " + bytes.length + "\",\"file\":\"" + name
                    + "\",\"data\":\"" + Base64.getEncoder().encodeToString(bytes) + "\",\"csrf\":\"" + csrf + "\"}", true).join();
            assertThat(s.await("\"id\":1", T)).as(name).contains("\"ERROR\"").containsPattern("bidirectional control|control character");
        }
        try (var names = Files.list(sys.uploadDir())) {
            assertThat(names.map(p -> p.getFileName().toString())).noneMatch(n -> n.matches(".*[\u202E\u2066\u0085].*"));
        }
    }
}
