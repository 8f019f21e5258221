package org.ripv.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * {@code bench web}'s fleet page with N vehicles, timed over its endpoint as fleet.js loads it (not
 * in a browser: {@link WebLoadBench} does that): its files, {@code /api/session}, the WebSocket,
 * {@code ?mailboxes}, then a {@code ?watch} per vehicle, all sent at once.
 */
final class FleetPageTiming {
    private final PrintStream out;
    private final int vehicles;
    private final int fleetRuns;

    FleetPageTiming(PrintStream out, int vehicles, int fleetRuns) {
        this.out = out;
        this.vehicles = vehicles;
        this.fleetRuns = fleetRuns;
    }
    /**
     * The fleet page as a browser loads it, timed: fleet.html and the files it and its modules
     * name, {@code /api/session}, the WebSocket, {@code ?mailboxes} (the list is drawn: the page is
     * usable), then a {@code ?watch} for each vehicle one after another, as fleet.js does.
     */
    void run(WebWatchers.Page page, int httpPort) throws Exception {
        HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
        String base = "http://localhost:" + httpPort;
        double[] listed = new double[fleetRuns];
        double[] watched = new double[fleetRuns];
        int shown = 0;
        int refused = 0;
        String whyRefused = "";
        for (int run = 0; run < fleetRuns; run++) {
            long t0 = System.nanoTime();
            Set<String> files = new LinkedHashSet<>(List.of("/fleet.html"));
            Set<String> fetched = new LinkedHashSet<>();
            while (fetched.size() < files.size()) {
                for (String f : List.copyOf(files)) {
                    if (fetched.add(f)) {
                        String body = get(http, base + f, page.cookie());
                        Matcher m = Pattern.compile("(?:src|href)=\"(/?[\\w./-]+\\.(?:js|css))\"|from '\\./([\\w.-]+\\.js)'").matcher(body);
                        while (m.find()) {
                            String name = m.group(1) != null ? m.group(1) : m.group(2);
                            files.add(name.startsWith("/") ? name : "/" + name);
                        }
                    }
                }
            }
            get(http, base + "/api/session", page.cookie());
            Replies replies = new Replies();
            WebSocket ws = http.newWebSocketBuilder().header("Cookie", page.cookie()).header("Origin", page.origin())
                    .buildAsync(URI.create("ws://localhost:" + httpPort + "/ws"), replies).get(20, TimeUnit.SECONDS);
            try {
                ws.sendText(request(1, "?mailboxes", page.csrf()), true).join();
                String list = replies.reply(1, true);
                Matcher boxes = Pattern.compile("\"address\":\"([^\"]+)\"").matcher(list);
                List<String> mailboxes = new ArrayList<>();
                while (boxes.find()) {
                    mailboxes.add(boxes.group(1));
                }
                listed[run] = (System.nanoTime() - t0) / 1e6;
                long id = 2;
                refused = 0;
                for (String b : mailboxes) { // all sent at once, as fleet.js sends them
                    ws.sendText(request(id++, "?watch " + b, page.csrf()), true).join();
                }
                for (long r = 2; r < id; r++) {
                    String w = replies.reply(r, false); // a refusal, as fleet.js takes it: that vehicle is not live
                    if (!w.contains("\"status\":\"OK\"")) {
                        refused++;
                        whyRefused = w.replaceAll(".*\"text\":\"([^\"]*)\".*", "$1");
                    }
                }
                watched[run] = (System.nanoTime() - t0) / 1e6;
                shown = mailboxes.size();
            } finally {
                ws.sendClose(WebSocket.NORMAL_CLOSURE, "done").join();
            }
        }
        Arrays.sort(listed);
        Arrays.sort(watched);
        out.printf("fleet page, %d vehicles (%d MailBoxes listed; measured as the page loads it: %s, /api/session, the WebSocket,"
                        + " ?mailboxes, then one ?watch per MailBox; not in a browser): list drawn median %.0f ms (max %.0f),"
                        + " every vehicle watched median %.0f ms (max %.0f) over %d loads (target: interactive under 1 s)%n",
                vehicles, shown, "fleet.html and its files", listed[fleetRuns / 2], listed[fleetRuns - 1], watched[fleetRuns / 2],
                watched[fleetRuns - 1], fleetRuns);
        if (refused > 0) {
            out.printf("  %d of the %d ?watch requests refused (\"%s\"): the page shows those vehicles from ?mailboxes but not live%n",
                    refused, shown, whyRefused);
        }
    }

    private static String request(long id, String body, String csrf) {
        return "{\"id\":" + id + ",\"mailbox\":\"\",\"body\":\"" + body + "\",\"csrf\":\"" + csrf + "\"}";
    }

    /** The fleet page's socket: whole text messages as they come. */
    private static final class Replies implements WebSocket.Listener {
        private static final Pattern FINAL_REPLY = Pattern.compile("\"type\":\"reply\".*?\"id\":(\\d+),|\"id\":(\\d+),.*?\"type\":\"reply\"");
        final LinkedBlockingQueue<String> messages = new LinkedBlockingQueue<>();
        private final Map<Long, String> early = new HashMap<>();
        private final StringBuilder partial = new StringBuilder();

        @Override
        public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
            partial.append(data);
            if (last) {
                messages.add(partial.toString());
                partial.setLength(0);
            }
            webSocket.request(1);
            return CompletableFuture.completedFuture(null);
        }

        /** The final reply to request {@code id}; with {@code mustBeOk}, an exception unless it is OK. */
        String reply(long id, boolean mustBeOk) throws Exception {
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            String m = early.remove(id);
            while (m == null && System.nanoTime() < end) {
                String next = messages.poll(1, TimeUnit.SECONDS);
                Matcher final_ = next == null ? null : FINAL_REPLY.matcher(next);
                if (final_ != null && final_.find() && !next.contains("\"status\":\"PROGRESS\"")) {
                    long to = Long.parseLong(final_.group(1) != null ? final_.group(1) : final_.group(2));
                    if (to == id) {
                        m = next;
                    } else {
                        early.put(to, next); // requests are answered in any order
                    }
                }
            }
            if (m != null) {
                if (mustBeOk && !m.contains("\"status\":\"OK\"")) {
                    throw new IOException("request " + id + " refused: " + m);
                }
                return m;
            }
            throw new IOException("no reply to request " + id + " within 30 s");
        }
    }

    static String get(HttpClient http, String url, String cookie) throws Exception {
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(URI.create(url)).header("Cookie", cookie).timeout(Duration.ofSeconds(30))
                .build(), HttpResponse.BodyHandlers.ofString());
        if (r.statusCode() != 200) {
            throw new IOException("GET " + url + ": " + r.statusCode());
        }
        return r.body();
    }
}
