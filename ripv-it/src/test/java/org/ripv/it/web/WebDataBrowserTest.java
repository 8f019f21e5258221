package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.Dimension;
import org.openqa.selenium.Keys;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.interactions.Actions;
import org.openqa.selenium.support.ui.Select;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The data page and the generic service page as launched (issue 21 items 5 and 7): the server, the
 * DatabaseServer, the DataVisServer and the example ClockService are processes from the jars; a
 * real headless Chromium sends the ClockService a command on a page that knows nothing of it,
 * ingests a Slocum file through the same page, sees its positions in the data page's view and
 * draws {@code vis:track} as a chart whose CSV is the positions; a user whose permit rules allow
 * only the views gets no SQL box, and the server refuses their SQL when the page is bypassed. With
 * {@code --map-tiles} the fleet's map is Leaflet (from the WebJar) asking the given tile host, and draws
 * the call records' layers and a goto list there (its numbers apart, with a legend).
 */
@ResourceLock(Shared.BROWSER)
class WebDataBrowserTest {
    static final String DB = "<DatabaseServer>::<localhost>TTY1";
    static final String TRACKED = "unit_363";
    /** A tile server that is not there: the map must still be Leaflet's, asking that host and no other. */
    static final String TILES = "https://127.0.0.1:9/tiles/{z}/{x}/{y}.png";

    @TempDir
    static Path dir;
    static LaunchedWeb sys;

    @BeforeAll
    static void start() throws Exception {
        Chromium.assume();
        sys = new LaunchedWeb(dir, List.of("alice:operators", "vera:db-views"), List.of(
                // docs/web.md's view-only user: the DatabaseServer lets a db-views user read the views only (issue 33 item 6)
                "allow @db-views DatabaseServer * SELECT *"), "--map-tiles", TILES);
        sys.service("database", "--data", dir.resolve("database").toString());
        sys.service("datavis", "--workdir", dir.resolve("datavis").toString());
        sys.service("clock");
        Path downloads = Files.createDirectories(sys.data.resolve("download"));
        Files.copy(Path.of(WebConsoleBrowserTest.root().toString(), "ripv-services/src/test/resources/slocum/unit_363_2013_245_6_6.mrg"),
                downloads.resolve("unit_363_2013_245_6_6.mrg"));
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    static String text(ChromeDriver b, String id) {
        return b.findElement(By.id(id)).getText();
    }

    static void send(ChromeDriver b, String service, String command) {
        new Select(b.findElement(By.id("service"))).selectByValue("<" + service + ">::<localhost>");
        b.findElement(By.id("command")).sendKeys(command, Keys.ENTER);
    }

    @Test
    void anOperatorUsesTheClockOnTheGenericPageIngestsAndChartsTheTrack() throws Exception {
        ChromeDriver b = sys.loggedIn("alice");
        try {
            WebDriverWait wait = new WebDriverWait(b, WebConsoleBrowserTest.T);
            b.get(sys.url("/service.html?s=ClockService"));
            wait.until(d -> d.findElements(By.cssSelector("#mailboxes tr[data-address]")).size() == 1);
            assertThat(text(b, "mailboxes")).contains("TTY1").contains("ready");
            send(b, "ClockService", "time");
            wait.until(d -> text(b, "replies").matches("(?s).*TTY1> time\\s+\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d.*"));
            send(b, "ClockService", "nonsense");
            wait.until(d -> text(b, "replies").contains("ClockService knows time, echo TEXT and sleep MILLIS, not 'nonsense'"));
            LaunchedWeb.shot(b, "service-desktop");

            // The same page talks to the DatabaseServer: the ingest is an ordinary command.
            send(b, "DatabaseServer", "ingest unit_363_2013_245_6_6.mrg");
            wait.until(d -> text(b, "replies").contains("positions"));
            assertThat(text(b, "replies").substring(text(b, "replies").indexOf("> ingest"))).doesNotContain("Error");

            b.get(sys.url("/data.html"));
            wait.until(d -> text(b, "table-state").matches("\\d+ rows.*"));
            int positions = b.findElements(By.cssSelector("#table tbody tr")).size();
            assertThat(positions).isGreaterThan(10);
            assertThat(text(b, "table")).contains(TRACKED).contains("gps");
            assertThat(b.findElement(By.id("sql-form")).isDisplayed()).as("an operator may send any SQL").isTrue();
            b.findElement(By.id("sql")).sendKeys("SELECT COUNT(*) AS n FROM positions WHERE vehicle = '" + TRACKED + "'", Keys.ENTER);
            wait.until(d -> text(b, "table-state").startsWith("1 row"));
            assertThat(b.findElement(By.cssSelector("#table tbody td")).getText()).isEqualTo(String.valueOf(positions));
            // A result in several pages (issue 38): the page joins them, and draws every row.
            b.findElement(By.id("sql")).clear();
            b.findElement(By.id("sql")).sendKeys("SELECT a.time_utc, b.lat FROM positions a, positions b, positions c"
                    + " FETCH FIRST 1200 ROWS ONLY", Keys.ENTER);
            wait.until(d -> text(b, "table-state").startsWith("1200 rows"));
            assertThat(b.findElements(By.cssSelector("#table tbody tr"))).hasSize(1200);

            new Select(b.findElement(By.id("plot"))).selectByValue("track");
            assertThat(b.findElement(By.id("vehicle")).getAttribute("value")).isEqualTo(TRACKED);
            b.findElement(By.id("draw")).click();
            wait.until(d -> "TRACK".equals(d.findElement(By.id("chart")).getAttribute("data-kind")));
            assertThat(b.findElement(By.id("chart")).getAttribute("data-points")).isEqualTo(String.valueOf(positions));
            WebElement plot = b.findElement(By.cssSelector("#chart .u-over"));
            new Actions(b).moveToElement(plot, 10, 10).perform();
            wait.until(d -> text(b, "readout").startsWith("pointer "));

            assertThat(b.findElement(By.id("chart-csv")).getAttribute("download")).isEqualTo("track-" + TRACKED + ".csv");
            b.findElement(By.id("chart-csv")).click();
            Path csvFile = sys.downloads("alice").resolve("track-" + TRACKED + ".csv");
            sys.waitFor("the CSV download", () -> Files.exists(csvFile));
            List<String> lines = Files.readAllLines(csvFile);
            assertThat(lines.get(0)).startsWith("series,").containsIgnoringCase("longitude");
            assertThat(lines).hasSize(positions + 1);
            assertThat(lines.subList(1, lines.size())).allMatch(l -> l.matches("[^,]+,-?\\d+(\\.\\d+)?([eE]-?\\d+)?,-?\\d+(\\.\\d+)?([eE]-?\\d+)?"));
            b.findElement(By.id("chart-png")).click();
            Path pngFile = sys.downloads("alice").resolve("track-" + TRACKED + ".png");
            sys.waitFor("the PNG download", () -> Files.exists(pngFile));
            byte[] png = Files.readAllBytes(pngFile);
            assertThat(java.util.Arrays.copyOf(png, 4)).containsExactly(0x89, 'P', 'N', 'G');
            b.executeScript("document.getElementById('chart').scrollIntoView()");
            LaunchedWeb.shot(b, "data-desktop");
            b.manage().window().setSize(new Dimension(390, 844));
            assertThat((Long) b.executeScript("return document.documentElement.scrollWidth - document.documentElement.clientWidth"))
                    .as("no sideways scrolling on a phone").isLessThanOrEqualTo(0L);
            b.findElement(By.id("draw")).click(); // drawn again at the phone's width
            wait.until(d -> text(b, "chart-state").startsWith("plotted"));
            LaunchedWeb.shot(b, "data-phone");
        } finally {
            b.quit();
        }
    }

    @Test
    void withMapTilesTheFleetMapIsLeafletOnThoseTiles() throws Exception {
        ChromeDriver b = sys.loggedIn("alice");
        try {
            WebDriverWait wait = new WebDriverWait(b, WebConsoleBrowserTest.T);
            wait.until(d -> !d.findElements(By.cssSelector("#map.leaflet-container img.leaflet-tile")).isEmpty());
            assertThat(b.findElements(By.cssSelector("#map.leaflet-container img.leaflet-tile")))
                    .allMatch(img -> img.getAttribute("src").startsWith("https://127.0.0.1:9/tiles/"));
            assertThat(b.findElement(By.cssSelector(".leaflet-control-attribution")).getText()).contains("127.0.0.1:9");
            // The call records' layers on tiles: a vehicle as the fleet page hands it over, with two surfacings'
            // currents (one too weak to draw) and its waypoint, drawn by the page's own module on a second map.
            Object drawn = b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                    + "import('/tilemap.js').then((m) => { const c = document.createElement('canvas'); c.id = 'tile-test';"
                    + " document.body.append(c); const draw = m.tileMap(c, arguments[0]);"
                    + " const fixes = [{ lat: 41.60, lon: -70.60, t: 1, gps: true, current_e: 0.11, current_n: -0.05 },"
                    + "  { lat: 41.65, lon: -70.55, t: 2, gps: true, current_e: 0, current_n: 0 }];"
                    + " draw([{ name: 'ru29', track: fixes, currents: fixes,"
                    + "  waypoint: { from: fixes[1], to: { lat: 41.75, lon: -70.41 }, words: '12.2 km 038°' } }]);"
                    + " const d = document.getElementById('tile-test');"
                    + " done(d.dataset.points + ' ' + d.dataset.arrows + ' ' + d.dataset.waypoints + ' '"
                    + "  + d.querySelectorAll('path.leaflet-interactive').length); });", TILES);
            assertThat(String.valueOf(drawn)).as("points arrows waypoints paths").startsWith("2 1 1 ");
            // The goto list a glider runs on tiles (what the fleet page hands over from ?plan current): numbered squares on
            // a dashed line, a legend entry, and of two waypoints a few metres apart one number hidden, not drawn over the other.
            Object gotoList = b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                    + "import('/tilemap.js').then((m) => { const c = document.createElement('canvas'); c.id = 'goto-test';"
                    + " document.body.append(c); const draw = m.tileMap(c, arguments[0]);"
                    + " const fixes = [{ lat: 41.60, lon: -70.60, t: 1, gps: true }, { lat: 41.65, lon: -70.55, t: 2, gps: false }];"
                    + " const goto = { waypoints: [{ n: 0, lat: 41.70, lon: -70.50 }, { n: 1, lat: 41.75, lon: -70.41 },"
                    + "  { n: 2, lat: 41.7501, lon: -70.4101 }], heading: { lat: 41.75, lon: -70.41 } };"
                    + " const d = document.getElementById('goto-test'); d.style.height = '450px';" // the fleet's CSS sizes only #map
                    + " window.dispatchEvent(new Event('resize'));" // Leaflet measures its box again
                    + " setTimeout(() => draw([{ name: 'ru29', track: fixes, goto }]), 200);"
                    + " setTimeout(() => {" // after the fit's zoom and move
                    + "  done([d.dataset.goto, d.dataset.labels, d.querySelector('.map-legend').textContent,"
                    + "   d.querySelectorAll('.goto-icon').length, d.querySelectorAll('.leaflet-tooltip.goto-label.covered').length,"
                    + "   d.querySelectorAll('.leaflet-tooltip.goto-label:not(.covered)').length]); }, 1500); });", TILES);
            List<?> g = (List<?>) gotoList;
            assertThat(String.valueOf(g.get(0))).isEqualTo("[[\"ru29\",0,41.7,-70.5],[\"ru29\",1,41.75,-70.41],[\"ru29\",2,41.7501,-70.4101]]");
            assertThat(String.valueOf(g.get(2))).contains("GPS").contains("dead-reckoned").contains("goto list");
            assertThat(((Number) g.get(3)).intValue()).as("squares").isEqualTo(3);
            assertThat(((Number) g.get(4)).intValue()).as("numbers hidden under another").isEqualTo(1);
            assertThat(((Number) g.get(5)).intValue()).as("numbers shown").isEqualTo(2);
            List<List<Number>> shown = new com.fasterxml.jackson.databind.ObjectMapper().readValue(String.valueOf(g.get(1)),
                    new com.fasterxml.jackson.core.type.TypeReference<>() {});
            assertThat(shown).hasSize(3); // the vehicle's name and two numbers
            for (int i = 0; i < shown.size(); i++) {
                for (int j = i + 1; j < shown.size(); j++) {
                    List<Number> p = shown.get(i);
                    List<Number> q = shown.get(j);
                    assertThat(p.get(0).intValue() < q.get(0).intValue() + q.get(2).intValue() && q.get(0).intValue() < p.get(0).intValue() + p.get(2).intValue()
                            && p.get(1).intValue() < q.get(1).intValue() + q.get(3).intValue() && q.get(1).intValue() < p.get(1).intValue() + p.get(3).intValue())
                            .as("label %s over label %s", p, q).isFalse();
                }
            }
        } finally {
            b.quit();
        }
    }

    @Test
    void aUserWithoutTheRightGetsNoSqlBoxAndTheServerRefusesTheirSql() throws Exception {
        ChromeDriver b = sys.loggedIn("vera");
        try {
            WebDriverWait wait = new WebDriverWait(b, WebConsoleBrowserTest.T);
            b.get(sys.url("/data.html"));
            wait.until(d -> !text(b, "table-state").isEmpty() && !text(b, "table-state").equals("Running…"));
            // The views are what the permit file lets vera send (rows, or no table yet before the ingest).
            assertThat(text(b, "table-state")).doesNotContain("FORBIDDEN");
            b.findElement(By.id("view-dives")).click();
            wait.until(d -> !text(b, "table-state").equals("Running…"));
            assertThat(text(b, "table-state")).doesNotContain("FORBIDDEN");
            assertThat(b.findElement(By.id("sql-form")).isDisplayed()).as("no SQL box without the right").isFalse();
            // Past the page: the server refuses the SQL anyway.
            Object reply = b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                    + "import('/postoffice.js').then(async (m) => { const s = await m.session(); const po = new m.PostOffice(s.csrf);"
                    + " const r = await po.send(arguments[0], 'SELECT * FROM vehicle'); done(r.status + ' ' + r.error + ' ' + r.text); });", DB);
            assertThat(String.valueOf(reply)).startsWith("ERROR FORBIDDEN").contains("db-views").contains("SELECT * FROM vehicle");
        } finally {
            b.quit();
        }
    }
}
