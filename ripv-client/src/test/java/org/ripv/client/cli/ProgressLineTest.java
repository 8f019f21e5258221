package org.ripv.client.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.ripv.messages.Progress;

/** The CLI's PROGRESS line shows rate and time left when they are known. */
class ProgressLineTest {
    @Test
    void aTransferShowsPercentRateAndEta() {
        assertThat(ReplyPrinter.progressLine(new Progress("receiving MISSION1.LOG", 20480, 51200, 11200)))
                .isEqualTo("receiving MISSION1.LOG 20480/51200 (40%) 11.2 kB/s ETA 0:03");
        assertThat(ReplyPrinter.progressLine(new Progress("sending goto_l10.ma", 0, 102400, 0)))
                .isEqualTo("sending goto_l10.ma 0/102400 (0%)");
        assertThat(ReplyPrinter.progressLine(new Progress("rows", 12, -1, 830)))
                .isEqualTo("rows 12 830 B/s");
    }

    @Test
    void etaIsMinutesAndSecondsOrHours() {
        assertThat(new Progress("x", 0, 11520 * 72, 11520).etaText()).isEqualTo("1:12");
        assertThat(new Progress("x", 0, 3723, 1).etaText()).isEqualTo("1:02:03");
        assertThat(new Progress("x", 40, 100, 10).shortText()).isEqualTo("40 % ETA 0:06");
        assertThat(new Progress("x", 40, -1, 10).shortText()).isEmpty();
    }
}
