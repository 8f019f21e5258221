package org.ripv.server.http;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The landing page over real HTTP on loopback. */
class LandingPageTest {
    static final long LIMIT = 4096;

    @TempDir
    Path tmp;
    Path uploads;
    Path jar;
    LandingPage page;
    HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    String base;

    @BeforeEach
    void start() throws IOException {
        uploads = tmp.resolve("upload");
        jar = tmp.resolve("ripv-client.jar");
        page = new LandingPage(new LandingPage.Options(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0),
                uploads, LIMIT, jar, () -> "RIPVServer on testhost\nclient port 4444, 3 service(s) registered", 4444,
                TESTER, null));
        page.start();
        base = "http://127.0.0.1:" + page.port();
    }

    @AfterEach
    void stop() {
        page.stop();
    }

    /** Lets "tester" in with "pass"; refuses files named forbidden*. */
    static final WebAccess TESTER = new WebAccess() {
        @Override
        public Result login(String user, char[] password, String address) {
            return user.equals("tester") && new String(password).equals("pass") ? Result.ok(user)
                    : Result.refused("wrong user name or password");
        }

        @Override
        public boolean mayUpload(String user, String fileName) {
            return !fileName.startsWith("forbidden");
        }
    };

    String cookie;
    String csrf;

    /** Logs in through the form; keeps the session cookie and the form's CSRF token. */
    void logIn() throws Exception {
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(URI.create(base + "/login"))
                .header("Content-Type", "application/x-www-form-urlencoded")
                .POST(HttpRequest.BodyPublishers.ofString("user=tester&password=pass")).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(r.statusCode()).as(r.body()).isEqualTo(303);
        String set = r.headers().firstValue("Set-Cookie").orElseThrow();
        assertThat(set).contains("HttpOnly").contains("SameSite=Strict");
        cookie = set.split(";")[0];
        String index = http.send(HttpRequest.newBuilder(URI.create(base + "/")).header("Cookie", cookie).build(),
                HttpResponse.BodyHandlers.ofString()).body();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("action=\"/upload\\?csrf=([0-9a-f]+)\"").matcher(index);
        assertThat(m.find()).as(index).isTrue();
        csrf = m.group(1);
    }

    HttpResponse<String> get(String path) throws Exception {
        return http.send(HttpRequest.newBuilder(URI.create(base + path)).timeout(Duration.ofSeconds(10)).build(),
                HttpResponse.BodyHandlers.ofString());
    }

    @Test
    void frontPageSaysWhatThisServerIsAndOffersTheClientAndTheForm() throws Exception {
        Files.write(jar, new byte[] {'P', 'K', 3, 4});
        HttpResponse<String> r = get("/");
        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.headers().firstValue("Content-Type")).hasValue("text/html; charset=utf-8");
        assertThat(r.body()).contains("RIPVServer on testhost").contains("3 service(s) registered")
                .contains("href=\"/ripv-client.jar\"").contains("href=\"/ripv-client.jnlp\"")
                .contains("href=\"/login\"").doesNotContain("action=\"/upload")
                .contains("client 127.0.0.1:4444").contains("ripv cli --server 127.0.0.1:4444");
    }

    @Test
    void statusTextIsEscaped() throws Exception {
        page.stop();
        page = new LandingPage(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), uploads, LIMIT, null,
                () -> "<script>alert(1)</script>");
        page.start();
        base = "http://127.0.0.1:" + page.port();
        String body = get("/").body();
        assertThat(body).doesNotContain("<script>").contains("&lt;script&gt;");
        assertThat(body).contains("offers no client jar");
    }

    @Test
    void servesTheClientJarWhenItExists() throws Exception {
        byte[] content = new byte[100_000];
        for (int i = 0; i < content.length; i++) {
            content[i] = (byte) (i * 31);
        }
        Files.write(jar, content);
        HttpResponse<byte[]> r = http.send(HttpRequest.newBuilder(URI.create(base + "/ripv-client.jar")).build(),
                HttpResponse.BodyHandlers.ofByteArray());
        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.headers().firstValue("Content-Type")).hasValue("application/java-archive");
        assertThat(r.body()).isEqualTo(content);
    }

    @Test
    void aMissingJarIsAClear404() throws Exception {
        HttpResponse<String> r = get("/ripv-client.jar");
        assertThat(r.statusCode()).isEqualTo(404);
        assertThat(r.body()).contains("ripv-client.jar is not there").contains("mvn -DskipTests package");
    }

    @Test
    void jnlpPointsAtTheJarOnTheHostTheBrowserUsed() throws Exception {
        HttpResponse<String> r = get("/ripv-client.jnlp");
        assertThat(r.statusCode()).isEqualTo(200);
        assertThat(r.headers().firstValue("Content-Type")).hasValue("application/x-java-jnlp-file");
        assertThat(r.body()).startsWith("<?xml").contains("codebase=\"http://127.0.0.1:" + page.port() + "/\"")
                .contains("<jar href=\"ripv-client.jar\" main=\"true\"/>")
                .contains("main-class=\"org.ripv.client.ClientMain\"")
                .contains("<argument>client</argument>").contains("<argument>127.0.0.1:4444</argument>");
    }

    @Test
    void aForgedHostHeaderCannotInjectIntoTheJnlp() throws Exception {
        // HttpClient will not send a bad Host header, so speak HTTP by hand.
        try (java.net.Socket s = new java.net.Socket(InetAddress.getLoopbackAddress(), page.port())) {
            s.getOutputStream().write(("GET /ripv-client.jnlp HTTP/1.1\r\nHost: evil\"><jar href=\"http://x/y.jar\r\n"
                    + "Connection: close\r\n\r\n").getBytes(StandardCharsets.ISO_8859_1));
            String answer = new String(s.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(answer).startsWith("HTTP/1.1 200").doesNotContain("evil").doesNotContain("http://x/y.jar")
                    .contains("codebase=\"http://127.0.0.1:" + page.port() + "/\"");
        }
    }

    @Test
    void unknownPathsAndWrongMethodsAreRefused() throws Exception {
        assertThat(get("/etc/passwd").statusCode()).isEqualTo(404);
        assertThat(get("/upload").statusCode()).isEqualTo(405);
        HttpResponse<String> post = http.send(HttpRequest.newBuilder(URI.create(base + "/"))
                .POST(HttpRequest.BodyPublishers.ofString("x")).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(post.statusCode()).isEqualTo(405);
    }

    // ---------------------------------------------------------------- uploads

    static final String BOUNDARY = "----ripvTestBoundary7MA4YWxkTrZu0gW";

    /** A multipart body; a null content is a plain text field. */
    static byte[] form(Map<String, Object[]> fields) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        for (Map.Entry<String, Object[]> f : fields.entrySet()) {
            b.write(("--" + BOUNDARY + "\r\n").getBytes(StandardCharsets.ISO_8859_1));
            Object[] v = f.getValue();
            if (v[0] == null) {
                b.write(("Content-Disposition: form-data; name=\"" + f.getKey() + "\"\r\n\r\n").getBytes(StandardCharsets.UTF_8));
                b.write(((String) v[1]).getBytes(StandardCharsets.UTF_8));
            } else {
                b.write(("Content-Disposition: form-data; name=\"" + f.getKey() + "\"; filename=\"" + v[0] + "\"\r\n"
                        + "Content-Type: application/octet-stream\r\n\r\n").getBytes(StandardCharsets.UTF_8));
                b.write((byte[]) v[1]);
            }
            b.write("\r\n".getBytes(StandardCharsets.ISO_8859_1));
        }
        b.write(("--" + BOUNDARY + "--\r\n").getBytes(StandardCharsets.ISO_8859_1));
        return b.toByteArray();
    }

    HttpResponse<String> post(byte[] body) throws Exception {
        if (cookie == null) {
            logIn();
        }
        return http.send(HttpRequest.newBuilder(URI.create(base + "/upload?csrf=" + csrf)).header("Cookie", cookie)
                .header("Content-Type", "multipart/form-data; boundary=" + BOUNDARY)
                .POST(HttpRequest.BodyPublishers.ofByteArray(body)).build(), HttpResponse.BodyHandlers.ofString());
    }

    static byte[] bytes(int n, int seed) {
        byte[] b = new byte[n];
        for (int i = 0; i < n; i++) {
            b[i] = (byte) (seed + i * 7);
        }
        return b;
    }

    long visibleFiles() throws IOException {
        try (Stream<Path> s = Files.list(uploads)) {
            return s.count();
        }
    }

    HttpResponse<String> postAs(String query, String cookieHeader, byte[] body) throws Exception {
        HttpRequest.Builder b = HttpRequest.newBuilder(URI.create(base + "/upload" + query))
                .header("Content-Type", "multipart/form-data; boundary=" + BOUNDARY);
        if (cookieHeader != null) {
            b.header("Cookie", cookieHeader);
        }
        return http.send(b.POST(HttpRequest.BodyPublishers.ofByteArray(body)).build(), HttpResponse.BodyHandlers.ofString());
    }

    static byte[] oneFile(String name) throws IOException {
        Map<String, Object[]> f = new LinkedHashMap<>();
        f.put("file-to-upload-1", new Object[] {name, bytes(100, 9)});
        return form(f);
    }

    @Test
    void anAnonymousUploadIsRefusedAndWritesNothing() throws Exception {
        // Issue 10 item 2: curl -F file-to-upload-1=@x;filename=mission.bin http://server:8080/upload
        HttpResponse<String> r = postAs("", null, oneFile("mission.bin"));
        assertThat(r.statusCode()).isEqualTo(403);
        assertThat(r.body()).contains("Log in first");
        assertThat(visibleFiles()).isZero();
        // A wrong password gives no session; a session without the form's CSRF token is refused too.
        HttpResponse<String> bad = http.send(HttpRequest.newBuilder(URI.create(base + "/login"))
                .POST(HttpRequest.BodyPublishers.ofString("user=tester&password=guess")).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(bad.statusCode()).isEqualTo(403);
        assertThat(bad.headers().firstValue("Set-Cookie")).isEmpty();
        logIn();
        assertThat(postAs("", cookie, oneFile("mission.bin")).statusCode()).isEqualTo(403);
        assertThat(postAs("?csrf=" + "0".repeat(48), cookie, oneFile("mission.bin")).statusCode()).isEqualTo(403);
        assertThat(visibleFiles()).isZero();
        // The permit decides per name; an existing file is never replaced.
        assertThat(post(oneFile("forbidden.bin")).statusCode()).isEqualTo(403);
        assertThat(post(oneFile("mission.bin")).statusCode()).isEqualTo(200);
        Files.write(uploads.resolve("mission.bin"), new byte[] {1, 2, 3});
        HttpResponse<String> again = post(oneFile("mission.bin"));
        assertThat(again.statusCode()).isEqualTo(409);
        assertThat(Files.readAllBytes(uploads.resolve("mission.bin"))).containsExactly(1, 2, 3);
        assertThat(visibleFiles()).isEqualTo(1);
    }

    @Test
    void withoutAccessThePageTakesNoUploadsAtAll() throws Exception {
        page.stop();
        page = new LandingPage(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), uploads, LIMIT, null, () -> "x");
        page.start();
        base = "http://127.0.0.1:" + page.port();
        assertThat(get("/").body()).contains("takes no uploads").doesNotContain("<form");
        HttpResponse<String> r = postAs("", null, oneFile("mission.bin"));
        assertThat(r.statusCode()).isEqualTo(403);
        assertThat(r.body()).contains("--http-upload");
        assertThat(get("/login").statusCode()).isEqualTo(404);
        assertThat(visibleFiles()).isZero();
    }

    @Test
    void uploadsSeveralFilesByteForByte() throws Exception {
        Map<String, Object[]> f = new LinkedHashMap<>();
        f.put("file-to-upload-1", new Object[] {"glider.bin", bytes(1500, 1)});
        f.put("note", new Object[] {null, "a text field is ignored"});
        // Bytes that look like a boundary start must survive.
        byte[] tricky = ("line\r\n--" + BOUNDARY.substring(0, 10) + "\r\n--\r\n").getBytes(StandardCharsets.ISO_8859_1);
        f.put("file-to-upload-2", new Object[] {"data.dat", tricky});
        f.put("file-to-upload-3", new Object[] {"", new byte[0]});
        HttpResponse<String> r = post(form(f));
        assertThat(r.statusCode()).as(r.body()).isEqualTo(200);
        assertThat(r.body()).contains("glider.bin (1500 bytes)").contains("data.dat");
        assertThat(Files.readAllBytes(uploads.resolve("glider.bin"))).isEqualTo(bytes(1500, 1));
        assertThat(Files.readAllBytes(uploads.resolve("data.dat"))).isEqualTo(tricky);
        assertThat(visibleFiles()).as("no temporary files left").isEqualTo(2);
    }

    @Test
    void aNameWithASlashMeansNoneOfTheFilesAreSaved() throws Exception {
        for (String bad : new String[] {"../evil.sh", "dir/file", "C:\\Users\\me\\file.txt", ".hidden", "..", ".profile"}) {
            Map<String, Object[]> f = new LinkedHashMap<>();
            f.put("file-to-upload-1", new Object[] {"good.txt", bytes(10, 2)});
            f.put("file-to-upload-2", new Object[] {bad, bytes(10, 3)});
            HttpResponse<String> r = post(form(f));
            assertThat(r.statusCode()).as(bad).isEqualTo(400);
            assertThat(r.body()).contains("Filename problem").contains("None of the files were saved");
            assertThat(visibleFiles()).as("nothing written for " + bad).isZero();
        }
        assertThat(tmp.resolve("evil.sh")).doesNotExist();
    }

    @Test
    void overTheLimitMeansNoneOfTheFilesAreSaved() throws Exception {
        Map<String, Object[]> f = new LinkedHashMap<>();
        f.put("file-to-upload-1", new Object[] {"a.bin", bytes(3000, 4)});
        f.put("file-to-upload-2", new Object[] {"b.bin", bytes(3000, 5)});
        HttpResponse<String> r = post(form(f));
        assertThat(r.statusCode()).isEqualTo(413);
        assertThat(r.body()).contains("limit of " + LIMIT + " bytes").contains("None of the files were saved");
        assertThat(visibleFiles()).isZero();
    }

    @Test
    void aDeclaredLengthFarOverTheLimitIsRefusedBeforeReading() throws Exception {
        Map<String, Object[]> f = new LinkedHashMap<>();
        f.put("file-to-upload-1", new Object[] {"big.bin", bytes((int) (LIMIT + LandingPage.FORM_OVERHEAD + 10), 6)});
        logIn();
        // On a fresh connection, as before the log-in existed: the server answers without reading
        // the body, which a kept-alive connection may see as a reset while it still writes.
        HttpResponse<String> r = HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create(base + "/upload?csrf=" + csrf))
                .header("Cookie", cookie).header("Content-Type", "multipart/form-data; boundary=" + BOUNDARY)
                .POST(HttpRequest.BodyPublishers.ofByteArray(form(f))).build(), HttpResponse.BodyHandlers.ofString());
        assertThat(r.statusCode()).isEqualTo(413);
        assertThat(visibleFiles()).isZero();
    }

    @Test
    void malformedFormsAreClearErrors() throws Exception {
        logIn();
        HttpResponse<String> notMultipart = http.send(HttpRequest.newBuilder(URI.create(base + "/upload?csrf=" + csrf))
                .header("Cookie", cookie).header("Content-Type", "text/plain").POST(HttpRequest.BodyPublishers.ofString("hello")).build(),
                HttpResponse.BodyHandlers.ofString());
        assertThat(notMultipart.statusCode()).isEqualTo(400);
        assertThat(notMultipart.body()).contains("multipart/form-data");

        byte[] whole = form(Map.of("file-to-upload-1", new Object[] {"cut.bin", bytes(500, 7)}));
        byte[] truncated = java.util.Arrays.copyOf(whole, whole.length - 60);
        HttpResponse<String> r = post(truncated);
        assertThat(r.statusCode()).isEqualTo(400);
        assertThat(r.body()).contains("None of the files were saved");
        assertThat(visibleFiles()).isZero();

        HttpResponse<String> empty = post(form(Map.of("note", new Object[] {null, "no files"})));
        assertThat(empty.statusCode()).isEqualTo(400);
        assertThat(empty.body()).contains("no files");
    }

    @Test
    void stopReleasesThePort() throws Exception {
        int port = page.port();
        page.stop();
        try (java.net.ServerSocket s = new java.net.ServerSocket()) {
            s.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
            assertThat(s.isBound()).isTrue();
        }
    }
}
