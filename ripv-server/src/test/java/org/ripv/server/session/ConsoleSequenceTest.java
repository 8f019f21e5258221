package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.EmbeddedStateStore;

/**
 * The server numbers every console entry it takes: entries of one millisecond get different,
 * increasing numbers, a MailBox's state says up to which it counts, and a restarted server's
 * numbers continue above the old ones.
 */
class ConsoleSequenceTest {
    static final String SERVICE = "<SerialPortServer>::<shore>";
    static final String RU29 = SERVICE + "ru29";

    @TempDir
    Path data;

    @Test
    void entriesOfOneMillisecondAreNumberedInOrderAndAcrossARestart() throws Exception {
        long t = System.currentTimeMillis();
        ConsoleEntry surfaced = new ConsoleEntry(t, RU29, ConsoleEntry.Kind.EVENT, "", "", VehicleEvent.SURFACED, null, null);
        ConsoleEntry dived = new ConsoleEntry(t, RU29, ConsoleEntry.Kind.EVENT, "", "", VehicleEvent.DIVED, null, null);
        long before;
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            ConsoleHub hub = new ConsoleHub(data.resolve("transcripts"), store, 90, m -> new byte[0]);
            hub.publish(SERVICE, List.of(surfaced));
            SessionState first = hub.state(RU29);
            hub.publish(SERVICE, List.of(dived));
            SessionState second = hub.state(RU29);
            assertThat(first.lastSeq()).isPositive();
            assertThat(second.lastSeq()).isGreaterThan(first.lastSeq());
            assertThat(second.state()).isEqualTo(SessionState.State.DIVED);
            assertThat(second.calls()).isEqualTo(1);
            before = second.lastSeq();
            hub.close();
        }
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            ConsoleHub hub = new ConsoleHub(data.resolve("transcripts"), store, 90, m -> new byte[0]);
            hub.publish(SERVICE, List.of(new ConsoleEntry(t, RU29, ConsoleEntry.Kind.EVENT, "", "", VehicleEvent.SURFACED,
                    null, null)));
            assertThat(hub.state(RU29).lastSeq()).as("numbers go on above the last server's").isGreaterThan(before);
            hub.close();
        }
    }
}
