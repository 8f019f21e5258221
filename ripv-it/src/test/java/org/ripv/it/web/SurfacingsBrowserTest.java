package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.StaleElementReferenceException;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.plans.Forecast;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.ripv.probe.FreePorts;

/**
 * Issue 35 items 5 and 6 as launched: the server, a SerialPortServer and a GliderDOS glider
 * (aborting on its second call, leaking from its third) from the jars, and headless Chromium at a
 * desk's size and a phone's. The vehicle page's last call (battery, leak, abort, fix, current, the
 * next call, the waypoint's distance, bearing and ETA), its five trend charts and its map with a
 * current arrow per surfacing and the waypoint; the fleet's because, battery, abort badge, next
 * call and map layers. Then the server restarts while the glider has stopped calling: the interval
 * it learned before comes back from the stored call records, and the glider is OVERDUE by it.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
@ResourceLock(Shared.BROWSER)
class SurfacingsBrowserTest {
    static final String GLIDER1 = "<SerialPortServer>::<localhost>glider1";
    /** The simulated glider steers for 41° 45' N, 70° 25' W (its goto list's default). */
    static final double WPT_LAT = 41.75;
    static final double WPT_LON = -(70 + 25.0 / 60);

    @TempDir
    static Path dir;
    static LaunchedWeb sys;
    static Process glider;

    @BeforeAll
    static void start() throws Exception {
        Chromium.assume();
        sys = new LaunchedWeb(dir, List.of("alice:operators"), List.of());
        // A grace of 40 s: the restart below must happen before the glider is due.
        Files.writeString(sys.data.resolve("surfacing-alerts.conf"), "* overdue.grace 40s\n");
        int link = FreePorts.one();
        sys.launch("serial", null, "-Dripv.host=localhost", "-jar", LaunchedWeb.jar("ripv-services"), "serial", "--server",
                "127.0.0.1:" + sys.registry, "--secret-file", sys.data.resolve("service.secret").toString(), "--carrier", "ignore",
                "--no-enumerate", "--work", dir.resolve("work").toString(),
                "--link", "listen://127.0.0.1:" + link + ",name=glider1,prompt-regex=Glider[Dd][Oo][Ss] [A-Z] -?[0-9]+ >|C:\\\\>,line-ending=cr");
        sys.waitFor("the SerialPortServer's MailBoxes", () -> sys.log("serial").contains("MailBoxes:"));
        glider = sys.launch("glider1", null, "-jar", LaunchedWeb.jar("ripv-services"), "simulator", "--call", "127.0.0.1:" + link,
                "--name", "glider1", "--dialog", "gliderdos", "--surface-seconds", "3", "--dive-seconds", "3",
                "--abort-on-call", "2", "--leak-from-call", "3", "--dir", dir.resolve("glider1").toString());
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    static String text(WebDriver b, String css) {
        return fresh(() -> b.findElement(By.cssSelector(css)).getText());
    }

    static String attr(WebDriver b, String css, String name) {
        return fresh(() -> String.valueOf(b.findElement(By.cssSelector(css)).getAttribute(name)));
    }

    /**
     * Reads an element again when the page redrew it between finding and reading: the fleet table
     * is rebuilt on every pushed event, so a found row may be gone a moment later.
     */
    static <T> T fresh(Supplier<T> read) {
        for (int i = 0; ; i++) {
            try {
                return read.get();
            } catch (StaleElementReferenceException redrawn) {
                if (i == 50) {
                    throw redrawn;
                }
            }
        }
    }

    /** {@code ?surfacings MAILBOX --json --outlook} through the page's own Post Office (one socket per page). */
    @SuppressWarnings("unchecked")
    static Map<String, Object> surfacings(ChromeDriver b, String mailbox) throws Exception {
        String json = String.valueOf(b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                + "Promise.all([import('/postoffice.js'), import('/surfacing.js')]).then(async ([p, m]) => {"
                + " if (!window.testPo) { const s = await p.session(); window.testPo = new p.PostOffice(s.csrf); }"
                + " done(JSON.stringify(await m.surfacings(window.testPo, arguments[0]))); });", mailbox));
        return new ObjectMapper().readValue(json, Map.class);
    }

    /** The server's ?history of the MailBox as text, one entry a line ("EVENT text"). */
    static String history(ChromeDriver b, String mailbox) {
        return String.valueOf(b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                + "import('/postoffice.js').then(async (p) => {"
                + " if (!window.testPo) { const s = await p.session(); window.testPo = new p.PostOffice(s.csrf); }"
                + " const r = await window.testPo.send('', '?history ' + arguments[0] + ' --last 200');"
                + " done((r.result?.entries || []).map((e) => (e.event || e.kind) + ' ' + e.text).join('\\n') || r.text); });", mailbox));
    }

    static WebDriverWait waiting(WebDriver b) {
        return PilotConsoleBrowserTest.waiting(b);
    }

    @Test
    @Order(1)
    @SuppressWarnings("unchecked")
    void theVehiclePageShowsTheLastCallItsTrendsAndTheWayToItsWaypoint() throws Exception {
        ChromeDriver b = sys.loggedIn("alice");
        try {
            WebDriverWait wait = waiting(b);
            b.get(sys.url("/vehicle.html?m=" + java.net.URLEncoder.encode(GLIDER1, java.nio.charset.StandardCharsets.UTF_8)));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            // Four calls: an abort on the second, a leak from the third, the interval learned from three.
            wait.until(d -> Integer.parseInt(attr(d, "#surfacing", "data-records")) >= 4
                    && text(d, "dd[data-key=next]").contains("learned from"));
            PilotConsoleBrowserTest.viewport(b, 1366, 768);
            Thread.sleep(300); // drawn again at the new size
            // The card against the record it shows (the server's own numbers): the page read in one go, as a call may come.
            Map<String, String> card = (Map<String, String>) b.executeScript("const o = {};"
                    + " for (const dd of document.querySelectorAll('#last-call dd')) o[dd.dataset.key] = dd.innerText;"
                    + " const a = (s, n) => document.querySelector(s).getAttribute(n);"
                    + " Object.assign(o, { records: a('#surfacing', 'data-records'), series: a('#trends', 'data-series'),"
                    + " battery_points: a('#trend-battery_v', 'data-points'), arrows: a('#track', 'data-arrows'),"
                    + " waypoints: a('#track', 'data-waypoints'), gps: a('#track', 'data-gps') }); return o;");
            Map<String, Object> d = surfacings(b, GLIDER1);
            List<Map<String, Object>> records = (List<Map<String, Object>>) d.get("records");
            Map<String, Object> last = records.stream().filter(r -> card.get("time").startsWith(
                    r.get("time_utc").toString().replace("T", " ").substring(0, 19))).reduce((x, y) -> y).orElseThrow();
            Map<String, Object> o = (Map<String, Object>) d.get("outlook");
            assertThat(card.get("battery")).isEqualTo(String.format(java.util.Locale.ROOT, "%.2f V", ((Number) last.get("battery_v")).doubleValue()));
            assertThat(card.get("vacuum")).isEqualTo("7.21 inHg");
            assertThat(card.get("leak")).isEqualTo("leak LEAK (1.21 V)"); // the badge, then the words
            assertThat(card.get("abort")).contains("last abort: MS_ABORT_OVERDEPTH")
                    .contains("dive_to: depth 1012.3 > max depth 1000.0").contains("1 since reset");
            assertThat(card.get("because")).isEqualTo("Surface interval [1]");
            assertThat(card.get("mission")).isNotBlank();
            assertThat(card.get("coulombs")).endsWith("Ah (m_coulomb_amphr_total)");
            // 0.112 m/s east, 0.048 south: 0.122 m/s toward 113°.
            assertThat(card.get("current")).isEqualTo("0.122 m/s toward 113°");
            assertThat(card.get("next")).contains("every").contains("learned from its last");
            // The waypoint: distance and bearing from the card's fix, worked again here on the sphere.
            Matcher fix = Pattern.compile("(-?\\d+\\.\\d+), (-?\\d+\\.\\d+)").matcher(card.get("fix"));
            assertThat(fix.find()).isTrue();
            double lat = Double.parseDouble(fix.group(1));
            double lon = Double.parseDouble(fix.group(2));
            assertThat(lat).isCloseTo(((Number) last.get("gps_lat")).doubleValue(), within(1e-5));
            Matcher w = Pattern.compile("41\\.75000, -70\\.41667 — (\\d+\\.\\d\\d) km at (\\d+)°, ETA (\\d{4}-\\d\\d-\\d\\d \\d\\d:\\d\\d:\\d\\d) UTC")
                    .matcher(card.get("waypoint"));
            assertThat(w.find()).as(card.get("waypoint")).isTrue();
            assertThat(Double.parseDouble(w.group(1))).isCloseTo(Forecast.distance(lat, lon, WPT_LAT, WPT_LON) / 1000, within(0.006));
            assertThat(Double.parseDouble(w.group(2))).isCloseTo(Forecast.bearing(lat, lon, WPT_LAT, WPT_LON), within(0.6));
            if (records.get(records.size() - 1) == last) {
                assertThat(o.get("wpt_eta_utc").toString().replace("T", " ")).startsWith(w.group(3));
            }
            // Five trend series charted, a value per call each; the map: a current arrow per surfacing, the waypoint.
            int shown = Integer.parseInt(card.get("records"));
            assertThat(card.get("series")).isEqualTo("5");
            assertThat(Integer.parseInt(card.get("battery_points"))).isEqualTo(shown);
            assertThat(Integer.parseInt(card.get("arrows"))).isEqualTo(shown);
            assertThat(card.get("waypoints")).isEqualTo("1");
            assertThat(Integer.parseInt(card.get("gps"))).isEqualTo(shown);
            LaunchedWeb.shot(b, "vehicle-surfacing-desktop");
            b.executeScript("document.getElementById('trends').scrollIntoView()");
            LaunchedWeb.shot(b, "vehicle-trends-desktop");
            PilotConsoleBrowserTest.viewport(b, 390, 844);
            Thread.sleep(300);
            PilotConsoleBrowserTest.noSidewaysScrolling(b);
            b.executeScript("document.getElementById('surfacing').scrollIntoView()");
            assertThat(attr(b, "#trends", "data-series")).isEqualTo("5");
            assertThat(attr(b, "#track", "data-waypoints")).isEqualTo("1");
            LaunchedWeb.shot(b, "vehicle-surfacing-phone");

            // The fleet: because, battery, the abort badge (beside the state, so a phone shows it), the next call, the map's layers.
            PilotConsoleBrowserTest.viewport(b, 1366, 768);
            b.get(sys.url("/fleet.html"));
            wait.until(x -> "true".equals(x.findElement(By.tagName("body")).getAttribute("data-ready")));
            String row = "tr[data-address='" + GLIDER1 + "']";
            wait.until(x -> !x.findElements(By.cssSelector(row + " .badge.abort")).isEmpty());
            assertThat(text(b, row + " .badge.abort")).isEqualTo("abort"); // the second call's, not new since
            assertThat(attr(b, row + " .badge.abort", "title")).startsWith("last abort: MS_ABORT_OVERDEPTH (dive_to: depth 1012.3");
            assertThat(text(b, row + " .badge.leak")).isEqualTo("leak");
            assertThat(attr(b, row + " .badge.leak", "title")).isEqualTo("leak detect 1.21 V");
            assertThat(text(b, row + " .because")).isIn("Surface interval [1]", "Abort [MS_ABORT_OVERDEPTH]");
            assertThat(text(b, row + " .battery")).matches("1\\d\\.\\d\\d V");
            assertThat(text(b, row + " .next-call")).matches("next (\\d{4}-\\d\\d-\\d\\d )?\\d\\d:\\d\\d:\\d\\d UTC \\((in|.* late).*\\)");
            assertThat(Integer.parseInt(attr(b, "#map", "data-arrows"))).isGreaterThanOrEqualTo(4);
            assertThat(attr(b, "#map", "data-waypoints")).isEqualTo("1");
            LaunchedWeb.shot(b, "fleet-surfacing-desktop");
            PilotConsoleBrowserTest.viewport(b, 390, 844);
            Thread.sleep(300);
            PilotConsoleBrowserTest.noSidewaysScrolling(b);
            assertThat(fresh(() -> b.findElement(By.cssSelector(row + " .badge.abort")).isDisplayed())).isTrue();
            assertThat(attr(b, "#map", "data-waypoints")).isEqualTo("1");
            LaunchedWeb.shot(b, "fleet-surfacing-phone");
        } finally {
            b.quit();
        }
    }

    @Test
    @Order(2)
    @SuppressWarnings("unchecked")
    void aRestartedServerKeepsTheLearnedIntervalAndTellsTheLateGliderOverdue() throws Exception {
        ChromeDriver b = sys.loggedIn("alice");
        long interval;
        try {
            Map<String, Object> o = (Map<String, Object>) surfacings(b, GLIDER1).get("outlook");
            assertThat(o.get("interval_from").toString()).startsWith("learned from");
            interval = ((Number) o.get("interval_s")).longValue();
        } finally {
            b.quit();
        }
        // The glider stops calling, and the server restarts before it is due (its interval plus 40 s).
        glider.destroy();
        glider.waitFor();
        sys.restartServer();
        ChromeDriver after = sys.loggedIn("alice");
        try {
            Map<String, Object> o = (Map<String, Object>) surfacings(after, GLIDER1).get("outlook");
            assertThat(o.get("interval_from").toString()).startsWith("learned from");
            assertThat(((Number) o.get("interval_s")).longValue()).isBetween(interval - 3, interval + 3);
            assertThat(o.get("next_call_utc")).isNotNull();
            WebDriverWait wait = new WebDriverWait(after, java.time.Duration.ofSeconds(120));
            wait.until(x -> history(after, GLIDER1).lines().anyMatch(l -> l.startsWith("OVERDUE no call for")));
            String overdue = history(after, GLIDER1).lines().filter(l -> l.startsWith("OVERDUE no call for")).findFirst().orElseThrow();
            assertThat(overdue).contains("(learned from its last").contains("+ 40 s grace");
            assertThat(sys.serverLog()).doesNotContain("their call intervals are learned afresh");
        } finally {
            after.quit();
        }
    }
}
