package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.it.web.LaunchedWeb;
import org.ripv.it.web.WebVisitor;

/**
 * The public view ({@code --public 'glider*'}, issue 21 item 9) against an anonymous script: the
 * server, a SerialPortServer with a public glider and a vehicle that is not public, and the
 * simulated glider calling in, all from the jars. The visitor gets the public glider's name, state,
 * last contact and track, and nothing else: not the other vehicle, not a console line, no session,
 * no console WebSocket, no upload, no write to the public view.
 */
class PublicViewAttackTest {
    @TempDir
    static Path dir;
    static LaunchedWeb sys;
    static WebVisitor web;
    static final ObjectMapper JSON = new ObjectMapper();

    @BeforeAll
    static void start() throws Exception {
        sys = new LaunchedWeb(dir, List.of("alice:operators"), List.of(), "--public", "glider*");
        sys.vehicles("glider1", "hidden2");
        web = new WebVisitor(sys.http, true);
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void anonymousSeesOnlyTheMatchingVehiclesNameStateLastContactAndTrack() throws Exception {
        JsonNode[] seen = new JsonNode[1];
        sys.waitFor("the public glider on call with a fix", () -> {
            try {
                HttpResponse<String> r = web.get("/api/public");
                seen[0] = JSON.readTree(r.body());
                JsonNode v = seen[0].path("vehicles").path(0);
                return r.statusCode() == 200 && "ON_CALL".equals(v.path("state").asText()) && v.path("track").size() > 0;
            } catch (Exception e) {
                return false;
            }
        });
        JsonNode vehicles = seen[0].get("vehicles");
        assertThat(vehicles).hasSize(1);
        JsonNode glider = vehicles.get(0);
        assertThat(glider.get("name").asText()).isEqualTo("glider1");
        List<String> fields = new ArrayList<>();
        glider.fieldNames().forEachRemaining(fields::add);
        assertThat(fields).containsExactly("name", "state", "lastContact", "track");
        assertThat(glider.get("lastContact").asLong()).isPositive();
        assertThat(glider.get("track").get(0).size()).isEqualTo(2);
        String body = web.get("/api/public").body();
        assertThat(body).as("no other vehicle, no address, no console text").doesNotContain("hidden2").doesNotContain("SerialPortServer")
                .doesNotContainIgnoringCase("GPS Location").doesNotContainIgnoringCase("picodos").doesNotContain("localhost");
    }

    @Test
    void anonymousGetsNothingElse() throws Exception {
        assertThat(web.get("/api/session").statusCode()).as("no session without a log-in").isEqualTo(401);
        assertThat(web.get("/api/session", "Cookie", "ripv-session=guessed").statusCode()).isEqualTo(401);
        assertThatThrownBy(() -> web.socket("other=1", web.base)).as("no console WebSocket").rootCause().hasMessageContaining("403");
        assertThatThrownBy(() -> web.socket("ripv-session=guessed", web.base)).rootCause().hasMessageContaining("403");
        HttpResponse<String> upload = web.post("/upload", "multipart/form-data; boundary=x",
                "--x\r\nContent-Disposition: form-data; name=\"file\"; filename=\"a.txt\"\r\n\r\nhello\r\n--x--\r\n", "Origin", web.base);
        assertThat(upload.statusCode()).as("no upload").isEqualTo(403);
        HttpResponse<String> write = web.post("/api/public", "application/json", "{\"name\":\"hidden2\"}", "Origin", web.base);
        assertThat(write.statusCode()).as("the public view is read only").isEqualTo(405);
        assertThat(web.get("/api/public?name=hidden2").body()).doesNotContain("hidden2");
        assertThat(web.get("/api/public/../session").statusCode()).isNotEqualTo(200);
        HttpResponse<String> page = web.get("/public.html");
        assertThat(page.statusCode()).isEqualTo(200);
        assertThat(page.headers().firstValue("Content-Security-Policy").orElseThrow()).contains("script-src 'self'");
    }
}
