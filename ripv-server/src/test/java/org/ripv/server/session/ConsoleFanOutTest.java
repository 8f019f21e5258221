package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.OutgoingServerMessage;
import org.ripv.server.store.EmbeddedStateStore;

/**
 * A MailBox with many watchers gets each line written by several threads (issue 38): every
 * watcher still gets every line once, in the order taken, while lines come from several threads at
 * once and watchers join and leave meanwhile; and the service is answered only once its lines are
 * with every page.
 */
class ConsoleFanOutTest {
    static final String SERVICE = "<SerialPortServer>::<shore>";
    static final String RU29 = SERVICE + "ru29";

    /** A client connection that records the text of every line pushed to it, and the threads that pushed. */
    static final class Recorder implements Outlet {
        final List<String> lines = new ArrayList<>();
        final Set<String> threads = ConcurrentHashMap.newKeySet();
        /** True for a client that writes the server's frames (a socket), false for a web page. */
        final boolean encodes;

        Recorder(boolean encodes) {
            this.encodes = encodes;
        }

        @Override
        public synchronized boolean push(OutgoingServerMessage message, java.util.function.Supplier<byte[]> frame, Runnable written) {
            threads.add(Thread.currentThread().getName());
            if (encodes) {
                assertThat(frame.get()).isNotNull();
            }
            ConsoleBatch b = (ConsoleBatch) message.footer().result();
            b.entries().forEach(e -> lines.add(e.text()));
            written.run();
            return true;
        }

        @Override
        public void send(OutgoingServerMessage reply) {
        }

        @Override
        public boolean isOpen() {
            return true;
        }

        synchronized List<String> lines() {
            return List.copyOf(lines);
        }
    }

    @TempDir
    Path data;

    @Test
    void manyWatchersGetEveryLineInOrderFromSeveralThreads() throws Exception {
        int watchers = ConsoleHub.INLINE_WATCHERS * 4;
        int lines = 300;
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            AtomicInteger encoded = new AtomicInteger();
            ConsoleHub hub = new ConsoleHub(data.resolve("transcripts"), store, 90, m -> {
                encoded.incrementAndGet();
                return new byte[1];
            });
            List<Recorder> rs = new ArrayList<>();
            for (int i = 0; i < watchers; i++) {
                Recorder r = new Recorder(i == 1 || i == watchers - 1); // two socket clients, the rest web pages
                rs.add(r);
                assertThat(hub.watch("c" + i, "u", RU29, r, (s, recent) -> null)).isNull();
            }
            // Two publishers at once, as two RMI threads (a service and the server's own events); each
            // numbers its lines, and each page must see each publisher's lines in its order.
            ExecutorService two = Executors.newFixedThreadPool(2);
            List<Future<?>> done = new ArrayList<>();
            for (String who : List.of("a", "b")) {
                done.add(two.submit(() -> {
                    for (int i = 0; i < lines; i++) {
                        hub.publish(SERVICE, List.of(ConsoleEntry.line(RU29, who + " " + i)));
                        if (who.equals("a") && i == lines / 2) {
                            hub.clientClosed("c3"); // a page leaves while lines are being written
                        }
                    }
                    return null;
                }));
            }
            for (Future<?> f : done) {
                f.get(60, TimeUnit.SECONDS);
            }
            two.shutdown();
            // publish returned, so every page has every line (the service is answered after the fan-out)
            for (int i = 0; i < watchers; i++) {
                List<String> got = rs.get(i).lines();
                if (i == 3) {
                    assertThat(got.size()).isLessThan(2 * lines);
                    continue;
                }
                assertThat(got).as("watcher %d", i).hasSize(2 * lines);
                for (String who : List.of("a", "b")) {
                    List<String> mine = got.stream().filter(l -> l.startsWith(who + " ")).toList();
                    assertThat(mine).as("watcher %d, publisher %s: in order", i, who)
                            .isEqualTo(java.util.stream.IntStream.range(0, lines).mapToObj(n -> who + " " + n).toList());
                }
            }
            assertThat(encoded.get()).as("each line encoded once for the socket clients, not per watcher")
                    .isEqualTo(2 * lines);
            assertThat(rs.get(0).threads).as("the first watchers are written on the taking thread")
                    .noneMatch(t -> t.startsWith("ripv-console-fanout"));
            if (Runtime.getRuntime().availableProcessors() > 1) {
                assertThat(rs.stream().flatMap(r -> r.threads.stream()).filter(t -> t.startsWith("ripv-console-fanout")))
                        .as("the watchers beyond the first %d are spread over the fan-out threads", ConsoleHub.INLINE_WATCHERS)
                        .isNotEmpty();
            }
            hub.close();
        }
    }
}
