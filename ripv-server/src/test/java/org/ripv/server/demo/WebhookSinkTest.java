package org.ripv.server.demo;

import static org.assertj.core.api.Assertions.assertThat;

import com.sun.net.httpserver.HttpServer;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.net.InetAddress;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** The demo's webhook sink under what any local process may send it. */
class WebhookSinkTest {
    final ByteArrayOutputStream printed = new ByteArrayOutputStream();
    final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();
    HttpServer server;
    URI base;

    @BeforeEach
    void start() throws Exception {
        WebhookSink sink = new WebhookSink(new PrintStream(printed, true, StandardCharsets.UTF_8));
        sink.port = 0;
        server = sink.start();
        base = URI.create("http://127.0.0.1:" + server.getAddress().getPort() + "/");
    }

    @AfterEach
    void stop() {
        server.stop(0);
    }

    int post(String path, byte[] body) throws Exception {
        return http.send(HttpRequest.newBuilder(base.resolve(path)).timeout(Duration.ofSeconds(10))
                .POST(HttpRequest.BodyPublishers.ofByteArray(body)).build(), HttpResponse.BodyHandlers.discarding()).statusCode();
    }

    String lines() {
        return printed.toString(StandardCharsets.UTF_8);
    }

    @Test
    void aPostIsOneLineWithItsControlCharactersWrittenOut() throws Exception {
        assertThat(post("hook", "{\"event\":\"ALERT\",\"text\":\"\u001b[2J\u001b]0;owned\u0007 leak\r\nnext\"}"
                .getBytes(StandardCharsets.UTF_8))).isEqualTo(204);
        String out = lines();
        assertThat(out.lines()).hasSize(1);
        assertThat(out).contains(" POST /hook {\"event\":\"ALERT\",\"text\":\"\\u001b[2J\\u001b]0;owned\\u0007 leak  next\"}")
                .doesNotContain("\u001b").doesNotContain("\u0007");
    }

    @Test
    void aHugeBodyIsCutAndOnlyPostIsTaken() throws Exception {
        assertThat(post("big", "x".repeat(1 << 20).getBytes(StandardCharsets.US_ASCII))).isEqualTo(204);
        assertThat(lines().strip()).endsWith(" POST /big " + "x".repeat(WebhookSink.MAX_BODY));
        int get = http.send(HttpRequest.newBuilder(base).GET().build(), HttpResponse.BodyHandlers.discarding()).statusCode();
        assertThat(get).isEqualTo(405);
    }

    @Test
    void connectionsThatNeverSendTheirRequestLeaveTheSinkServing() throws Exception {
        List<Socket> silent = new ArrayList<>();
        try {
            for (int i = 0; i < WebhookSink.THREADS - 1; i++) {
                Socket s = new Socket(InetAddress.getLoopbackAddress(), server.getAddress().getPort());
                s.getOutputStream().write("POST /slow HTTP/1.1\r\nHost: x\r\nContent-Length: 100\r\n\r\n{".getBytes(StandardCharsets.US_ASCII));
                s.getOutputStream().flush();
                silent.add(s);
            }
            assertThat(post("after", "ok".getBytes(StandardCharsets.US_ASCII))).isEqualTo(204);
            assertThat(lines()).contains(" POST /after ok");
        } finally {
            for (Socket s : silent) {
                s.close();
            }
        }
    }
}
