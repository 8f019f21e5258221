package org.ripv.server.http;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Upload throughput of the landing page's form over loopback. Run with {@code -Dripv.bench=true}. */
class LandingPageBenchmarkTest {
    @TempDir
    Path dir;

    @Test
    void uploadThroughput() throws Exception {
        assumeTrue(Boolean.getBoolean("ripv.bench"), "benchmark: run with -Dripv.bench=true");
        int size = 64 * 1024 * 1024;
        LandingPage page = new LandingPage(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0),
                dir.resolve("up"), 2L * size, null, () -> "bench");
        page.start();
        try {
            byte[] file = new byte[size];
            new java.util.Random(1).nextBytes(file);
            ByteArrayOutputStream body = new ByteArrayOutputStream(size + 1024);
            body.write(("--B0undary\r\nContent-Disposition: form-data; name=\"f\"; filename=\"big.bin\"\r\n\r\n")
                    .getBytes(StandardCharsets.ISO_8859_1));
            body.write(file);
            body.write("\r\n--B0undary--\r\n".getBytes(StandardCharsets.ISO_8859_1));
            byte[] bytes = body.toByteArray();
            HttpClient http = HttpClient.newHttpClient();
            for (int round = 0; round < 3; round++) {
                long t0 = System.nanoTime();
                HttpResponse<String> r = http.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + page.port() + "/upload"))
                        .header("Content-Type", "multipart/form-data; boundary=B0undary")
                        .POST(HttpRequest.BodyPublishers.ofByteArray(bytes)).build(), HttpResponse.BodyHandlers.ofString());
                double s = (System.nanoTime() - t0) / 1e9;
                assertThat(r.statusCode()).isEqualTo(200);
                System.out.printf("round %d: %d MB in %.2f s = %.0f MB/s%n", round, size >> 20, s, (size >> 20) / s);
            }
            assertThat(Files.size(dir.resolve("up/big.bin"))).isEqualTo(size);
        } finally {
            page.stop();
        }
    }
}
