package org.ripv.messages;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/** The rules the server's and the clients' vehicle states both follow (docs/sessions.md "State"). */
class VehicleEventRulesTest {
    @Test
    void theCallsLife() {
        assertThat(VehicleEvent.SURFACED.callState()).isEqualTo(SessionState.State.ON_CALL);
        assertThat(VehicleEvent.DIVED.callState()).isEqualTo(SessionState.State.DIVED);
        assertThat(VehicleEvent.LINK_LOST.callState()).isEqualTo(SessionState.State.LOST);
        assertThat(Arrays.stream(VehicleEvent.values()).filter(e -> e.callState() != null)).hasSize(3);
        assertThat(Arrays.stream(VehicleEvent.values()).filter(VehicleEvent::startsCall)).containsExactly(VehicleEvent.SURFACED);
    }

    @Test
    void contactsAreWhatTheVehicleItselfSaidOrDid() {
        assertThat(Arrays.stream(VehicleEvent.values()).filter(VehicleEvent::fromVehicle)).containsExactlyInAnyOrder(
                VehicleEvent.SURFACED, VehicleEvent.DIVED, VehicleEvent.ALERT, VehicleEvent.TRANSFER_DONE, VehicleEvent.TRANSFER_FAILED);
        assertThat(ConsoleEntry.line("<S>::<h>ru29", "GPS").isContact()).isTrue();
        assertThat(ConsoleEntry.command("<S>::<h>ru29", "alice", "dir").isContact()).isFalse();
        assertThat(Arrays.stream(VehicleEvent.values()).filter(VehicleEvent::endsWorkflow)).containsExactlyInAnyOrder(
                VehicleEvent.WORKFLOW_DONE, VehicleEvent.WORKFLOW_DONE_WITH_ERRORS, VehicleEvent.WORKFLOW_FAILED);
    }
}
