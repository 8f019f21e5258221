package org.ripv.it;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.bench.CallsBench;
import org.junit.jupiter.api.parallel.ResourceLock;

/** 100 vehicles call 100 listen:// links within 20 s, each for a few seconds: all taken and streamed. */
@ResourceLock(Shared.CPU)
class ManyCallsTest {
    @TempDir
    Path dir;

    @Test
    void aHundredVehiclesCallingInAreAllAcceptedAndStreamedInOrder() throws Exception {
        // Earlier tests in this JVM should have stopped their links; one that still redials is named
        // here, since it is what once took a vehicle's port (CallsBench.ADDRESS).
        Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.getName().startsWith("serial-link-monitor") || t.getName().startsWith("glider-simulator"))
                .forEach(t -> System.err.println("ManyCallsTest: still running from an earlier test: " + t.getName()));
        CallsBench.Result r = CallsBench.run(100, Duration.ofSeconds(20), Duration.ofSeconds(4), 10, dir);
        assertThat(r.surfaced()).as(r.toString()).isEqualTo(100);
        assertThat(r.surfacedWithPosition()).as(r.toString()).isEqualTo(100);
        assertThat(r.dived()).as(r.toString()).isEqualTo(100);
        assertThat(r.linesSent()).as(r.toString()).isGreaterThan(100 * 30);
        assertThat(r.linesSeen()).as(r.toString()).isEqualTo(r.linesSent());
        assertThat(r.skipped()).as(r.toString()).isZero();
        assertThat(r.outOfOrder()).as(r.toString()).isZero();
    }
}
