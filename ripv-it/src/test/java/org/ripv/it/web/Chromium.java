package org.ripv.it.web;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Assumptions;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.chrome.ChromeDriverService;
import org.openqa.selenium.chrome.ChromeOptions;

/**
 * Debian's headless Chromium under Selenium, with the driver given explicitly (Selenium Manager
 * never downloads anything). Without chromium and chromedriver the test skips, saying so; under
 * {@code RIPV_REQUIRE_TOOLS=1} (CI) it fails instead.
 */
public final class Chromium {
    static final Path BROWSER = Path.of("/usr/bin/chromium");
    static final Path DRIVER = Path.of("/usr/bin/chromedriver");

    private Chromium() {}

    public static void assume() {
        boolean there = Files.isExecutable(BROWSER) && Files.isExecutable(DRIVER);
        String why = "needs " + BROWSER + " and " + DRIVER + " (apt-get install chromium chromium-driver)";
        if (!there && "1".equals(System.getenv("RIPV_REQUIRE_TOOLS"))) {
            throw new AssertionError("RIPV_REQUIRE_TOOLS is set but this test " + why);
        }
        Assumptions.assumeTrue(there, why);
    }

    /** A fresh browser with its own profile; the server's self-signed certificate is accepted as a user would after the warning. */
    public static ChromeDriver start(Path profile) {
        return start(profile, null);
    }

    /** The same, saving what the page downloads into {@code downloads} without asking (null: Chromium's default). */
    public static ChromeDriver start(Path profile, Path downloads) {
        ChromeDriverService service = new ChromeDriverService.Builder().usingDriverExecutable(DRIVER.toFile())
                .usingAnyFreePort().withLogFile(new File(profile.toFile(), "chromedriver.log")).build();
        ChromeOptions options = new ChromeOptions();
        options.setBinary(BROWSER.toFile());
        options.addArguments("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage",
                "--ignore-certificate-errors", "--window-size=1280,900", "--user-data-dir=" + profile.resolve("profile"));
        if (downloads != null) {
            options.setExperimentalOption("prefs", java.util.Map.of("download.default_directory", downloads.toString(),
                    "download.prompt_for_download", false));
        }
        ChromeDriver driver = new ChromeDriver(service, options);
        driver.manage().timeouts().scriptTimeout(Duration.ofSeconds(30));
        return driver;
    }
}
