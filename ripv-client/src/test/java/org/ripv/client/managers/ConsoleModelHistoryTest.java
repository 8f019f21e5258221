package org.ripv.client.managers;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ConsoleBatch;
import org.ripv.messages.ConsoleEntry;

/**
 * Scrolling back: the transcript's copy of an entry carries no console number while the live
 * replay's does, and a burst of lines shares one millisecond; the older lines still join once, in
 * order (ConsoleGuiTest saw 20 of 31 in a clean-clone run).
 */
class ConsoleModelHistoryTest {
    static final String BOX = "<SerialPortServer>::<localhost>ru29";

    @Test
    void theTranscriptMeetsTheNumberedReplayInOneMillisecond() {
        long ms = 1_790_000_000_000L;
        List<ConsoleEntry> transcript = new ArrayList<>();
        for (int i = 0; i < 31; i++) {
            transcript.add(new ConsoleEntry(ms, BOX, ConsoleEntry.Kind.LINE, "", "line " + i, null, null, null));
        }
        List<ConsoleEntry> replay = transcript.subList(11, 31).stream().map(e -> e.withSeq(1000 + e.text().length())).toList();
        ConsoleModel model = new ConsoleModel();
        model.add(new ConsoleBatch(BOX, replay, 0, false));

        model.addHistory(new ConsoleBatch(BOX, transcript, 0, false));
        model.addHistory(new ConsoleBatch(BOX, transcript, 0, false));

        assertThat(model.entries(BOX)).extracting(ConsoleEntry::text).hasSize(31).doesNotHaveDuplicates()
                .startsWith("line 0", "line 1").endsWith("line 30");
    }
}
