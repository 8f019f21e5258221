package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.EmbeddedStateStore;

/**
 * A closing hub takes no more entries: one that came in between closing the vehicle states and
 * closing the transcript had its line stored and its state lost. Refused, the service keeps the
 * entries and offers them to the next server, which also finds the state saved before.
 */
class ConsoleHubCloseTest {
    static final String SERVICE = "<SerialPortServer>::<shore>";
    static final String RU29 = SERVICE + "ru29";

    @TempDir
    Path data;

    @Test
    void entriesOfferedToAClosedHubAreRefusedAndTheStateBeforeItIsKept() throws Exception {
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            ConsoleHub hub = new ConsoleHub(data.resolve("transcripts"), store, 90, m -> new byte[0]);
            hub.publish(SERVICE, List.of(ConsoleEntry.event(RU29, VehicleEvent.SURFACED, "", 41.5, -70.5),
                    ConsoleEntry.line(RU29, "before the close")));
            hub.close();

            assertThatThrownBy(() -> hub.publish(SERVICE, List.of(ConsoleEntry.line(RU29, "after the close"))))
                    .isInstanceOf(IllegalStateException.class).hasMessageContaining("not taken");

            ConsoleHub next = new ConsoleHub(data.resolve("transcripts"), store, 90, m -> new byte[0]);
            assertThat(next.state(RU29).state()).isEqualTo(SessionState.State.ON_CALL);
            next.close();
        }
    }
}
