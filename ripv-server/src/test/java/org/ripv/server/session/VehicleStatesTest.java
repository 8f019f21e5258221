package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.EmbeddedStateStore;

/** A vehicle's call state goes to the state store and back; a damaged saved state is ignored, not fatal. */
class VehicleStatesTest {
    static final String BOX = "<SerialPortServer>::<shore>ru29";

    @TempDir
    Path data;

    @Test
    void theStateOutlivesItsVehicleStatesAndADamagedOneIsIgnored() throws Exception {
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            VehicleStates first = new VehicleStates(store);
            first.apply(ConsoleEntry.event(BOX, VehicleEvent.SURFACED, "call 1", 41.6, -70.5));
            first.apply(ConsoleEntry.event(BOX, VehicleEvent.DIVED, "hung up", null, null));
            first.close(); // saves what waits

            SessionState back = new VehicleStates(store).state(BOX);
            assertThat(back.state()).isEqualTo(SessionState.State.DIVED);
            assertThat(back.calls()).isEqualTo(1);
            assertThat(back.lat()).isEqualTo(41.6);

            for (String junk : new String[] {"not json at all", "{\"state\":\"SUNK\"}", "{\"state\":", "\u0000\u0001"}) {
                store.saveVehicleState(BOX, junk);
                VehicleStates again = new VehicleStates(store);
                assertThat(again.state(BOX)).as(junk).isNull(); // as if nothing had been heard yet
                again.apply(ConsoleEntry.event(BOX, VehicleEvent.SURFACED, "call", null, null));
                assertThat(again.state(BOX).state()).isEqualTo(SessionState.State.ON_CALL);
                again.sync();
                assertThat(store.loadVehicleState(BOX)).get().asString().contains("\"ON_CALL\"");
                again.close();
            }
        }
    }
}
