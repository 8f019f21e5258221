package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.cert.X509Certificate;
import java.time.Duration;
import java.util.stream.Stream;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManager;
import javax.net.ssl.X509TrustManager;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.server.ServerConfig;

/**
 * Issue 10, item 2: before the fix, {@code curl -F file-to-upload-1=@x;filename=mission.bin
 * http://server:8080/upload} stored the attacker's file with no log-in, and the page showed
 * every service's description (a database's JDBC URL) to anyone.
 */
class AnonymousUploadAttackTest {
    static final String BOUNDARY = "----ripvAttack";

    @TempDir
    Path dir;

    /** The visitor's browser after clicking through the self-signed certificate warning (curl -k). */
    static HttpClient insecureClient() throws Exception {
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
        return HttpClient.newBuilder().sslContext(ctx).connectTimeout(Duration.ofSeconds(10)).build();
    }

    static HttpRequest upload(String base, String name) {
        String body = "--" + BOUNDARY + "\r\nContent-Disposition: form-data; name=\"file-to-upload-1\"; filename=\"" + name
                + "\"\r\nContent-Type: application/octet-stream\r\n\r\nATTACKER\r\n--" + BOUNDARY + "--\r\n";
        return HttpRequest.newBuilder(URI.create(base + "/upload")).header("Content-Type", "multipart/form-data; boundary=" + BOUNDARY)
                .POST(HttpRequest.BodyPublishers.ofString(body)).build();
    }

    @Test
    void theDefaultPageOverHttpsTakesNoAnonymousUploadAndShowsNoPaths() throws Exception {
        try (TestSystem sys = TestSystem.start(ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0))) {
            sys.user("alice", "operators");
            sys.register(new ClockService("localhost"));
            Files.writeString(sys.uploadDir().resolve("mission.bin"), "OPERATOR");
            HttpClient http = insecureClient();
            String base = "https://localhost:" + sys.server().httpPort();

            HttpResponse<String> r = http.send(upload(base, "mission.bin"), HttpResponse.BodyHandlers.ofString());
            assertThat(r.statusCode()).isEqualTo(403);
            assertThat(Files.readString(sys.uploadDir().resolve("mission.bin"))).isEqualTo("OPERATOR");
            assertThat(http.send(upload(base, "new.bin"), HttpResponse.BodyHandlers.ofString()).statusCode()).isEqualTo(403);
            try (Stream<Path> files = Files.list(sys.uploadDir())) {
                assertThat(files.filter(Files::isRegularFile).map(p -> p.getFileName().toString())).containsExactly("mission.bin");
            }

            String page = http.send(HttpRequest.newBuilder(URI.create(base + "/")).build(), HttpResponse.BodyHandlers.ofString()).body();
            assertThat(page).contains("ClockService").contains("SHA256:")
                    .doesNotContain(sys.dataDir().toAbsolutePath().toString())
                    .doesNotContain("Example service: time") // service descriptions (a database's is its JDBC URL)
                    .doesNotContain("jdbc:");
            // Plain HTTP on the TLS port serves nothing: only a redirect to https (issue 32), no page, no cookie.
            HttpResponse<String> plain = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                    URI.create("http://localhost:" + sys.server().httpPort() + "/")).timeout(Duration.ofSeconds(5)).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertThat(plain.statusCode()).isEqualTo(308);
            assertThat(plain.headers().firstValue("Location")).contains("https://localhost:" + sys.server().httpPort() + "/");
            assertThat(plain.headers().firstValue("Set-Cookie")).isEmpty();
            assertThat(plain.body()).doesNotContain("ClockService").doesNotContain("SHA256:");
        }
    }

    @Test
    void withHttpUploadOnlyALoggedInUserWithTheRightUploads() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        config = config.withSecurity(config.security().withHttpUpload(true));
        try (TestSystem sys = TestSystem.start(config)) {
            sys.user("alice", "operators");
            HttpClient http = insecureClient();
            String base = "https://localhost:" + sys.server().httpPort();
            assertThat(http.send(upload(base, "mission.bin"), HttpResponse.BodyHandlers.ofString()).statusCode()).isEqualTo(403);

            HttpResponse<String> login = http.send(HttpRequest.newBuilder(URI.create(base + "/login"))
                    .header("Content-Type", "application/x-www-form-urlencoded")
                    .POST(HttpRequest.BodyPublishers.ofString("user=alice&password=" + TestSystem.PASSWORD.replace(" ", "+"))).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertThat(login.statusCode()).as(login.body()).isEqualTo(303);
            String cookie = login.headers().firstValue("Set-Cookie").orElseThrow();
            assertThat(cookie).contains("Secure").contains("HttpOnly");
            String session = cookie.split(";")[0];
            String page = http.send(HttpRequest.newBuilder(URI.create(base + "/")).header("Cookie", session).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("/upload\\?csrf=([0-9a-f]+)").matcher(page);
            assertThat(m.find()).isTrue();
            HttpRequest withSession = HttpRequest.newBuilder(upload(base, "mission.bin"), (k, v) -> true)
                    .uri(URI.create(base + "/upload?csrf=" + m.group(1))).header("Cookie", session).build();
            HttpResponse<String> ok = http.send(withSession, HttpResponse.BodyHandlers.ofString());
            assertThat(ok.statusCode()).as(ok.body()).isEqualTo(200);
            assertThat(Files.readString(sys.uploadDir().resolve("mission.bin"), StandardCharsets.UTF_8)).isEqualTo("ATTACKER");
        }
    }
}
