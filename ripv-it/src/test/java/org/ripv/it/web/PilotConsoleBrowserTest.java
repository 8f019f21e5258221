package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;

import java.net.URLEncoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.Keys;
import org.openqa.selenium.StaleElementReferenceException;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.ripv.probe.FreePorts;

/**
 * A pilot's console, round two (issue 32), as launched: the server, a SerialPortServer with two
 * listening links, the DatabaseServer and two simulated gliders from the jars, and headless
 * Chromium. glider1 speaks GliderDOS (the surface dialog, the keys and its countdown); glider2 is a
 * PicoDOS glider on a 2400-baud call with a 64 KB file, so a transfer runs long enough to cancel.
 * <ul>
 * <li>the vehicle page's badge follows the call, "dives in N s" counts down the dialog's countdown,
 *     the key buttons are the link's keys, Ctrl-C takes the glider to GliderDOS and stops the count;
 * <li>Esc cancels the command the page started (not the one before it), and a command's output
 *     is shown once;
 * <li>the Files page's Cancel stops the transfer it started, and nothing is stored;
 * <li>the fleet map draws the whole track: the transcript's GPS fixes and the database's
 *     positions, dead-reckoned ones told apart, with a scale bar;
 * <li>the controls follow the permit rules, not the role's name.
 * </ul>
 */
@ResourceLock(Shared.BROWSER)
class PilotConsoleBrowserTest {
    static final String GLIDER1 = "<SerialPortServer>::<localhost>glider1";
    static final String GLIDER2 = "<SerialPortServer>::<localhost>glider2";
    static final String DB = "<DatabaseServer>::<localhost>TTY1";

    @TempDir
    static Path dir;
    static LaunchedWeb sys;

    @BeforeAll
    static void start() throws Exception {
        Chromium.assume();
        sys = new LaunchedWeb(dir, List.of("alice:operators", "olga:observers", "vic:visitors", "pia:pilots"), List.of(
                // Roles named nothing like 'observers': their rules alone decide what their pages offer.
                "allow @visitors * * ?read",
                "allow @visitors DatabaseServer * *",
                "allow @pilots * * ?read",
                "allow @pilots SerialPortServer * ?key ctrl-c"));
        sys.service("database", "--data", dir.resolve("database").toString());
        Path downloads = Files.createDirectories(sys.data.resolve("download"));
        Files.copy(WebConsoleBrowserTest.root().resolve("ripv-services/src/test/resources/slocum/unit_363_2013_245_6_6.mrg"),
                downloads.resolve("unit_363_2013_245_6_6.mrg"));
        int link1 = FreePorts.one();
        int link2 = FreePorts.one();
        sys.launch("serial", null, "-Dripv.host=localhost", "-jar", LaunchedWeb.jar("ripv-services"), "serial", "--server",
                "127.0.0.1:" + sys.registry, "--secret-file", sys.data.resolve("service.secret").toString(), "--carrier", "ignore",
                "--no-enumerate", "--work", dir.resolve("work").toString(),
                "--link", "listen://127.0.0.1:" + link1 + ",name=glider1,prompt-regex=GliderDOS[^>]*>|C:\\\\>,line-ending=cr",
                "--link", "listen://127.0.0.1:" + link2 + ",name=glider2");
        sys.waitFor("the SerialPortServer's MailBoxes", () -> sys.log("serial").contains("MailBoxes:"));
        sys.launch("glider1", null, "-jar", LaunchedWeb.jar("ripv-services"), "simulator", "--call", "127.0.0.1:" + link1, "--name",
                "glider1", "--dialog", "gliderdos", "--surface-seconds", "45", "--dive-seconds", "4", "--dir",
                dir.resolve("glider1").toString());
        Path g2 = Files.createDirectories(dir.resolve("glider2"));
        byte[] big = new byte[64 * 1024];
        new Random(32).nextBytes(big);
        Files.write(g2.resolve("BIG.DAT"), big);
        Files.writeString(g2.resolve("SMALL.TXT"), "a small file from glider2\n".repeat(4));
        sys.launch("glider2", null, "-jar", LaunchedWeb.jar("ripv-services"), "simulator", "--call", "127.0.0.1:" + link2, "--name",
                "glider2", "--dive-seconds", "4", "--surface-seconds", "600", "--baud", "2400", "--dir", g2.toString());
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    static String text(WebDriver b, String id) {
        return b.findElement(By.id(id)).getText();
    }

    static String page(String name, String mailbox) {
        return sys.url("/" + name + "?m=" + URLEncoder.encode(mailbox, StandardCharsets.UTF_8));
    }

    static WebDriverWait waiting(WebDriver b) {
        WebDriverWait w = new WebDriverWait(b, WebConsoleBrowserTest.T);
        w.ignoring(StaleElementReferenceException.class);
        return w;
    }

    static List<String> keyButtons(WebDriver b) {
        return b.findElements(By.cssSelector("#keys button")).stream().map(WebElement::getText).toList();
    }

    /** The MailBox's call state as the server has it (?status), asked from the page's own Post Office. */
    static String state(ChromeDriver b, String mailbox) {
        return String.valueOf(b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                + "import('/postoffice.js').then(async (m) => { const s = await m.session(); const po = new m.PostOffice(s.csrf);"
                + " const r = await po.send('', '?status ' + arguments[0]); done(r.result?.session?.state ?? 'none'); });", mailbox));
    }

    /** The page's viewport exactly (a phone's as a phone has it), for the check and the screenshots. */
    static void viewport(ChromeDriver b, int width, int height) {
        b.executeCdpCommand("Emulation.setDeviceMetricsOverride", java.util.Map.of("width", width, "height", height,
                "deviceScaleFactor", 1, "mobile", width < 600));
    }

    static void noSidewaysScrolling(ChromeDriver b) {
        assertThat((Long) b.executeScript("return document.documentElement.scrollWidth - document.documentElement.clientWidth"))
                .as("no sideways scrolling on a phone").isLessThanOrEqualTo(0L);
    }

    @Test
    void aPilotSeesTheCallAndItsCountdownPressesCtrlCCancelsWhatTheyStartedAndSeesOutputOnce() throws Exception {
        ChromeDriver b = sys.loggedIn("alice");
        try {
            WebDriverWait wait = waiting(b);
            b.get(page("vehicle.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            // The next surfacing (the first may be under way already): on call, and the dialog's countdown as "dives in N s".
            wait.until(d -> text(d, "badge").equals("on call") && d.findElement(By.id("dives-in")).isDisplayed());
            Matcher m = Pattern.compile("dives in (\\d+) s").matcher(text(b, "dives-in"));
            assertThat(m.matches()).as(text(b, "dives-in")).isTrue();
            int first = Integer.parseInt(m.group(1));
            assertThat(first).isBetween(0, 45);
            wait.until(d -> !text(d, "dives-in").equals("dives in " + first + " s")); // it counts down, live
            assertThat(keyButtons(b)).as("the link's keys").containsExactly("Ctrl-C", "Ctrl-R", "Ctrl-E", "Ctrl-F");
            viewport(b, 1366, 768);
            LaunchedWeb.shot(b, "vehicle-countdown-desktop");
            viewport(b, 390, 844);
            noSidewaysScrolling(b);
            LaunchedWeb.shot(b, "vehicle-countdown-phone");
            viewport(b, 1366, 768);

            // Ctrl-C takes the glider to GliderDOS: the key goes to this page's MailBox, and the count stops.
            b.findElement(By.xpath("//div[@id='keys']/button[text()='Ctrl-C']")).click();
            wait.until(d -> text(d, "console").contains("alice> ?key ctrl-c") && text(d, "console").contains("GliderDOS"));
            wait.until(d -> !d.findElement(By.id("dives-in")).isDisplayed());
            assertThat(text(b, "badge")).isEqualTo("on call");

            // ?key typed in the page means this page's vehicle (no full address needed).
            b.findElement(By.id("command")).sendKeys("?key ctrl-c", Keys.ENTER);
            wait.until(d -> text(d, "console").split("alice> \\?key ctrl-c", -1).length == 3); // the vehicle's console has it
            assertThat(text(b, "console")).doesNotContain("usage: ?key MAILBOX KEY").doesNotContain("Error: ");

            // Output once: what the glider prints arrives as console lines, not again as the reply.
            WebElement command = b.findElement(By.id("command"));
            command.sendKeys("help", Keys.ENTER);
            wait.until(d -> text(d, "console").contains("alice> help") && text(d, "console").contains("monitor [SECONDS]"));
            Thread.sleep(1500); // a second copy would come with the reply, right after
            String afterHelp = text(b, "console").substring(text(b, "console").lastIndexOf("alice> help"));
            assertThat(afterHelp.split("monitor \\[SECONDS]", -1)).as("the help text once:\n" + afterHelp).hasSize(2);

            // Esc cancels the command this page started: the glider is interrupted, the request ends CANCELLED.
            command.sendKeys("monitor 60", Keys.ENTER);
            wait.until(d -> d.findElement(By.id("cancel")).isEnabled() && text(d, "console").contains("alice> monitor 60"));
            command.sendKeys(Keys.ESCAPE);
            wait.until(d -> text(d, "console").contains("cancelled by alice"));
            String console = text(b, "console");
            assertThat(console).contains("interrupted 'monitor 60'").doesNotContain("is queued or running");
            wait.until(d -> !d.findElement(By.id("cancel")).isEnabled());

            // Nobody answers GliderDOS: it resumes and dives; the badge follows the call's event as it comes.
            wait.until(d -> !text(d, "badge").equals("on call"));
            String badge = text(b, "badge");
            assertThat(badge).isIn("dived", "link lost");
            assertThat(text(b, "console")).contains(badge.equals("dived") ? "[DIVED]" : "[LINK_LOST]");
            wait.until(d -> text(d, "badge").equals("on call")); // and calls again
        } finally {
            b.quit();
        }
    }

    @Test
    void theFilesPageCancelsTheTransferItStarted() throws Exception {
        ChromeDriver b = sys.loggedIn("alice");
        try {
            WebDriverWait wait = waiting(b);
            b.get(page("files.html", GLIDER2));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            wait.until(d -> "ON_CALL".equals(state(b, GLIDER2)));
            b.findElement(By.id("transfer-names")).sendKeys("BIG.DAT");
            b.findElement(By.xpath("//button[text()='ymodem:get']")).click();
            wait.until(d -> text(d, "transfer-progress").matches("(?s).*\\d+ %.*"));
            assertThat(b.findElement(By.id("transfer-cancel")).isDisplayed()).isTrue();
            viewport(b, 1366, 768);
            LaunchedWeb.shot(b, "files-cancel-desktop");
            b.findElement(By.id("transfer-cancel")).click();
            wait.until(d -> text(d, "transfer-reply").startsWith("Error:"));
            assertThat(text(b, "transfer-reply")).containsIgnoringCase("cancel").doesNotContain("no request #");
            assertThat(b.findElement(By.id("transfer-cancel")).isDisplayed()).isFalse();
            b.findElement(By.id("refresh-downloads")).click();
            Thread.sleep(500);
            assertThat(text(b, "downloads")).doesNotContain("BIG.DAT");
            // A small one comes whole, and its row's Download stays one line on a phone.
            WebElement names = b.findElement(By.id("transfer-names"));
            names.clear();
            names.sendKeys("SMALL.TXT");
            b.findElement(By.xpath("//button[text()='ymodem:get']")).click();
            wait.until(d -> text(d, "downloads").contains("SMALL.TXT"));
            LaunchedWeb.shot(b, "files-desktop");

            // A row's Download is its Cancel while the chunks come: 64 MB stored for glider2 stops part way, nothing saved.
            Path folder = sys.data.resolve("download").resolve(text(b, "downloads").lines().filter(l -> l.contains("SMALL.TXT"))
                    .findFirst().orElseThrow().split("/")[0]);
            try (var out = Files.newOutputStream(folder.resolve("HUGE.BIN"))) {
                byte[] mb = new byte[1 << 20];
                for (int i = 0; i < 64; i++) {
                    out.write(mb);
                }
            }
            b.findElement(By.id("refresh-downloads")).click();
            wait.until(d -> text(d, "downloads").contains("HUGE.BIN"));
            By huge = By.xpath("//tbody[@id='downloads']/tr[contains(@data-name,'HUGE.BIN')]//button");
            b.findElement(huge).click();
            wait.until(d -> d.findElement(huge).getText().equals("Cancel") && text(d, "download-status").contains("HUGE.BIN: "));
            b.findElement(huge).click();
            wait.until(d -> text(d, "download-status").startsWith("Error: download of"));
            assertThat(text(b, "download-status")).contains("HUGE.BIN cancelled at");
            assertThat(b.findElement(huge).getText()).isEqualTo("Download");
            assertThat(sys.downloads("alice").resolve("HUGE.BIN")).doesNotExist();
            viewport(b, 390, 844);
            noSidewaysScrolling(b);
            WebElement download = b.findElement(By.xpath("//tbody[@id='downloads']//button[text()='Download']"));
            b.executeScript("arguments[0].scrollIntoView({block: 'center'})", download);
            assertThat(download.getSize().getHeight()).as("Download on one line").isLessThan(2 * download.getSize().getWidth() / 3 + 20)
                    .isLessThan(48);
            LaunchedWeb.shot(b, "files-phone");
        } finally {
            b.quit();
        }
    }

    @Test
    void theFleetMapDrawsTheWholeTrackGpsAndDeadReckonedWithAScale() throws Exception {
        ChromeDriver b = sys.loggedIn("alice");
        try {
            WebDriverWait wait = waiting(b);
            Object ingest = b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                    + "import('/postoffice.js').then(async (m) => { const s = await m.session(); const po = new m.PostOffice(s.csrf);"
                    + " const r = await po.send(arguments[0], 'ingest unit_363_2013_245_6_6.mrg'); done(r.status + ' ' + r.text); });", DB);
            assertThat(String.valueOf(ingest)).startsWith("OK");
            b.get(sys.url("/fleet.html"));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            wait.until(d -> Integer.parseInt(d.findElement(By.id("map")).getAttribute("data-gps")) > 0);
            WebElement map = b.findElement(By.id("map"));
            int gps = Integer.parseInt(map.getAttribute("data-gps"));
            int dr = Integer.parseInt(map.getAttribute("data-dr"));
            assertThat(dr).as("the database's dead-reckoned positions").isGreaterThan(10);
            assertThat(gps).as("the transcript's and the database's GPS fixes").isGreaterThan(2);
            assertThat(map.getAttribute("data-scale")).matches("\\d+(\\.\\d+)? k?m");
            // The whole track: every position the database holds and the transcript's fixes, not the last one or two.
            Object dbRows = b.executeAsyncScript("const done = arguments[arguments.length - 1];"
                    + "import('/postoffice.js').then(async (m) => { const s = await m.session(); const po = new m.PostOffice(s.csrf);"
                    + " const r = await po.send(arguments[0], 'SELECT COUNT(*) FROM positions'); done(r.result.rows[0][0]); });", DB);
            assertThat(gps + dr).isGreaterThanOrEqualTo(Integer.parseInt(String.valueOf(dbRows)) + 2);
            assertThat(b.findElement(By.cssSelector("table.fleet")).getText()).contains("glider1").contains("glider2");
            // Fitted to one vehicle (a fleet may be oceans apart): the database's glider and its track.
            String scaleOfAll = map.getAttribute("data-scale");
            new org.openqa.selenium.support.ui.Select(b.findElement(By.id("map-focus"))).selectByVisibleText("unit_363");
            wait.until(d -> !scaleOfAll.equals(d.findElement(By.id("map")).getAttribute("data-scale")));
            assertThat(b.findElement(By.id("map")).getAttribute("data-dr")).isEqualTo(String.valueOf(dr)); // every fix still drawn
            viewport(b, 1366, 768);
            LaunchedWeb.shot(b, "fleet-track-desktop");
            viewport(b, 390, 844);
            noSidewaysScrolling(b);
            WebElement position = b.findElement(By.xpath("//table[contains(@class,'fleet')]//th[text()='Position']"));
            assertThat(position.isDisplayed()).as("the fleet shows Position on a phone").isTrue();
            b.executeScript("document.getElementById('map').scrollIntoView()");
            LaunchedWeb.shot(b, "fleet-track-phone");
        } finally {
            b.quit();
        }
    }

    @Test
    void eachUserGetsTheControlsTheirRulesAllowNotTheirRolesName() throws Exception {
        // vic's role is no 'observers', but his rules let him only read: no command line, no keys, no transfers, no queue.
        ChromeDriver b = sys.loggedIn("vic");
        try {
            WebDriverWait wait = waiting(b);
            b.get(page("vehicle.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.findElement(By.id("command-form")).isDisplayed()).isFalse();
            assertThat(b.findElement(By.id("observer")).isDisplayed()).isTrue();
            assertThat(keyButtons(b)).isEmpty();
            wait.until(d -> text(d, "console").contains("GPS Location")); // he reads the console
            b.get(page("files.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.findElement(By.id("transfers")).isDisplayed()).isFalse();
            b.get(page("queue.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.findElement(By.id("add")).isDisplayed()).isFalse();
            assertThat(b.findElement(By.id("clear-queue")).isDisplayed()).isFalse();
            viewport(b, 1366, 768);
            LaunchedWeb.shot(b, "queue-observer-desktop");
        } finally {
            b.quit();
        }
        // pia may press Ctrl-C and nothing else: the one key, no command line.
        b = sys.loggedIn("pia");
        try {
            WebDriverWait wait = waiting(b);
            b.get(page("vehicle.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            wait.until(d -> !keyButtons(d).isEmpty());
            assertThat(keyButtons(b)).containsExactly("Ctrl-C");
            assertThat(b.findElement(By.id("command-form")).isDisplayed()).isFalse();
            assertThat(b.findElement(By.id("observer")).isDisplayed()).isFalse();
        } finally {
            b.quit();
        }
        // olga, an observer by the template's rules, and alice, an operator: the template's rules decide for them too.
        b = sys.loggedIn("olga");
        try {
            WebDriverWait wait = waiting(b);
            b.get(page("vehicle.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.findElement(By.id("command-form")).isDisplayed()).isFalse();
            assertThat(keyButtons(b)).isEmpty();
            b.get(page("files.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.findElement(By.id("transfers")).isDisplayed()).isFalse();
        } finally {
            b.quit();
        }
        b = sys.loggedIn("alice");
        try {
            WebDriverWait wait = waiting(b);
            b.get(page("files.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.findElements(By.cssSelector("#transfer-buttons button")).stream().map(WebElement::getText))
                    .containsExactly("ymodem:get", "ymodem:put", "zmodem:get", "zmodem:put");
            b.get(page("queue.html", GLIDER1));
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.findElement(By.id("add")).isDisplayed()).isTrue();
            wait.until(d -> !text(d, "receipts-status").isEmpty());
            assertThat(text(b, "receipts-status")).doesNotContain("oldest first"); // the card lists them newest first
        } finally {
            b.quit();
        }
    }
}
