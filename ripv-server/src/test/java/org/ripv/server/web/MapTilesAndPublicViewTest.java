package org.ripv.server.web;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code --map-tiles}: a usable URL only, and the CSP lets images come from that one host; the
 * public view's {@code /api/public} is 404 unless the operator turned it on, and then gives the
 * fleet's four fields.
 */
class MapTilesAndPublicViewTest {
    @TempDir
    Path dir;

    private WebConsole console(String tiles) {
        return new WebConsole(new WebConsole.Options(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), dir, 1024, null, null,
                4444, null, false, null, null, null, tiles));
    }

    private static HttpResponse<String> get(WebConsole web, String path) throws Exception {
        return HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + web.port() + path)).build(),
                HttpResponse.BodyHandlers.ofString());
    }

    @Test
    void aTileUrlMustBeHttpsWithItsPlaceholders() {
        for (String bad : List.of("http://tile.example.org/{z}/{x}/{y}.png", "https://tile.example.org/tiles.png",
                "https://tile.example.org/{z}/{x}.png", "https://tile.example.org/{z}/{x}/{y}.png; script-src *", "javascript:alert(1)")) {
            assertThatThrownBy(() -> WebConsole.checkMapTiles(bad)).as(bad).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("--map-tiles '" + bad + "'").hasMessageContaining("e.g. https://");
        }
        WebConsole.checkMapTiles("https://tile.openstreetmap.org/{z}/{x}/{y}.png");
        WebConsole.checkMapTiles(null);
    }

    @Test
    void theCspAllowsImagesFromTheTileHostOnly() throws Exception {
        try (WebConsole web = console("https://tiles.example.org:8443/osm/{z}/{x}/{y}.png")) {
            web.start();
            String csp = get(web, "/").headers().firstValue("Content-Security-Policy").orElseThrow();
            assertThat(csp).contains("img-src 'self' data: blob: https://tiles.example.org:8443;").contains("script-src 'self';")
                    .doesNotContain("osm");
        }
        try (WebConsole web = console(null)) {
            web.start();
            assertThat(get(web, "/").headers().firstValue("Content-Security-Policy").orElseThrow()).contains("img-src 'self' data: blob:;");
        }
    }

    @Test
    void thePublicViewIsOffUntilTurnedOnAndThenGivesFourFields() throws Exception {
        try (WebConsole web = console(null)) {
            web.start();
            assertThat(get(web, "/api/public").statusCode()).isEqualTo(404);
        }
        PublicFleet fleet = () -> CompletableFuture.completedFuture(List.of(
                new PublicFleet.Vehicle("glider1", "DIVED", 1_700_000_000_000L, List.of(new double[] {50.1, -145.2}))));
        try (WebConsole web = console(null).withPublicView(fleet)) {
            web.start();
            HttpResponse<String> r = get(web, "/api/public");
            assertThat(r.statusCode()).isEqualTo(200);
            assertThat(r.body()).isEqualTo("{\"mapTiles\":null,\"vehicles\":[{\"name\":\"glider1\",\"state\":\"DIVED\","
                    + "\"lastContact\":1700000000000,\"track\":[[50.1,-145.2]]}]}");
        }
    }
}
