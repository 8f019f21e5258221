package org.ripv.services.serial;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;

/** SURFACED's wait for the GPS line, on a clock the test moves. */
class CallStateTest {
    static final long SECOND = 1_000_000_000L;
    static final GpsFix FIX = new GpsFix(41.6332, -70.5365);

    final List<ConsoleEntry> out = new ArrayList<>();
    final CallState call = new CallState("<SerialPortServer>::<h>v1", out::add);

    @Test
    void aDialogThatStartsLateAfterTheConnectStillGivesSurfacedItsPosition() {
        call.started("caller 127.0.0.1:4000", 0);
        call.tick(6 * SECOND); // a modem's carrier, or a stalled moment, before the first words
        call.heard(6 * SECOND);
        call.tick(7 * SECOND);
        call.position(FIX);

        assertThat(surfaced()).singleElement().satisfies(e -> assertThat(e.lat()).isEqualTo(FIX.lat()));
    }

    @Test
    void noGpsLineWithinTheWaitAfterTheFirstWordsGivesSurfacedWithoutAPosition() {
        call.started("caller 127.0.0.1:4000", 0);
        call.heard(SECOND);
        call.tick(5 * SECOND);
        assertThat(surfaced()).isEmpty();
        call.tick(6 * SECOND + 1);

        assertThat(surfaced()).singleElement().satisfies(e -> assertThat(e.lat()).isNull());
    }

    @Test
    void aCallerThatSaysNothingIsStillSurfacedAfterTheSilentWait() {
        call.started("caller 127.0.0.1:4000", 0);
        call.tick(29 * SECOND);
        assertThat(surfaced()).isEmpty();
        call.tick(30 * SECOND + 1);

        assertThat(surfaced()).hasSize(1);
    }

    @Test
    void onlyTheFirstWordsOfACallStartTheWait() {
        call.started("caller 127.0.0.1:4000", 0);
        call.heard(SECOND);
        call.heard(5 * SECOND); // later text does not push SURFACED further away
        call.tick(6 * SECOND + 1);

        assertThat(surfaced()).hasSize(1);
    }

    private List<ConsoleEntry> surfaced() {
        return out.stream().filter(e -> e.event() == VehicleEvent.SURFACED).toList();
    }
}
