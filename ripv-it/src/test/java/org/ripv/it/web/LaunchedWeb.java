package org.ripv.it.web;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.openqa.selenium.By;
import org.openqa.selenium.OutputType;
import org.openqa.selenium.chrome.ChromeDriver;
import org.openqa.selenium.support.ui.WebDriverWait;
import org.ripv.probe.FreePorts;

/**
 * A RIPVServer and services started from the jars as separate processes, for browser tests that
 * need their own (WebConsoleBrowserTest's launch, wait and log-in, as an object). Close it to
 * stop every process it started.
 */
public final class LaunchedWeb implements AutoCloseable {
    public final Path dir;
    public final Path data;
    public final int port;
    public final int registry;
    public final int http;
    private final LaunchedProcesses processes;
    private final java.util.concurrent.atomic.AtomicInteger browsers = new java.util.concurrent.atomic.AtomicInteger();
    private String[] serverArgs;
    private Process server;
    private int restarts;

    /** Users as NAME:ROLES (each with {@link WebConsoleBrowserTest#PASSWORD}); extra permit lines appended after them. */
    public LaunchedWeb(Path dir, List<String> users, List<String> permitLines, String... serverOptions) throws Exception {
        this.dir = dir;
        this.processes = new LaunchedProcesses(dir, WebConsoleBrowserTest.T);
        this.data = Files.createDirectories(dir.resolve("server"));
        Path permit = data.resolve("permit.txt");
        for (String u : users) {
            String[] w = u.split(":");
            Process p = launch("passwd-" + w[0], WebConsoleBrowserTest.PASSWORD + "\n", "-jar", jar("ripv-server"), "passwd", "--permit",
                    permit.toString(), w[0], "--roles", w[1]);
            assertThat(p.waitFor()).as(log("passwd-" + w[0])).isZero();
        }
        if (!permitLines.isEmpty()) {
            Files.write(permit, permitLines, StandardCharsets.UTF_8, java.nio.file.StandardOpenOption.APPEND);
        }
        port = FreePorts.one();
        registry = FreePorts.one();
        http = FreePorts.one();
        List<String> args = new ArrayList<>(List.of("-jar", jar("ripv-server"), "server", "--data", data.toString(), "--port",
                String.valueOf(port), "--registry-port", String.valueOf(registry), "--http-port", String.valueOf(http), "--bind", "127.0.0.1"));
        args.addAll(List.of(serverOptions));
        serverArgs = args.toArray(String[]::new);
        server = launch("server", null, serverArgs);
        waitForWebConsole();
    }

    /** Stops the server (as a restart does: SIGTERM, then forcibly after 10 s) and starts it again on the same data and ports. */
    public void restartServer() throws Exception {
        server.destroy();
        if (!server.waitFor(10, java.util.concurrent.TimeUnit.SECONDS)) {
            server.destroyForcibly().waitFor();
        }
        server = launch("server-" + (++restarts + 1), null, serverArgs);
        waitForWebConsole();
    }

    /** The log of the server running now. */
    public String serverLog() {
        return log(restarts == 0 ? "server" : "server-" + (restarts + 1));
    }

    private void waitForWebConsole() throws InterruptedException {
        waitFor("the server's web console", () -> {
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), http)) {
                return true;
            } catch (IOException e) {
                return false;
            }
        });
    }

    static String jar(String module) {
        return WebConsoleBrowserTest.jar(module).toString();
    }

    /** A service (serial, database, datavis; clock from ripv-common) registered with this server; waits until it is. */
    public void service(String kind, String... options) throws Exception {
        List<String> args = new ArrayList<>(List.of("-Dripv.host=localhost", "-jar"));
        if (kind.equals("clock")) {
            args.add(jar("ripv-common")); // as ./ripv service clock runs it
        } else {
            args.addAll(List.of(jar("ripv-services"), kind));
        }
        args.addAll(List.of("--server", "127.0.0.1:" + registry, "--secret-file", data.resolve("service.secret").toString()));
        args.addAll(List.of(options));
        Process p = launch(kind, null, args.toArray(String[]::new));
        waitFor(kind + " registering", () -> {
            assertThat(p.isAlive()).as(log(kind)).isTrue();
            return log(kind).contains("registered with the RIPVServer");
        });
    }

    /**
     * A SerialPortServer with one listening link per name (MailBoxes {@code <SerialPortServer>::<localhost>NAME}),
     * and the simulated glider calling in on the first, diving for 5 s and staying up for 10 minutes.
     */
    public void vehicles(String... names) throws Exception {
        List<String> args = new ArrayList<>(List.of("-Dripv.host=localhost", "-jar", jar("ripv-services"), "serial", "--server",
                "127.0.0.1:" + registry, "--secret-file", data.resolve("service.secret").toString(), "--carrier", "ignore", "--no-enumerate"));
        int calling = 0;
        for (String n : names) {
            int link = FreePorts.one();
            calling = calling == 0 ? link : calling;
            args.addAll(List.of("--link", "listen://127.0.0.1:" + link + ",name=" + n));
        }
        launch("serial", null, args.toArray(String[]::new));
        waitFor("the SerialPortServer's MailBoxes", () -> log("serial").contains("MailBoxes:"));
        launch("simulator", null, "-jar", jar("ripv-services"), "simulator", "--call", "127.0.0.1:" + calling, "--name", names[0],
                "--dive-seconds", "5", "--surface-seconds", "600", "--dir", dir.resolve("glider").toString());
    }

    Process launch(String name, String input, String... args) throws IOException {
        return processes.launch(name, input, args);
    }

    public void waitFor(String what, java.util.function.BooleanSupplier check) throws InterruptedException {
        processes.waitFor(what, check);
    }

    public String log(String name) {
        return processes.log(name);
    }

    public String url(String page) {
        return "https://127.0.0.1:" + http + page;
    }

    /** A fresh browser of the user's own, logged in, on the fleet page. */
    ChromeDriver loggedIn(String user) throws IOException {
        // A profile of its own each time: a second browser of the same user starts logged out, as a new device does.
        ChromeDriver b = Chromium.start(Files.createDirectories(dir.resolve(user + "-browser-" + browsers.incrementAndGet())), downloads(user));
        try {
            b.get(url("/"));
            b.findElement(By.id("user")).sendKeys(user);
            b.findElement(By.id("password")).sendKeys(WebConsoleBrowserTest.PASSWORD);
            b.findElement(By.xpath("//button[text()='Log in']")).click();
            new WebDriverWait(b, WebConsoleBrowserTest.T).until(d -> d.getCurrentUrl().endsWith("/fleet.html"));
            return b;
        } catch (RuntimeException | Error e) {
            b.quit();
            throw new AssertionError("could not log in as " + user + "; server log:\n" + log("server"), e);
        }
    }

    /** Where the user's browser saves downloads. */
    Path downloads(String user) throws IOException {
        return Files.createDirectories(dir.resolve(user + "-downloads"));
    }

    /** Saves a screenshot to ripv-it/target/web-screenshots/NAME.png. */
    static void shot(ChromeDriver b, String name) throws IOException {
        Path shots = Files.createDirectories(WebConsoleBrowserTest.root().resolve("ripv-it/target/web-screenshots"));
        Files.write(shots.resolve(name + ".png"), b.getScreenshotAs(OutputType.BYTES));
    }

    @Override
    public void close() {
        processes.stopAll();
    }
}
