package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** "No slower than lrzsz" is read from the medians of paired rows, RIPV's first in each pair. */
class ZmodemBenchVersusTest {
    private static ZmodemBench.Row row(String pair, double seconds) {
        return new ZmodemBench.Row(pair, 115200, 1000, seconds, 0, 0, true);
    }

    @Test
    void ripvSlowerOnTheMedianIsSaidSoEvenWhenOneRoundWasFaster() {
        List<ZmodemBench.Row> pairs = List.of(row("RIPV → rz", 96.00), row("sz → rz", 96.10),
                row("RIPV → rz", 96.30), row("sz → rz", 96.00), row("RIPV → rz", 96.20), row("sz → rz", 96.05));
        assertThat(ZmodemBench.versus("RIPV's sender", "sz", pairs))
                .isEqualTo("RIPV's sender against sz on the same link, median of 3: 96.20 s against 96.05 s (SLOWER by 0.16 %)");
    }

    @Test
    void ripvFasterOnTheMedian() {
        List<ZmodemBench.Row> pairs = List.of(row("RIPV → rz", 96.00), row("sz → rz", 96.03), row("RIPV → rz", 96.02),
                row("sz → rz", 96.05));
        assertThat(ZmodemBench.versus("RIPV's sender", "sz", pairs)).endsWith("96.01 s against 96.04 s (faster by 0.03 %)");
    }

}
