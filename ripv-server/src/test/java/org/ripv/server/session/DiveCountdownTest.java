package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.EmbeddedStateStore;

/** The vehicle state's diveAt: set by the dialog's countdown, moved by each tick, cleared when the call ends. */
class DiveCountdownTest {
    static final String RU29 = "<SerialPortServer>::<shore>ru29";

    @TempDir
    Path data;

    @Test
    void theCountdownSetsDiveAtAndTheCallsEndClearsIt() {
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            VehicleStates states = new VehicleStates(store);
            states.apply(new ConsoleEntry(1000, RU29, ConsoleEntry.Kind.EVENT, "", "call 1", VehicleEvent.SURFACED, null, null));
            assertThat(states.state(RU29).diveAt()).isZero();
            states.apply(ConsoleEntryAt(2000, "Hit Control-R to RESUME the mission, or Control-C to abort it"));
            assertThat(states.state(RU29).diveAt()).isZero(); // not the countdown
            states.apply(ConsoleEntryAt(3000, "Hit Control-C within 50 seconds to abort the mission..."));
            assertThat(states.state(RU29).diveAt()).isEqualTo(53_000);
            states.apply(ConsoleEntryAt(13_000, "Hit Control-C within 40 seconds to abort the mission..."));
            assertThat(states.state(RU29).diveAt()).isEqualTo(53_000);
            states.apply(ConsoleEntryAt(14_000, "   sensor:hit_control_c_within(s)=99"));
            assertThat(states.state(RU29).diveAt()).isEqualTo(53_000);
            states.apply(new ConsoleEntry(20_000, RU29, ConsoleEntry.Kind.EVENT, "", "the caller hung up", VehicleEvent.DIVED, null, null));
            assertThat(states.state(RU29).diveAt()).isZero();
            states.close();
        }
    }

    private static ConsoleEntry ConsoleEntryAt(long time, String text) {
        return new ConsoleEntry(time, RU29, ConsoleEntry.Kind.LINE, "", text, null, null, null);
    }
}
