package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openqa.selenium.By;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.testing.LoopbackSshd;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * The data page's DAC delivery card as launched (issue 37 item 4): the server and a DatabaseServer
 * with a deployment whose drop is Debian's OpenSSH on a loopback port; rosie_713's files are
 * ingested from the generic service page, and the data page shows the deployment's ten profiles,
 * their QC and that they were sent — what the service's own state says.
 */
@ResourceLock(Shared.BROWSER)
class WebDacBrowserTest {
    static final Path SHARED = WebConsoleBrowserTest.root().resolve("../shared/data/slocum-binary").normalize();
    static final String SEG = "rosie_713-2019-166-0-157";

    @TempDir
    Path dir;

    @Test
    void theDataPageShowsTheDeliveriesProfilesTheirQcAndWhatWasSent() throws Exception {
        Chromium.assume();
        assumeTrue(Files.isDirectory(SHARED.resolve("realtime_raw")), "needs ../shared/data/slocum-binary beside the repository");
        try (LoopbackSshd sshd = LoopbackSshd.start(Files.createDirectories(dir.resolve("sshd")));
             LaunchedWeb sys = new LaunchedWeb(dir, List.of("alice:operators"), List.of())) {
            Path root = WebConsoleBrowserTest.root();
            Path deployment = dir.resolve("deployment.json");
            Files.writeString(deployment, "{\"glider\": \"rosie_713\", \"metadata\": \"" + root.resolve("docs/samples/dac-deployment.json")
                    + "\", \"qc\": \"" + root.resolve("docs/samples/dac-qc.yml") + "\", \"folder\": \"" + dir.resolve("dac")
                    + "\", \"destination\": \"" + sshd.url() + "\", \"key\": \"" + sshd.key() + "\", \"known_hosts\": \""
                    + sshd.knownHosts() + "\"}");
            sys.service("database", "--data", dir.resolve("database").toString(), "--dac", deployment.toString());
            Path downloads = Files.createDirectories(sys.data.resolve("download"));
            for (String f : List.of(SEG + ".sbd", SEG + ".tbd")) {
                Files.copy(SHARED.resolve("realtime_raw").resolve(f), downloads.resolve(f));
            }
            for (String c : List.of("6b016a2e.cac", "426bd56d.cac")) {
                Files.copy(SHARED.resolve("cac").resolve(c), downloads.resolve(c));
            }
            ChromeDriver b = sys.loggedIn("alice");
            try {
                WebDriverWait wait = new WebDriverWait(b, WebConsoleBrowserTest.T);
                b.get(sys.url("/data.html"));
                wait.until(d -> WebDataBrowserTest.text(b, "dac-state").startsWith("1 deployment"));
                assertThat(WebDataBrowserTest.text(b, "dac-deployments")).contains("rosie_713 → " + sshd.url()).contains("no profile yet");

                b.get(sys.url("/service.html?s=DatabaseServer"));
                wait.until(d -> d.findElements(By.cssSelector("#mailboxes tr[data-address]")).size() == 1);
                WebDataBrowserTest.send(b, "DatabaseServer", "ingest 6b016a2e.cac 426bd56d.cac " + SEG + ".sbd " + SEG + ".tbd");
                wait.until(d -> WebDataBrowserTest.text(b, "replies").contains("642 rows"));

                b.get(sys.url("/data.html"));
                wait.until(d -> {
                    if (!WebDataBrowserTest.text(b, "dac-deployments").contains("10 profile(s) (10 sent)")) {
                        d.findElement(By.id("dac-refresh")).click();
                        return false;
                    }
                    return true;
                });
                String card = WebDataBrowserTest.text(b, "dac-deployments");
                assertThat(card).contains("newest profile rosie_713_20190620T080055Z_rt.nc: its data");
                assertThat(b.findElements(By.cssSelector("#dac-deployments tbody tr"))).hasSize(10);
                assertThat(b.findElement(By.cssSelector("#dac-deployments tbody tr")).getText())
                        .contains("rosie_713_20190620T062352Z_rt.nc").contains("real-time").contains("dive").contains("24")
                        .contains("QC temperature 23 good 1 suspect").contains("sent");
                b.executeScript("document.getElementById('dac').scrollIntoView()");
                LaunchedWeb.shot(b, "data-dac-desktop");
                assertThat(sshd.drop().toFile().list()).hasSize(10);
            } finally {
                b.quit();
            }
        }
    }
}
