package org.ripv.retry;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.Duration;
import org.junit.jupiter.api.Test;

class BackoffTest {
    @Test
    void doublesUpToTheMostAndStartsAgainAfterASuccess() {
        Backoff b = new Backoff(Duration.ofMillis(500), Duration.ofMillis(5000));
        long[] waits = new long[7];
        for (int i = 0; i < waits.length; i++) {
            waits[i] = b.nextMillis();
        }
        assertThat(waits).containsExactly(500, 1000, 2000, 4000, 5000, 5000, 5000);
        b.reset();
        assertThat(b.nextMillis()).isEqualTo(500);
    }

    @Test
    void refusesAWaitThatCannotGrow() {
        assertThatThrownBy(() -> new Backoff(Duration.ZERO, Duration.ofSeconds(1))).isInstanceOf(IllegalArgumentException.class);
        assertThatThrownBy(() -> new Backoff(Duration.ofSeconds(2), Duration.ofSeconds(1))).isInstanceOf(IllegalArgumentException.class);
    }
}
