package org.ripv.bench;

import static org.ripv.bench.BenchTools.intOption;
import static org.ripv.bench.BenchTools.median;

import com.fasterxml.jackson.databind.JsonNode;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.ripv.server.permit.PermitFile;
import org.ripv.service.ServiceConnector;
import org.ripv.service.ServiceOptions;

/**
 * {@code ./ripv bench webload} (issue 38, item 4; a measurement, not a timed test): the web
 * console's fleet page with N vehicles (default 100) loaded in a real browser — Debian's Chromium,
 * headless, over its DevTools socket ({@link HeadlessChromium}) — from the server jar launched as
 * {@code ./ripv server} runs it, timed from the navigation's start to every vehicle shown: a row
 * for each in the table and the page ready ({@code body[data-ready]}: each vehicle watched live,
 * its history and track in). Also the time to the rows alone (the list drawn).
 *
 * <p>The floor, in the same run and the same browser: the same page as it stood when ready, its
 * scripts taken out, served as a static file of the same size (with the same style sheet) from a
 * bare HTTP server in this JVM, timed to the same condition. The difference is what the console's
 * scripts, its log-in session, its WebSocket and the server's answers cost. Besides wall time, the
 * CPU per load of every process that took part (the server, this JVM with the fleet's service or
 * the static server, and the browser's processes), and the load average.
 *
 * <p>Options: {@code --vehicles N} (default 100), {@code --runs N} loads of each (default 7; the
 * first of each is a warm-up and not counted).
 */
public final class WebLoadBench {
    /** Installed before every document: notes when N rows are drawn and when the page is ready with them. */
    private static final String OBSERVER = """
            (() => {
              const want = %d;
              const check = () => {
                const rows = document.querySelectorAll('#vehicles tr').length;
                if (rows >= want && window.__ripvListed === undefined) window.__ripvListed = performance.now();
                if (rows >= want && document.body && document.body.dataset.ready === 'true' && window.__ripvShown === undefined) {
                  window.__ripvShown = performance.now();
                  observer.disconnect();
                }
              };
              const observer = new MutationObserver(check);
              observer.observe(document, {childList: true, subtree: true, attributes: true, attributeFilter: ['data-ready']});
              document.addEventListener('DOMContentLoaded', check);
            })();
            """;

    private WebLoadBench() {}

    public static void main(String[] args) throws Exception {
        System.exit(run(args));
    }

    /** The benchmark; its exit status is returned, not exited with ({@code ShortRuns} runs several in one JVM). */
    public static int run(String[] args) throws Exception {
        int vehicles = intOption(args, "--vehicles", 100);
        int runs = intOption(args, "--runs", 7);
        if (vehicles < 1 || vehicles > 1000 || runs < 2) {
            System.err.println("Usage: ripv bench webload [--vehicles N] [--runs N]   (1 to 1,000 vehicles, at least 2 runs: the first is a warm-up)");
            return 2;
        }
        System.out.printf(Locale.ROOT, "WebLoadBench: the fleet page with %d vehicles in headless Chromium, %d loads after a warm-up,"
                + " against a static page of the same size in the same browser (the machine may be shared)%n", vehicles, runs - 1);
        System.out.println(CpuClock.machineLine());
        String missing = HeadlessChromium.missing();
        if (missing != null) {
            System.out.println("webload: skipped, it " + missing);
            return 0;
        }
        Path dir = Files.createTempDirectory("ripv-bench-webload");
        PermitFile.setUser(dir.resolve("permit.txt"), "bench", "bench-password".toCharArray(), List.of("observers"), 1000);
        WebBench.Server server = WebBench.startServer(dir, "512m", 200, 200);
        FleetService fleet = new FleetService("localhost", vehicles);
        ServiceConnector link = null;
        HttpServer statics = null;
        try (HeadlessChromium browser = HeadlessChromium.start(Files.createDirectories(dir.resolve("chromium")))) {
            String secret = Files.readString(server.secretFile(), StandardCharsets.UTF_8).trim();
            link = ServiceConnector.connect(fleet, new ServiceOptions("localhost", server.registryPort(), secret, 0, Duration.ofSeconds(5)));
            link.awaitRegistered(Duration.ofSeconds(30));
            fleet.surfaceAll();
            String origin = "http://localhost:" + server.httpPort();
            WebWatchers.Page page = WebBench.login(server.httpPort(), "bench", "bench-password");
            String[] cookie = page.cookie().split("=", 2);
            browser.send("Network.enable", Map.of());
            browser.send("Network.setCookie", Map.of("name", cookie[0], "value", cookie[1], "url", origin));
            browser.send("Page.addScriptToEvaluateOnNewDocument", Map.of("source", String.format(Locale.ROOT, OBSERVER, vehicles)));

            Loads live = loads(browser, origin + "/fleet.html", runs, () -> {
                List<ProcessHandle> all = new ArrayList<>(browser.processes());
                all.add(server.process().toHandle());
                return all;
            });

            // The floor: the page as it stands now, ready, without its scripts, from a bare HTTP server.
            String html = "<!DOCTYPE html>\n" + browser.evaluate("document.documentElement.outerHTML").asText()
                    .replaceAll("(?s)<script\\b.*?</script>", "");
            String css = HttpClient.newHttpClient().send(HttpRequest.newBuilder(URI.create(origin + "/ripv.css")).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            statics = staticServer(Map.of("/fleet.html", html, "/ripv.css", css));
            Loads floor = loads(browser, "http://localhost:" + statics.getAddress().getPort() + "/fleet.html", runs, browser::processes);

            System.out.printf(Locale.ROOT, "%n%-58s %12s %12s %14s%n", "page (median of " + (runs - 1) + " loads; max)", "rows drawn ms",
                    "all shown ms", "CPU ms per load");
            System.out.printf(Locale.ROOT, "%-58s %12.0f %12s %14.1f   (loads ms %s)%n",
                    "fleet page, " + vehicles + " vehicles, live", median(live.listed), String.format(Locale.ROOT, "%.0f (%.0f)", median(live.shown), max(live.shown)),
                    live.cpuMillis, Arrays.toString(live.shown));
            System.out.printf(Locale.ROOT, "%-58s %12.0f %12s %14.1f   (loads ms %s)%n",
                    "floor: the same page static (" + html.length() / 1024 + " KiB and its style sheet)", median(floor.listed),
                    String.format(Locale.ROOT, "%.0f (%.0f)", median(floor.shown), max(floor.shown)), floor.cpuMillis, Arrays.toString(floor.shown));
            System.out.println(CpuClock.ratioLine("fleet page load (server, fleet service, browser)", live.cpuMillis * 1e3,
                    floor.cpuMillis * 1e3, median(live.shown) / Math.max(1e-3, median(floor.shown)))
                    + " (floor: the same page static in the same browser)");
            System.out.println("  CPU counted: the server's JVM, this JVM (the fleet's service; for the floor the static server) and every"
                    + " Chromium process, per load");
            System.out.println(CpuClock.machineLine());
            return 0;
        } finally {
            if (statics != null) {
                statics.stop(0);
            }
            if (link != null) {
                link.close();
            }
            fleet.stop();
            server.process().destroy();
            if (!server.process().waitFor(20, TimeUnit.SECONDS)) {
                server.process().destroyForcibly();
            }
            try (var s = Files.walk(dir)) {
                for (Path p : s.sorted(Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(p);
                }
            } catch (IOException ignored) {
                // Chromium may still be writing its profile as it ends; the folder is in /tmp
            }
        }
    }

    /** Each load's milliseconds from the navigation's start, and the CPU per counted load of the processes that took part. */
    private record Loads(double[] listed, double[] shown, double cpuMillis) {}

    private static Loads loads(HeadlessChromium browser, String url, int runs, Supplier<List<ProcessHandle>> processes) throws Exception {
        double[] listed = new double[runs - 1];
        double[] shown = new double[runs - 1];
        ProcessCpu cpu = new ProcessCpu(processes);
        long cpu0 = 0;
        for (int i = 0; i < runs; i++) {
            if (i == 1) {
                cpu0 = cpu.sample();
            }
            browser.evaluate("window.__ripvShown = undefined; window.__ripvListed = undefined; null"); // the last page's times are not this one's
            browser.send("Page.navigate", Map.of("url", url));
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            JsonNode t;
            while ((t = browser.evaluate("window.__ripvShown === undefined ? null : [window.__ripvListed, window.__ripvShown]")).isNull()) {
                if (System.nanoTime() > until) {
                    throw new IOException(url + ": the vehicles were not all shown within 120 s; the page says: "
                            + browser.evaluate("document.body ? document.body.innerText.slice(0, 400) : ''").asText());
                }
                Thread.sleep(20); // the page notes its own time; this only asks whether it is there yet
            }
            cpu.sample();
            if (i > 0) {
                listed[i - 1] = Math.round(t.get(0).asDouble() * 10) / 10.0;
                shown[i - 1] = Math.round(t.get(1).asDouble() * 10) / 10.0;
            }
        }
        return new Loads(listed, shown, (cpu.sample() - cpu0) / 1e6 / (runs - 1));
    }

    /**
     * CPU of this JVM and of a changing set of processes (a browser starts and ends renderers as it
     * navigates): each process's last figure is kept, so one that ended keeps what it had spent.
     */
    private static final class ProcessCpu {
        private final Supplier<List<ProcessHandle>> processes;
        private final Map<Long, Long> last = new HashMap<>();

        ProcessCpu(Supplier<List<ProcessHandle>> processes) {
            this.processes = processes;
        }

        long sample() {
            for (ProcessHandle p : processes.get()) {
                try {
                    last.put(p.pid(), WebBench.processCpuNanos(p.pid()));
                } catch (IOException | RuntimeException gone) {
                    // ended since it was listed: its last figure stands
                }
            }
            return CpuClock.processCpuNanos() + last.values().stream().mapToLong(Long::longValue).sum();
        }
    }

    private static HttpServer staticServer(Map<String, String> files) throws IOException {
        HttpServer s = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 16);
        s.createContext("/", x -> {
            String body = files.get(x.getRequestURI().getPath());
            byte[] bytes = (body == null ? "not found" : body).getBytes(StandardCharsets.UTF_8);
            x.getResponseHeaders().set("Content-Type", x.getRequestURI().getPath().endsWith(".css") ? "text/css" : "text/html; charset=utf-8");
            x.getResponseHeaders().set("Cache-Control", "no-cache");
            x.sendResponseHeaders(body == null ? 404 : 200, bytes.length);
            x.getResponseBody().write(bytes);
            x.close();
        });
        s.start();
        return s;
    }

    private static double max(double[] v) {
        return Arrays.stream(v).max().orElse(0);
    }
}
