package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.Dimension;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.interactions.Actions;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.ripv.probe.FreePorts;

/**
 * The plan page (issue 36, item 2, as a table), as launched: the server, the SerialPortServer and
 * the simulated glider are processes from the jars, and a headless Chromium writes a goto list
 * (adds waypoints, types their positions, edits a b_arg), saves it and sees the server's
 * {@code FILE:LINE: reason} for a latitude over 90°, fixes it, sends it on the next call as
 * {@code goto_l10.ma}, queues a put, and watches both changes become "in effect" as the glider's
 * dialogs show them; loads the saved file back; asks for the forecast. Then on the map (item 2):
 * the list the glider runs is drawn from {@code ?plan current}; a waypoint dragged with the
 * pointer moves in the table too; saved, the version shows its diff against the version sent;
 * the history lists both versions; sent, the fleet's pending-changes page lists it until the
 * glider's dialog steers for the dragged waypoint. At phone size a drag moves a waypoint as well
 * and neither page scrolls sideways. The fleet's map draws the glider's goto list as it runs it, at
 * 1366×768 and 390×844, its labels apart. Screenshots, desktop and phone, go to
 * {@code target/web-screenshots/plan-*.png} and {@code changes-*.png} (and docs/images).
 */
@ResourceLock(Shared.BROWSER)
class PlanEditorBrowserTest {
    static final String PASSWORD = WebConsoleBrowserTest.PASSWORD;
    static final Duration T = Duration.ofSeconds(150);

    @TempDir
    static Path dir;
    static int http;
    static String glider;
    static Path shots;
    static LaunchedProcesses system;

    @BeforeAll
    static void startTheSystem() throws Exception {
        Chromium.assume();
        system = new LaunchedProcesses(dir, T);
        shots = Files.createDirectories(WebConsoleBrowserTest.root().resolve("ripv-it/target/web-screenshots"));
        Path data = Files.createDirectories(dir.resolve("server"));
        Process pw = system.launch("passwd", PASSWORD + "\n", "-jar", WebConsoleBrowserTest.jar("ripv-server").toString(), "passwd",
                "--permit", data.resolve("permit.txt").toString(), "alice", "--roles", "operators");
        assertThat(pw.waitFor()).as(system.log("passwd")).isZero();
        int port = FreePorts.one();
        int registry = FreePorts.one();
        int link = FreePorts.one();
        http = FreePorts.one();
        system.launch("server", null, "-jar", WebConsoleBrowserTest.jar("ripv-server").toString(), "server", "--data", data.toString(),
                "--port", String.valueOf(port), "--registry-port", String.valueOf(registry), "--http-port", String.valueOf(http),
                "--bind", "127.0.0.1");
        system.waitFor("the server's web console", () -> {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), http)) {
                return true;
            } catch (IOException e) {
                return false;
            }
        });
        system.launch("serial", null, "-Dripv.host=localhost", "-jar", WebConsoleBrowserTest.jar("ripv-services").toString(), "serial",
                "--server", "127.0.0.1:" + registry, "--secret-file", data.resolve("service.secret").toString(), "--link",
                "listen://127.0.0.1:" + link + ",name=glider1,to-vehicle=zmodem,alert=leak|LEAK", "--carrier", "ignore", "--no-enumerate");
        system.waitFor("the SerialPortServer's MailBoxes", () -> system.log("serial").contains("MailBoxes:"));
        glider = "<SerialPortServer>::<localhost>glider1";
        system.launch("simulator", null, "-jar", WebConsoleBrowserTest.jar("ripv-services").toString(), "simulator", "--call",
                "127.0.0.1:" + link, "--name", "glider1", "--dive-seconds", "2", "--surface-seconds", "10", "--dir",
                dir.resolve("glider").toString());
    }

    @AfterAll
    static void stopTheSystem() {
        if (system != null) {
            system.stopAll();
        }
    }

    private static String text(org.openqa.selenium.WebDriver b, String id) {
        return b.findElement(By.id(id)).getText();
    }

    private static void type(WebElement e, String value) {
        e.clear();
        e.sendKeys(value);
    }

    /** Drags proposed waypoint {@code n} on the map by (dx, dy) CSS pixels with the pointer, as a pilot's mouse or finger does. */
    private static void drag(ChromeDriver b, WebElement map, int n, int dx, int dy) {
        String dots = map.getAttribute("data-dots");
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\[" + n + ",(-?\\d+),(-?\\d+)\\]").matcher(dots);
        assertThat(m.find()).as("waypoint " + n + " on the map: " + dots).isTrue();
        int x = Integer.parseInt(m.group(1));
        int y = Integer.parseInt(m.group(2));
        // The whole path of the pointer must lie inside the viewport, or WebDriver refuses the move
        // (MoveTargetOutOfBounds): scroll so the dot sits in the middle of the window first. A map
        // merely scrolled into view can still leave the dot below the fold on a phone, or the page
        // can grow above it while a live update lands.
        b.executeScript("const r = arguments[0].getBoundingClientRect();"
                + " window.scrollBy(r.left + arguments[1] - innerWidth / 2, r.top + arguments[2] - innerHeight / 2)", map, x, y);
        org.openqa.selenium.Rectangle r = map.getRect();
        int cx = x - r.getWidth() / 2;
        int cy = y - r.getHeight() / 2;
        int dragged = Integer.parseInt(java.util.Objects.requireNonNullElse(map.getAttribute("data-dragged"), "0"));
        new Actions(b).moveToElement(map, cx, cy).clickAndHold().moveByOffset(dx / 2, dy / 2).moveByOffset(dx - dx / 2, dy - dy / 2)
                .release().perform();
        new WebDriverWait(b, Duration.ofSeconds(5)).until(d -> !String.valueOf(dragged).equals(map.getAttribute("data-dragged")));
    }

    /** The goto list the fleet map drew: each waypoint as {@code [name, n, lat, lon, x, y]} (its data-goto). */
    private static List<List<Object>> drawnGoto(org.openqa.selenium.WebDriver b) {
        try {
            String json = b.findElement(By.id("map")).getAttribute("data-goto");
            return json == null ? List.of() : new com.fasterxml.jackson.databind.ObjectMapper().readValue(json,
                    new com.fasterxml.jackson.core.type.TypeReference<List<List<Object>>>() {});
        } catch (com.fasterxml.jackson.core.JsonProcessingException | org.openqa.selenium.StaleElementReferenceException e) {
            return List.of();
        }
    }

    /** The glider's goto list on the fleet map: waypoint 0 as typed, waypoint 1 where it was dragged. */
    private static boolean showsTheDraggedList(List<List<Object>> drawn, double lat1, double lon1) {
        List<List<Object>> mine = drawn.stream().filter(w -> glider.equals(w.get(0))).toList();
        return mine.size() == 2 && near(mine.get(0), 0, 41.3, -70.6) && near(mine.get(1), 1, lat1, lon1);
    }

    private static boolean near(List<Object> w, int n, double lat, double lon) {
        return ((Number) w.get(1)).intValue() == n && Math.abs(((Number) w.get(2)).doubleValue() - lat) < 1e-4
                && Math.abs(((Number) w.get(3)).doubleValue() - lon) < 1e-4;
    }

    /** The fleet map's labels (its data-labels boxes, the legend and the scale among them) overlap nowhere. */
    private static void labelsApart(ChromeDriver b) throws Exception {
        List<List<Object>> boxes = new com.fasterxml.jackson.databind.ObjectMapper().readValue(
                b.findElement(By.id("map")).getAttribute("data-labels"), new com.fasterxml.jackson.core.type.TypeReference<>() {});
        assertThat(boxes).extracting(x -> String.valueOf(x.get(0))).contains("glider1", "0", "1", "legend", "scale");
        for (int i = 0; i < boxes.size(); i++) {
            for (int j = i + 1; j < boxes.size(); j++) {
                List<Object> p = boxes.get(i);
                List<Object> q = boxes.get(j);
                int[] a = {((Number) p.get(1)).intValue(), ((Number) p.get(2)).intValue(), ((Number) p.get(3)).intValue(), ((Number) p.get(4)).intValue()};
                int[] c = {((Number) q.get(1)).intValue(), ((Number) q.get(2)).intValue(), ((Number) q.get(3)).intValue(), ((Number) q.get(4)).intValue()};
                boolean overlap = a[0] < c[0] + c[2] - 1 && c[0] < a[0] + a[2] - 1 && a[1] < c[1] + c[3] - 1 && c[1] < a[1] + a[3] - 1;
                assertThat(overlap).as("label %s over label %s", p, q).isFalse();
            }
        }
    }

    private void fleetGotoList(ChromeDriver b, WebDriverWait wait, double lat1, double lon1) throws Exception {
        PilotConsoleBrowserTest.viewport(b, 1366, 768);
        try {
            b.get("https://127.0.0.1:" + http + "/fleet.html");
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            wait.withMessage(() -> "the fleet map's goto lists: " + drawnGoto(b)).until(d -> showsTheDraggedList(drawnGoto(d), lat1, lon1));
            WebElement map = b.findElement(By.id("map"));
            for (List<Object> w : drawnGoto(b)) { // drawn inside the map
                assertThat(((Number) w.get(4)).intValue()).isBetween(0, map.getRect().getWidth());
                assertThat(((Number) w.get(5)).intValue()).isBetween(0, map.getRect().getHeight());
            }
            assertThat(map.getAttribute("data-legend")).isEqualTo("GPS, dead-reckoned, goto list");
            labelsApart(b);
            b.executeScript("arguments[0].scrollIntoView({block: 'center'})", map);
            Files.write(shots.resolve("fleet-goto-desktop.png"), b.getScreenshotAs(OutputType.BYTES));
            PilotConsoleBrowserTest.viewport(b, 390, 844);
            // drawn again at the phone's width
            wait.until(d -> d.findElement(By.id("map")).getRect().getWidth() < 390 && showsTheDraggedList(drawnGoto(d), lat1, lon1)
                    && drawnGoto(d).stream().allMatch(w -> ((Number) w.get(4)).intValue() < 390));
            PilotConsoleBrowserTest.noSidewaysScrolling(b);
            labelsApart(b);
            b.executeScript("arguments[0].scrollIntoView({block: 'center'})", b.findElement(By.id("map")));
            Files.write(shots.resolve("fleet-goto-phone.png"), b.getScreenshotAs(OutputType.BYTES));
        } finally {
            b.executeCdpCommand("Emulation.clearDeviceMetricsOverride", java.util.Map.of());
        }
    }

    @Test
    void aGotoListIsWrittenCheckedSentAndFollowedUntilTheGliderShowsIt() throws Exception {
        ChromeDriver b = Chromium.start(Files.createDirectories(dir.resolve("plan-browser")));
        try {
            WebDriverWait wait = new WebDriverWait(b, T);
            b.get("https://127.0.0.1:" + http + "/");
            b.findElement(By.id("user")).sendKeys("alice");
            b.findElement(By.id("password")).sendKeys(PASSWORD);
            b.findElement(By.xpath("//button[text()='Log in']")).click();
            wait.until(d -> d.getCurrentUrl().endsWith("/fleet.html"));
            b.get("https://127.0.0.1:" + http + "/queue.html?m=" + java.net.URLEncoder.encode(glider, StandardCharsets.UTF_8));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            b.findElement(By.linkText("Plan")).click();
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.getCurrentUrl()).contains("/plan.html?m=");

            // Two waypoints typed in the table; the first with a latitude over 90°.
            b.findElement(By.id("add-wpt")).click();
            b.findElement(By.id("add-wpt")).click();
            b.findElement(By.id("add-wpt")).click();
            List<WebElement> rows = b.findElements(By.cssSelector("#wpts tbody tr"));
            assertThat(rows).hasSize(3);
            rows.get(2).findElement(By.xpath(".//button[text()='Remove']")).click();
            rows = b.findElements(By.cssSelector("#wpts tbody tr"));
            assertThat(rows).hasSize(2);
            type(rows.get(0).findElement(By.className("lat")), "95.2");
            type(rows.get(0).findElement(By.className("lon")), "-70.6");
            type(rows.get(0).findElement(By.className("comment")), "west corner");
            type(rows.get(1).findElement(By.className("lat")), "41.31");
            type(rows.get(1).findElement(By.className("lon")), "-70.55");
            WebElement initial = b.findElement(By.cssSelector("#bargs tr[data-name='initial_wpt'] .value"));
            type(initial, "1");
            b.findElement(By.id("save")).click();
            wait.until(d -> !d.findElement(By.id("problems")).getText().isEmpty());
            assertThat(text(b, "problems")).contains("goto_l11.ma:").contains("latitude '9512.0000' is 95.20000°, over 90°");
            assertThat(text(b, "save-status")).startsWith("Error: goto_l11.ma was saved but does not pass the check");
            assertThat(b.findElement(By.id("send")).isEnabled()).isFalse();
            assertThat(b.findElement(By.cssSelector("#bargs tr[data-name='num_waypoints'] .value")).getAttribute("value")).isEqualTo("2");
            b.executeScript("document.getElementById('problems').scrollIntoView({block: 'center'})");
            Files.write(shots.resolve("plan-refused-desktop.png"), b.getScreenshotAs(OutputType.BYTES));

            type(rows.get(0).findElement(By.className("lat")), "41.3");
            b.findElement(By.id("save")).click();
            wait.until(d -> text(d, "save-status").startsWith("saved and checked: goto_l11(1).ma: goto_list, 2 waypoint(s)"));
            assertThat(b.findElement(By.id("problems")).isDisplayed()).isFalse();
            b.findElement(By.id("send")).click();
            wait.until(d -> text(d, "send-status").startsWith("change 1: "));
            type(b.findElement(By.id("set-value")), "40");
            b.findElement(By.id("set")).click();
            wait.until(d -> text(d, "set-status").contains("change 2: 'put c_dive_target_depth 40' queued"));

            // The glider's next call takes both; the call after shows them: the page follows the events.
            wait.withMessage(() -> "changes: " + text(b, "changes")).until(d ->
                    !d.findElements(By.cssSelector("#changes li[data-id='1'][data-state='in effect']")).isEmpty()
                            && !d.findElements(By.cssSelector("#changes li[data-id='2'][data-state='in effect']")).isEmpty());
            assertThat(text(b, "changes")).contains("c_wpt_lat/lon 41.31000, -70.55000 is waypoint 1")
                    .contains("sensor:c_dive_target_depth=40");
            assertThat(Files.readString(dir.resolve("glider/goto_l10.ma"))).contains("-7036.0000\t4118.0000 # west corner");

            b.findElement(By.id("forecast")).click();
            wait.until(d -> d.findElement(By.id("forecast-text")).isDisplayed());
            assertThat(text(b, "forecast-text")).startsWith("forecast of goto_l11(1).ma for " + glider);

            // The map: what the glider runs (the file in effect, the waypoint its dialog heads for) beside the proposed list.
            wait.withMessage(() -> "on the glider: " + text(b, "current-status")).until(d -> text(d, "current-status")
                    .contains("heading for 41.31000, -70.55000") && text(d, "current-status").contains("goto list: goto_l10.ma, change 1, in effect since"));
            WebElement map = b.findElement(By.id("plan-map"));
            assertThat(map.getAttribute("data-waypoints")).isEqualTo("2");
            // drag waypoint 1 (the one the glider heads for) 60 px right and 40 px down
            drag(b, map, 1, 60, 40);
            rows = b.findElements(By.cssSelector("#wpts tbody tr"));
            String movedLat = rows.get(1).findElement(By.className("lat")).getAttribute("value");
            String movedLon = rows.get(1).findElement(By.className("lon")).getAttribute("value");
            assertThat(Double.parseDouble(movedLat)).isLessThan(41.31);
            assertThat(Double.parseDouble(movedLon)).isGreaterThan(-70.55);
            assertThat(rows.get(0).findElement(By.className("lat")).getAttribute("value")).isEqualTo("41.3"); // as typed, untouched
            b.findElement(By.id("save")).click();
            wait.until(d -> text(d, "save-status").startsWith("saved and checked: goto_l11(2).ma: goto_list, 2 waypoint(s)"));
            assertThat(text(b, "save-status")).contains("version 2 of goto_l11.ma");
            assertThat(text(b, "diff")).startsWith("diff against version 1, the last sent (as goto_l10.ma, change 1,")
                    .containsPattern("\n- -7033\\.0000\\s+4118\\.6000\n"); // the waypoint as sent, out (getText shows the tab as a blank)
            assertThat(b.findElements(By.cssSelector("#diff .add"))).isNotEmpty();
            assertThat(b.findElements(By.cssSelector("#diff .del"))).isNotEmpty();
            b.findElement(By.id("history")).click();
            wait.until(d -> d.findElements(By.cssSelector("#versions li")).size() == 2);
            assertThat(b.findElement(By.cssSelector("#versions li[data-version='1']")).getAttribute("data-sent")).isEqualTo("true");
            assertThat(b.findElement(By.cssSelector("#versions li[data-version='2']")).getAttribute("data-sent")).isEqualTo("false");
            assertThat(text(b, "versions")).contains("by alice");
            b.executeScript("document.getElementById('plan-map').scrollIntoView({block: 'start'})");
            Files.write(shots.resolve("plan-map-desktop.png"), b.getScreenshotAs(OutputType.BYTES));
            b.findElement(By.id("send")).click();
            wait.until(d -> text(d, "send-status").startsWith("change 3: "));
            wait.until(d -> !d.findElements(By.cssSelector("#versions li[data-version='2'][data-sent='true']")).isEmpty());

            // The fleet's pending changes: change 3, with its state and age, linked to the plan page.
            b.findElement(By.linkText("Changes")).click();
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            WebElement pending = b.findElement(By.cssSelector("section.vehicle-changes tr[data-id='3']"));
            assertThat(pending.getAttribute("data-state")).isIn("queued", "sent", "received");
            assertThat(pending.getText()).contains("goto_l10.ma (from goto_l11(2).ma)").contains("ago").contains("alice");
            assertThat(b.findElement(By.cssSelector("section.vehicle-changes h3 a")).getAttribute("href")).contains("/plan.html?m=");
            assertThat(b.findElements(By.cssSelector("section.vehicle-changes tr[data-id='1']"))).isEmpty(); // settled: not pending
            Files.write(shots.resolve("changes-desktop.png"), b.getScreenshotAs(OutputType.BYTES));
            // it follows the change's events: received, then gone when in effect
            wait.withMessage(() -> "pending: " + text(b, "vehicles")).until(d ->
                    d.findElements(By.cssSelector("section.vehicle-changes tr[data-id='3']")).isEmpty());
            assertThat(text(b, "status")).startsWith("0 pending change(s)");
            // the vehicle's own map draws the goto list it runs too
            b.get("https://127.0.0.1:" + http + "/vehicle.html?m=" + java.net.URLEncoder.encode(glider, StandardCharsets.UTF_8));
            wait.withMessage(() -> "the vehicle's track map: " + b.findElement(By.id("track")).getAttribute("data-plan-waypoints"))
                    .until(d -> "2".equals(d.findElement(By.id("track")).getAttribute("data-plan-waypoints")));
            // The fleet's map draws the goto list each glider runs as well (the same ?plan current, PlanModel and
            // gliderLayer): the dragged list, once in effect, at a desk's size and a phone's, with its legend entry
            // and no label over another.
            fleetGotoList(b, wait, Double.parseDouble(movedLat), Double.parseDouble(movedLon));
            b.get("https://127.0.0.1:" + http + "/plan.html?m=" + java.net.URLEncoder.encode(glider, StandardCharsets.UTF_8));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            wait.withMessage(() -> "changes: " + text(b, "changes")).until(d ->
                    !d.findElements(By.cssSelector("#changes li[data-id='3'][data-state='in effect']")).isEmpty());
            assertThat(text(b, "changes")).contains(String.format(java.util.Locale.ROOT, "c_wpt_lat/lon %.5f, %.5f is waypoint 1",
                    Double.parseDouble(movedLat), Double.parseDouble(movedLon)));

            // The saved file loads back into the table.
            b.findElement(By.id("add-wpt")).click();
            type(b.findElement(By.id("plan-file")), "goto_l11(1).ma");
            b.findElement(By.id("load")).click();
            wait.until(d -> text(d, "load-status").startsWith("from the upload store"));
            rows = b.findElements(By.cssSelector("#wpts tbody tr"));
            assertThat(rows).hasSize(2);
            assertThat(rows.get(1).findElement(By.className("lat")).getAttribute("value")).isEqualTo("41.31000");
            assertThat(b.findElement(By.cssSelector("#bargs tr[data-name='initial_wpt'] .value")).getAttribute("value")).isEqualTo("1");

            b.executeScript("document.getElementById('changes').scrollIntoView({block: 'center'})");
            Files.write(shots.resolve("plan-desktop.png"), b.getScreenshotAs(OutputType.BYTES));
            b.manage().window().setSize(new Dimension(390, 844));
            assertThat((Long) b.executeScript("return document.documentElement.scrollWidth - document.documentElement.clientWidth"))
                    .as(() -> "no sideways scrolling on a phone; too wide: " + b.executeScript("return [...document.querySelectorAll('body *')]"
                            + ".filter(e => e.getBoundingClientRect().right > document.documentElement.clientWidth || e.scrollWidth > e.clientWidth + 1 && getComputedStyle(e).overflowX === 'visible')"
                            + ".map(e => e.tagName + '#' + e.id + '.' + e.className + ' ' + Math.round(e.getBoundingClientRect().right) + '/' + e.scrollWidth).join(', ') + ' scrollWidth ' + document.documentElement.scrollWidth + ' clientWidth ' + document.documentElement.clientWidth"))
                    .isLessThanOrEqualTo(0L);
            b.executeScript("document.getElementById('wpts').scrollIntoView({block: 'start'})");
            Files.write(shots.resolve("plan-phone.png"), b.getScreenshotAs(OutputType.BYTES));
            // a drag at phone size moves waypoint 0, and the table follows
            map = b.findElement(By.id("plan-map"));
            b.executeScript("arguments[0].scrollIntoView({block: 'start'})", map);
            wait.until(d -> d.findElement(By.id("plan-map")).getAttribute("data-dots").contains("[0,"));
            String before = b.findElements(By.cssSelector("#wpts tbody tr")).get(0).findElement(By.className("lon")).getAttribute("value");
            drag(b, map, 0, -30, 20);
            String after = b.findElements(By.cssSelector("#wpts tbody tr")).get(0).findElement(By.className("lon")).getAttribute("value");
            assertThat(Double.parseDouble(after)).isLessThan(Double.parseDouble(before));
            Files.write(shots.resolve("plan-map-phone.png"), b.getScreenshotAs(OutputType.BYTES));
            b.get("https://127.0.0.1:" + http + "/changes.html");
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat((Long) b.executeScript("return document.documentElement.scrollWidth - document.documentElement.clientWidth"))
                    .as("the changes page does not scroll sideways on a phone").isLessThanOrEqualTo(0L);
            Files.write(shots.resolve("changes-phone.png"), b.getScreenshotAs(OutputType.BYTES));
        } finally {
            b.quit();
        }
    }
}
