package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;

import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.Dimension;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.WebDriver;
import org.openqa.selenium.WebElement;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.ripv.probe.FreePorts;

/**
 * A vehicle's files, queue and receipts, and the user's notifications in the web console (issue 21
 * items 4 and 6), as launched: the server, the SerialPortServer and the simulated glider are
 * processes from the jars, and a headless Chromium uploads a workflow and queues it, sees its
 * receipt after the glider's next call, sees a typed workflow's error at its line, downloads
 * the file the glider sent, fetches one with the {@code ymodem:get} button, removes one queued
 * workflow and clears the queue, and adds and removes a
 * webhook that a real HTTP receiver on this host gets. Screenshots of each page, desktop and phone,
 * go to {@code target/web-screenshots/}.
 */
@ResourceLock(Shared.BROWSER)
class WebFilesBrowserTest {
    static final String PASSWORD = WebConsoleBrowserTest.PASSWORD;
    static final Duration T = Duration.ofSeconds(120);

    @TempDir
    static Path dir;
    static int http;
    static String glider;
    static Path data;
    static Path shots;
    static HttpServer receiver;
    static final LinkedBlockingQueue<String> hooks = new LinkedBlockingQueue<>();

    static LaunchedProcesses system;

    static Process launch(String name, String input, String... args) throws IOException {
        return system.launch(name, input, args);
    }

    static String log(String name) {
        return system.log(name);
    }

    static void waitFor(String what, java.util.function.BooleanSupplier check) throws InterruptedException {
        system.waitFor(what, check);
    }

    @BeforeAll
    static void startTheSystem() throws Exception {
        Chromium.assume();
        system = new LaunchedProcesses(dir, T);
        shots = Files.createDirectories(WebConsoleBrowserTest.root().resolve("ripv-it/target/web-screenshots"));
        receiver = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 16);
        receiver.createContext("/hook", x -> {
            hooks.add(new String(x.getRequestBody().readAllBytes(), StandardCharsets.UTF_8));
            x.sendResponseHeaders(204, -1);
            x.close();
        });
        receiver.start();
        data = dir.resolve("server");
        Files.createDirectories(data);
        Process pw = launch("passwd", PASSWORD + "\n", "-jar", WebConsoleBrowserTest.jar("ripv-server").toString(), "passwd", "--permit",
                data.resolve("permit.txt").toString(), "alice", "--roles", "operators");
        assertThat(pw.waitFor()).as(log("passwd")).isZero();
        int port = FreePorts.one();
        int registry = FreePorts.one();
        int link = FreePorts.one();
        http = FreePorts.one();
        launch("server", null, "-jar", WebConsoleBrowserTest.jar("ripv-server").toString(), "server", "--data", data.toString(),
                "--port", String.valueOf(port), "--registry-port", String.valueOf(registry), "--http-port", String.valueOf(http),
                "--bind", "127.0.0.1", "--webhook-allow", "127.0.0.1/32");
        waitFor("the server's web console", () -> {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), http)) {
                return true;
            } catch (IOException e) {
                return false;
            }
        });
        launch("serial", null, "-Dripv.host=localhost", "-jar", WebConsoleBrowserTest.jar("ripv-services").toString(), "serial",
                "--server", "127.0.0.1:" + registry, "--secret-file", data.resolve("service.secret").toString(), "--link",
                "listen://127.0.0.1:" + link + ",name=glider1", "--carrier", "ignore", "--no-enumerate");
        waitFor("the SerialPortServer's MailBoxes", () -> log("serial").contains("MailBoxes:"));
        glider = "<SerialPortServer>::<localhost>glider1";
        // Short dives and surfacings: the glider calls again and again, so "the next call" comes soon.
        launch("simulator", null, "-jar", WebConsoleBrowserTest.jar("ripv-services").toString(), "simulator", "--call",
                "127.0.0.1:" + link, "--name", "glider1", "--dive-seconds", "3", "--surface-seconds", "25", "--dir",
                dir.resolve("glider").toString());
    }

    @AfterAll
    static void stopTheSystem() {
        if (receiver != null) {
            receiver.stop(0);
        }
        if (system != null) {
            system.stopAll();
        }
    }

    static ChromeDriver browser(String name) throws IOException {
        ChromeDriver b = Chromium.start(Files.createDirectories(dir.resolve(name)));
        b.get("https://127.0.0.1:" + http + "/");
        b.findElement(By.id("user")).sendKeys("alice");
        b.findElement(By.id("password")).sendKeys(PASSWORD);
        b.findElement(By.xpath("//button[text()='Log in']")).click();
        new WebDriverWait(b, T).until(d -> d.getCurrentUrl().endsWith("/fleet.html"));
        return b;
    }

    static void open(ChromeDriver b, String page) {
        b.get("https://127.0.0.1:" + http + "/" + page + "?m=" + java.net.URLEncoder.encode(glider, StandardCharsets.UTF_8));
        new WebDriverWait(b, T).until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
    }

    /** Desktop and phone screenshots with the element {@code show} in view; on the phone nothing scrolls sideways. */
    static void shots(ChromeDriver b, String name, String show) throws IOException {
        String scroll = "document.getElementById(arguments[0]).scrollIntoView({block: 'center'})";
        b.executeScript(scroll, show);
        Files.write(shots.resolve(name + "-desktop.png"), b.getScreenshotAs(OutputType.BYTES));
        b.manage().window().setSize(new Dimension(390, 844));
        try {
            assertThat((Long) b.executeScript("return document.documentElement.scrollWidth - document.documentElement.clientWidth"))
                    .as("no sideways scrolling on a phone: " + name).isLessThanOrEqualTo(0L);
            b.executeScript(scroll, show);
            Files.write(shots.resolve(name + "-phone.png"), b.getScreenshotAs(OutputType.BYTES));
        } finally {
            b.manage().window().setSize(new Dimension(1280, 900));
        }
    }

    static String text(WebDriver b, String id) {
        return b.findElement(By.id(id)).getText();
    }

    @Test
    void aWorkflowIsUploadedQueuedAndItsReceiptShownAndWhatItFetchedDownloads() throws Exception {
        ChromeDriver b = browser("queue-browser");
        try {
            WebDriverWait wait = new WebDriverWait(b, T);
            b.get("https://127.0.0.1:" + http + "/vehicle.html?m=" + java.net.URLEncoder.encode(glider, StandardCharsets.UTF_8));
            wait.until(d -> d.findElement(By.id("queue-link")).getAttribute("href").contains("?m="));
            b.findElement(By.linkText("Queue and receipts")).click();
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            assertThat(b.getCurrentUrl()).contains("queue.html?m=");

            // A typed workflow with a misspelt step: the parser's FILE:LINE: reason, under line 3.
            WebElement typed = b.findElement(By.id("wf-text"));
            typed.clear();
            typed.sendKeys("workflow once\nsend dir\nymodem:gte MISSION1.LOG\n");
            b.findElement(By.id("wf-name")).clear();
            b.findElement(By.id("wf-name")).sendKeys("typo.wf");
            b.findElement(By.id("add-typed")).click();
            wait.until(d -> !d.findElements(By.id("error-line")).isEmpty());
            List<WebElement> lines = b.findElements(By.cssSelector("#wf-lines > li"));
            assertThat(lines.get(2).getAttribute("id")).isEqualTo("error-line");
            assertThat(lines.get(2).getText()).startsWith("ymodem:gte MISSION1.LOG").contains("typo.wf:3: unknown step 'ymodem:gte'");
            assertThat(text(b, "add-status")).startsWith("Error: typo.wf:3:");
            assertThat(text(b, "queue-status")).contains("is empty");
            shots(b, "queue", "wf-lines");

            // A workflow file from this computer: uploaded into the store, then queued.
            Path wf = dir.resolve("fetch-log.wf");
            Files.writeString(wf, "workflow once\nymodem:get MISSION1.LOG timeout=5m\nnotify \"fetched {fetched}\"\n");
            b.findElement(By.id("wf-file")).sendKeys(wf.toString());
            b.findElement(By.id("add-file")).click();
            wait.until(d -> text(d, "add-status").contains("queued workflow"));
            assertThat(b.findElement(By.id("wf-lines")).isDisplayed()).isFalse();
            // It runs on the glider's call (now, or the next one): its receipt appears, open it.
            wait.withMessage(() -> "no receipt of fetch-log.wf DONE; the page says: " + text(b, "receipts-status") + " / "
                    + text(b, "receipts") + " / " + text(b, "queue-status") + " / " + text(b, "queue")).until(d -> {
                List<WebElement> r = d.findElements(By.cssSelector("#receipts details summary"));
                if (r.stream().noneMatch(s -> s.getText().contains("fetch-log.wf") && s.getText().endsWith("— DONE"))) {
                    d.findElement(By.id("refresh-receipts")).click();
                    return false;
                }
                return true;
            });
            WebElement receipt = b.findElement(By.cssSelector("#receipts details"));
            receipt.findElement(By.tagName("summary")).click();
            wait.until(d -> receipt.findElement(By.tagName("pre")).isDisplayed());
            assertThat(receipt.findElement(By.tagName("pre")).getText()).contains("ymodem:get MISSION1.LOG: OK")
                    .contains("/MISSION1.LOG").contains("result: DONE");
            assertThat(text(b, "queue-status")).contains("is empty");

            // The file the glider sent, downloaded into the browser's download folder, byte for byte.
            Path downloads = Files.createDirectories(dir.resolve("downloads"));
            b.executeCdpCommand("Browser.setDownloadBehavior", Map.of("behavior", "allow", "downloadPath", downloads.toString()));
            open(b, "files.html");
            WebElement row = wait.until(d -> d.findElements(By.cssSelector("#downloads tr")).stream()
                    .filter(r -> r.getAttribute("data-name").endsWith("/MISSION1.LOG")).findFirst().orElse(null));
            String stored = row.getAttribute("data-name");
            row.findElement(By.tagName("button")).click();
            Path got = downloads.resolve("MISSION1.LOG");
            try {
                waitFor("the browser's download", () -> Files.exists(got) && text(b, "download-status").startsWith("Downloaded"));
            } catch (AssertionError e) {
                try (Stream<Path> there = Files.list(downloads)) {
                    throw new AssertionError(e.getMessage() + "; the page says '" + text(b, "download-status") + "', the folder holds "
                            + there.toList(), e);
                }
            }
            assertThat(Files.readAllBytes(got)).isEqualTo(Files.readAllBytes(data.resolve("download").resolve(stored)));

            // The ymodem:get button sends the CLI's command to the vehicle; the reply says what came.
            b.findElement(By.id("transfer-names")).sendKeys("MISSION2.LOG");
            b.findElement(By.xpath("//button[text()='ymodem:get']")).click();
            wait.until(d -> !text(d, "transfer-reply").isEmpty());
            assertThat(text(b, "transfer-reply")).doesNotStartWith("Error").contains("MISSION2.LOG");
            wait.until(d -> d.findElements(By.cssSelector("#downloads tr")).stream()
                    .anyMatch(r -> r.getAttribute("data-name").endsWith("/MISSION2.LOG")));

            // Uploading a name that is taken is refused (FILE_EXISTS) unless asked to keep or replace.
            b.findElement(By.id("upload-file")).sendKeys(wf.toString());
            b.findElement(By.id("upload")).click();
            wait.until(d -> text(d, "upload-status").startsWith("Error"));
            assertThat(text(b, "upload-status")).contains("fetch-log.wf");
            b.findElement(By.cssSelector("#if-exists option[value=keep]")).click();
            b.findElement(By.id("upload-file")).sendKeys(wf.toString());
            b.findElement(By.id("upload")).click();
            wait.until(d -> text(d, "upload-status").startsWith("stored as"));
            shots(b, "files", "name");

            // Two workflows that wait: the first runs (its wait-for never matches), the second waits behind it.
            // Remove takes the second out; Clear takes the rest.
            open(b, "queue.html");
            for (String name : List.of("hold.wf", "later.wf")) {
                WebElement steps = b.findElement(By.id("wf-text"));
                steps.clear();
                steps.sendKeys("workflow once\nwait-for 'NEVER PRINTED' timeout=20s\n");
                b.findElement(By.id("wf-name")).clear();
                b.findElement(By.id("wf-name")).sendKeys(name);
                b.findElement(By.id("add-typed")).click();
                wait.until(d -> text(d, "add-status").startsWith("queued workflow") && text(d, "add-status").contains(name));
            }
            wait.until(d -> d.findElements(By.cssSelector("#queue li")).size() == 2);
            WebElement later = b.findElements(By.cssSelector("#queue li")).stream().filter(li -> li.getText().contains("later.wf"))
                    .findFirst().orElseThrow();
            later.findElement(By.tagName("button")).click();
            wait.until(d -> text(d, "queue-reply").startsWith("removed workflow"));
            assertThat(text(b, "queue-reply")).contains("later.wf");
            wait.until(d -> d.findElements(By.cssSelector("#queue li")).size() == 1);
            assertThat(text(b, "queue")).contains("hold.wf");
            b.findElement(By.id("clear-queue")).click();
            b.switchTo().alert().accept();
            wait.until(d -> text(d, "queue-reply").startsWith("removed 1 workflow(s)"));
            wait.until(d -> text(d, "queue-status").contains("is empty"));
        } finally {
            b.quit();
        }
    }

    @Test
    void aWebhookIsAddedHearsTheGliderAndIsRemoved() throws Exception {
        ChromeDriver b = browser("notify-browser");
        try {
            WebDriverWait wait = new WebDriverWait(b, T);
            wait.ignoring(org.openqa.selenium.StaleElementReferenceException.class);
            wait.until(d -> d.findElement(By.linkText("Notifications"))).click();
            wait.until(d -> "true".equals(d.findElement(By.tagName("body")).getAttribute("data-ready")));
            String url = "http://127.0.0.1:" + receiver.getAddress().getPort() + "/hook";
            b.findElement(By.id("target")).sendKeys(url);
            b.findElement(By.id("events")).clear();
            b.findElement(By.id("events")).sendKeys("SURFACED,DIVED");
            b.findElement(By.id("glob")).clear();
            b.findElement(By.id("glob")).sendKeys("*glider1");
            b.findElement(By.id("add")).click();
            wait.until(d -> text(d, "add-status").startsWith("subscription "));
            WebElement item = b.findElement(By.cssSelector("#subscriptions li[data-id]"));
            assertThat(item.getText()).contains(url).contains("never used");
            // The glider dives and calls again: the receiver hears it, and the page shows the last result.
            String hook = hooks.poll(T.toSeconds(), TimeUnit.SECONDS);
            assertThat(hook).as("a webhook POST").isNotNull().contains("glider1");
            wait.until(d -> {
                d.findElement(By.id("refresh")).click();
                return d.findElement(By.cssSelector("#subscriptions li[data-id] .last")).getText().startsWith("last: ok");
            });
            // An address the rules refuse is refused by the server, and said so on the page.
            b.findElement(By.id("target")).clear();
            b.findElement(By.id("target")).sendKeys("http://10.1.2.3/hook");
            b.findElement(By.id("add")).click();
            wait.until(d -> text(d, "add-status").startsWith("Error"));
            assertThat(text(b, "add-status")).contains("10.1.2.3");
            shots(b, "notify", "subscriptions");
            b.findElement(By.cssSelector("#subscriptions li[data-id] button")).click();
            wait.until(d -> text(d, "list-status").startsWith("0 subscription"));
            assertThat(b.findElements(By.cssSelector("#subscriptions li"))).isEmpty();
        } finally {
            b.quit();
        }
    }
}
