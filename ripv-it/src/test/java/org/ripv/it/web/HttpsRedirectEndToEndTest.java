package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The launched server's HTTPS port (issue 32 item 12): {@code http://} on it answers a redirect to
 * the same address under {@code https://}, not TLS bytes read as garbage, and nothing else; the
 * favicon is there (no 404 in every page's log).
 */
class HttpsRedirectEndToEndTest {
    @TempDir
    static Path dir;
    static LaunchedWeb sys;

    @BeforeAll
    static void start() throws Exception {
        sys = new LaunchedWeb(dir, List.of("alice:operators"), List.of());
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void plainHttpOnTheHttpsPortIsSentToHttps() throws Exception {
        HttpClient plain = HttpClient.newBuilder().followRedirects(HttpClient.Redirect.NEVER).connectTimeout(Duration.ofSeconds(10)).build();
        for (String method : List.of("GET", "POST")) {
            HttpResponse<String> r = plain.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + sys.http + "/fleet.html?x=1"))
                    .method(method, HttpRequest.BodyPublishers.noBody()).timeout(Duration.ofSeconds(20)).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertThat(r.statusCode()).as(method).isEqualTo(308);
            assertThat(r.headers().firstValue("Location")).as(method).contains("https://127.0.0.1:" + sys.http + "/fleet.html?x=1");
            assertThat(r.headers().firstValue("Set-Cookie")).as("no session over plain HTTP").isEmpty();
            assertThat(r.body()).contains("https://127.0.0.1:" + sys.http + "/fleet.html?x=1");
        }
        // HTTPS on the same port is unchanged.
        WebVisitor tls = new WebVisitor(sys.http, true);
        HttpResponse<String> page = tls.get("/");
        assertThat(page.statusCode()).isEqualTo(200);
        assertThat(page.headers().firstValue("Strict-Transport-Security")).isPresent();
        HttpResponse<byte[]> icon = tls.http.send(HttpRequest.newBuilder(URI.create(tls.base + "/favicon.ico")).build(),
                HttpResponse.BodyHandlers.ofByteArray());
        assertThat(icon.statusCode()).isEqualTo(200);
        assertThat(icon.headers().firstValue("Content-Type").orElse("")).startsWith("image/");
        assertThat(java.util.Arrays.copyOf(icon.body(), 4)).containsExactly(0, 0, 1, 0); // an ICO file's header
    }
}
