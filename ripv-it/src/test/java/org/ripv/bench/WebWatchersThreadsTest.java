package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import java.nio.channels.SocketChannel;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.it.TestSystem;
import org.ripv.server.ServerConfig;
import org.ripv.service.ServiceConnector;
import org.junit.jupiter.api.parallel.Isolated;

/**
 * A web console page is a Post Office client with no thread and no loopback socket of its own
 * (issue 21, speed and scale): 500 WebSocket watchers of one vehicle add a bounded handful of
 * threads to the server, every one of them gets each line, and a page that never reads is held to
 * its bound — the server keeps at most the watcher's backlog for it and marks the lines it skipped —
 * while a page that reads still gets its lines. Before, each page was a loopback connection adopted
 * as a client, with a reader thread in the server and one in the web package: 1,000 threads here.
 */
@Isolated // counts this JVM's threads: another class's server would add its own
class WebWatchersThreadsTest {
    static final int PAGES = 500;

    @TempDir
    Path dir;

    @Test
    void fiveHundredPagesCostNoThreadEachAndAPageThatNeverReadsIsBounded() throws Exception {
        ServerConfig config = ServerConfig.forTests(dir.resolve("server")).plain().withPorts(0, 0, 0).withMaxClients(PAGES + 50);
        // every page is one log-in's here: the operator lets one user open them all (--web-pages)
        config = config.withSecurity(config.security().withWebPages(4 * PAGES));
        try (TestSystem sys = TestSystem.start(config)) {
            sys.user("watcher", "observers");
            VehicleConsoleService vehicle = new VehicleConsoleService("localhost", "ru29");
            ServiceConnector link = sys.register(vehicle);
            try (WebWatchers readers = new WebWatchers(2)) {
                WebWatchers.Page page = WebBench.login(sys.server().httpPort(), "watcher", TestSystem.PASSWORD);
                String box = vehicle.mailbox();
                readers.add(page, box, n -> { }); // the first opens Jetty's own threads and the hub's
                int before = ManagementFactory.getThreadMXBean().getThreadCount();
                AtomicLongArray seen = new AtomicLongArray(PAGES);
                for (int i = 0; i < PAGES; i++) {
                    int k = i;
                    readers.add(page, box, n -> seen.incrementAndGet(k));
                }
                int after = ManagementFactory.getThreadMXBean().getThreadCount();
                assertThat(after - before).as("threads for " + PAGES + " more pages (was 2 per page)").isLessThan(40);
                assertThat(threadsNamed("ripv-socket-handler-") + threadsNamed("ripv-web-link-")).isZero();

                vehicle.line("bench 0 " + System.nanoTime());
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (System.nanoTime() < until && count(seen) < PAGES) {
                    Thread.sleep(100);
                }
                assertThat(count(seen)).as("pages that got the line").isEqualTo(PAGES);
            }

            // One page stops reading; one keeps reading. A flood the stalled one's socket cannot hold.
            WebWatchers.Page page = WebBench.login(sys.server().httpPort(), "watcher", TestSystem.PASSWORD);
            SocketChannel stalled = WebWatchers.stalled(page, vehicle.mailbox());
            try (WebWatchers readers = new WebWatchers(1)) {
                AtomicLong lastSeen = new AtomicLong(-1);
                readers.add(page, vehicle.mailbox(), n -> lastSeen.set(n));
                // only these two watch now (the 501 pages above have gone), so what is skipped is theirs
                long gone = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (sys.server().console().watcherCount() != 2 && System.nanoTime() < gone) {
                    Thread.sleep(50);
                }
                assertThat(sys.server().console().watcherCount()).as("watchers: the stalled page and the reading one").isEqualTo(2);
                String pad = "x".repeat(1000);
                // Until the server has skipped lines for the stalled page: beside a busy machine the
                // service's own queue drops some of a flood (and says so), so a fixed count may never
                // get past the page's socket and backlog, and then there is nothing to be told.
                long floodEnd = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
                int flooded = 0;
                while (sys.server().console().skippedTotal() == 0 && System.nanoTime() < floodEnd && flooded < 200_000) {
                    for (int i = 0; i < 2_000; i++) {
                        vehicle.line("flood " + flooded++ + " " + pad);
                    }
                    Thread.sleep(100); // within the service's own publishing queue
                }
                assertThat(sys.server().console().skippedTotal()).as("lines the server skipped for the page that never reads, after "
                        + flooded + " lines of 1 KB").isPositive();
                // Again every 2 s until it arrives: right after a flood the service's own bounded
                // publishing queue may still be full and drop a line (and say so), before any server sees it.
                long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                long resend = 0;
                while (System.nanoTime() < end && lastSeen.get() < 0) {
                    if (System.nanoTime() >= resend) {
                        vehicle.line("bench 1 " + System.nanoTime());
                        resend = System.nanoTime() + TimeUnit.SECONDS.toNanos(2);
                    }
                    Thread.sleep(50);
                }
                assertThat(lastSeen.get()).as("the reading page got the line after the flood").isGreaterThanOrEqualTo(0);
                assertThat(sys.server().console().backlogTotal()).as("entries the server holds for the page that never reads")
                        .isLessThanOrEqualTo(2_000);

                WebWatchers.Conn resumed = readers.resume(stalled, n -> { });
                long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (System.nanoTime() < until && resumed.markers == 0 && !resumed.closed) {
                    vehicle.line("after");
                    Thread.sleep(200);
                }
                assertThat(resumed.markers > 0 || resumed.closed).as("the page that never read is told what it missed, or cut off"
                        + " (it read " + resumed.frames + " frames after it resumed; the server skipped " + sys.server().console().skippedTotal()
                        + " lines and holds " + sys.server().console().backlogTotal() + ")").isTrue();
            }
            link.close();
            vehicle.stop();
        }
    }

    private static long count(AtomicLongArray seen) {
        long n = 0;
        for (int i = 0; i < seen.length(); i++) {
            n += seen.get(i) > 0 ? 1 : 0;
        }
        return n;
    }

    private static long threadsNamed(String prefix) {
        return Thread.getAllStackTraces().keySet().stream().filter(t -> t.getName().startsWith(prefix)).count();
    }
}
