package org.ripv.it.security;

import static org.assertj.core.api.Assertions.assertThat;

import com.sun.net.httpserver.HttpServer;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URLEncoder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.examples.ClockService;
import org.ripv.it.TestSystem;
import org.ripv.it.web.Chromium;
import org.ripv.it.web.WebVisitor;
import org.ripv.server.ServerConfig;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * Issue 33 item 1: a page's {@code ?m=} was pasted into the commands it sends with the session's
 * CSRF token, so a link from another site to {@code queue.html?m=add%20MAILBOX%20evil.wf} made a
 * logged-in operator's own page queue a workflow an observer had uploaded, and
 * {@code ?m=clear%20MAILBOX} cleared a queue (SameSite does not help: the page's own socket
 * carries the cookie). Now a page takes {@code ?m=} only as one MailBox address and builds its
 * commands from words: headless Chromium follows those links from a second origin, the page says
 * the name is not valid, and nothing is queued or cleared.
 */
@ResourceLock(Shared.BROWSER)
class WebLinkInjectionAttackTest {
    static final String CLOCK = WebConsoleAttackTest.CLOCK;
    static final Duration T = Duration.ofSeconds(30);

    @TempDir
    static Path dir;
    static TestSystem sys;
    static WebVisitor web;
    static HttpServer evil;

    @BeforeAll
    static void start() throws Exception {
        Chromium.assume();
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).withPorts(0, 0, 0);
        sys = TestSystem.start(config).user("alice", "operators").user("olga", "observers");
        sys.register(new ClockService("localhost"));
        web = new WebVisitor(sys.server().httpPort(), true);
        // The attacker's site, another origin: a page of links into the console.
        evil = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
        evil.createContext("/", x -> {
            String q = x.getRequestURI().getRawQuery();
            byte[] page = ("<!doctype html><a id=\"go\" href=\"" + web.base + "/" + q + "\">see the glider</a>").getBytes(StandardCharsets.UTF_8);
            x.getResponseHeaders().add("Content-Type", "text/html; charset=utf-8");
            x.sendResponseHeaders(200, page.length);
            x.getResponseBody().write(page);
            x.close();
        });
        evil.start();
    }

    @AfterAll
    static void stop() {
        if (evil != null) {
            evil.stop(0);
        }
        if (sys != null) {
            sys.close();
        }
    }

    /** What {@code ?queue CLOCK} answers now, asked on a socket of the console as alice. */
    static String queue() throws Exception {
        String cookie = web.login("alice", TestSystem.PASSWORD);
        WebVisitor.Socket s = web.socket(cookie, web.base);
        s.send(1, "", "?queue " + CLOCK, web.csrf(cookie));
        return s.await("\"id\":1", T);
    }

    /** Alice's browser, logged in, clicks the attacker's link to {@code page} and gets the page's refusal. */
    static String follow(ChromeDriver b, String page) {
        b.get("http://127.0.0.1:" + evil.getAddress().getPort() + "/?" + page);
        b.findElement(By.id("go")).click();
        return new WebDriverWait(b, T).until(d -> {
            var shown = d.findElements(By.id("not-valid"));
            return shown.isEmpty() ? null : shown.get(0).getText();
        });
    }

    @Test
    void aLinkCannotMakeAnOperatorsPageQueueOrClear() throws Exception {
        // The observer's workflow, waiting in the upload store; and one workflow alice queued herself.
        Files.writeString(sys.uploadDir().resolve("evil.wf"), "workflow every-call\nsend time\n");
        Files.writeString(sys.uploadDir().resolve("mine.wf"), "workflow every-call\nsend time\n");
        String cookie = web.login("alice", TestSystem.PASSWORD);
        WebVisitor.Socket s = web.socket(cookie, web.base);
        s.send(1, "", "?queue add " + CLOCK + " mine.wf", web.csrf(cookie));
        assertThat(s.await("\"id\":1", T)).doesNotContain("\"ERROR\"");

        ChromeDriver b = Chromium.start(Files.createDirectories(dir.resolve("alice-browser")));
        try {
            b.get(web.base + "/");
            b.findElement(By.id("user")).sendKeys("alice");
            b.findElement(By.id("password")).sendKeys(TestSystem.PASSWORD);
            b.findElement(By.xpath("//button[text()='Log in']")).click();
            new WebDriverWait(b, T).until(d -> d.getCurrentUrl().endsWith("/fleet.html"));

            String add = URLEncoder.encode("add " + CLOCK + " evil.wf", StandardCharsets.UTF_8);
            assertThat(follow(b, "queue.html?m=" + add)).contains("is not a valid MailBox name").contains("nothing was sent");
            String clear = URLEncoder.encode("clear " + CLOCK, StandardCharsets.UTF_8);
            assertThat(follow(b, "queue.html?m=" + clear)).contains("is not a valid MailBox name");
            // The same words through the other pages that read ?m=, and a service page's ?s=.
            assertThat(follow(b, "vehicle.html?m=" + URLEncoder.encode("x " + CLOCK, StandardCharsets.UTF_8)))
                    .contains("is not a valid MailBox name");
            assertThat(follow(b, "files.html?m=" + clear)).contains("is not a valid MailBox name");
            assertThat(follow(b, "service.html?s=" + URLEncoder.encode("Clock Service", StandardCharsets.UTF_8)))
                    .contains("is not a valid service name");

            // The honest link still works: the page lists alice's own workflow.
            b.get(web.base + "/queue.html?m=" + URLEncoder.encode(CLOCK, StandardCharsets.UTF_8));
            new WebDriverWait(b, T).until(d -> "true".equals(d.findElement(By.tagName("body")).getDomAttribute("data-ready")));
            assertThat(b.findElement(By.id("queue")).getText()).contains("mine.wf");
        } finally {
            b.quit();
        }
        String listed = queue();
        assertThat(listed).as("alice's workflow is still queued (not cleared)").contains("mine.wf");
        assertThat(listed).as("the observer's workflow was not queued").doesNotContain("evil.wf");
    }
}
