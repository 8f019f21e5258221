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
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The public view in a browser that never logs in (issue 21 item 9): {@code --public 'glider*'}
 * shows the calling glider's state, last contact and track on the map, and not the vehicle whose
 * name does not match; the console pages send the anonymous visitor to log in. (The attacks on it
 * are {@code org.ripv.it.security.PublicViewAttackTest}.)
 */
@ResourceLock(Shared.BROWSER)
class PublicViewBrowserTest {
    @TempDir
    static Path dir;
    static LaunchedWeb sys;

    @BeforeAll
    static void start() throws Exception {
        Chromium.assume();
        sys = new LaunchedWeb(dir, List.of("alice:operators"), List.of(), "--public", "glider*");
        sys.vehicles("glider1", "hidden2");
    }

    @AfterAll
    static void stop() {
        if (sys != null) {
            sys.close();
        }
    }

    @Test
    void anAnonymousVisitorFollowsThePublicGliderAndNothingElse() throws Exception {
        ChromeDriver b = Chromium.start(Files.createDirectories(dir.resolve("anonymous-browser")));
        try {
            WebDriverWait wait = new WebDriverWait(b, WebConsoleBrowserTest.T);
            b.get(sys.url("/public.html"));
            // The page asks again every 15 s, so the glider shows up once it has called in and sent a fix.
            wait.until(d -> !d.findElements(By.cssSelector("tr[data-name='glider1'] .badge.ON_CALL")).isEmpty()
                    && !"0".equals(d.findElement(By.id("map")).getAttribute("data-points")));
            String table = b.findElement(By.id("vehicles")).getText();
            assertThat(table).contains("glider1").contains("on call").containsPattern("\\d+ s ago|\\d+ min ago").doesNotContain("hidden2");
            assertThat(b.findElement(By.tagName("body")).getText()).doesNotContain("Log out").doesNotContain("Command");
            LaunchedWeb.shot(b, "public-desktop");
            b.manage().window().setSize(new Dimension(390, 844));
            assertThat((Long) b.executeScript("return document.documentElement.scrollWidth - document.documentElement.clientWidth"))
                    .as("no sideways scrolling on a phone").isLessThanOrEqualTo(0L);
            LaunchedWeb.shot(b, "public-phone");
            b.get(sys.url("/vehicle.html?m=glider1"));
            wait.until(d -> d.findElements(By.id("password")).size() == 1); // the console is for those who log in
        } finally {
            b.quit();
        }
    }
}
