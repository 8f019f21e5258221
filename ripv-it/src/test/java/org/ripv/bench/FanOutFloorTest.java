package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/**
 * The console benchmark's yardstick reads what it is sent: every line reaches every socket once,
 * across several reader threads, with the delay taken from the line (real loopback sockets).
 */
class FanOutFloorTest {
    @Test
    void everyLineReachesEverySocketOnceWithItsDelay() throws Exception {
        List<ConsoleBench.Watch> ws = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            ConsoleBench.Watch w = new ConsoleBench.Watch(() -> { }, 100, null);
            w.recording = true;
            ws.add(w);
        }
        AtomicLong lastSent = new AtomicLong();
        try (FanOutFloor f = new FanOutFloor(ws, 2, 3, 480)) {
            for (int i = 0; i < 40; i++) {
                long now = System.nanoTime();
                lastSent.set(now);
                f.line("bench " + i + " " + now);
                Thread.sleep(2);
            }
            long end = System.nanoTime() + 10_000_000_000L;
            while (System.nanoTime() < end && ws.stream().anyMatch(w -> w.n.get() < 40)) {
                Thread.sleep(20);
            }
        }
        for (ConsoleBench.Watch w : ws) {
            assertThat(w.n.get()).isEqualTo(40);
            for (int i = 0; i < 40; i++) {
                assertThat(w.delays[i]).isBetween(0L, 10_000_000L); // microseconds: read after sent, within 10 s
            }
        }
    }

    @Test
    void aFrameLargerThanTheReadBufferIsReadWhole() throws Exception {
        List<ConsoleBench.Watch> ws = List.of(new ConsoleBench.Watch(() -> { }, 10, null));
        ws.get(0).recording = true;
        try (FanOutFloor f = new FanOutFloor(ws, 1, 1, 200_000)) { // three reads' worth, kept across them
            f.line("bench 1 " + System.nanoTime());
            f.line("bench 2 " + System.nanoTime());
            long end = System.nanoTime() + 10_000_000_000L;
            while (System.nanoTime() < end && ws.get(0).n.get() < 2) {
                Thread.sleep(20);
            }
        }
        assertThat(ws.get(0).n.get()).isEqualTo(2);
    }
}
