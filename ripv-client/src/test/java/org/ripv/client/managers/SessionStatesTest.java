package org.ripv.client.managers;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;

/**
 * What is news to a vehicle's state is decided by the console's sequence numbers: two events of
 * one millisecond are both taken, and a replay of counted entries is not counted again.
 */
class SessionStatesTest {
    static final String BOX = "<SerialPortServer>::<localhost>sim01";
    static final long MS = 1_790_000_000_000L;

    static ConsoleEntry event(VehicleEvent ev, long time, long seq) {
        return new ConsoleEntry(time, BOX, ConsoleEntry.Kind.EVENT, "", ev.name(), ev, null, null, seq);
    }

    @Test
    void surfacedAndDivedInOneMillisecondAreBothTaken() {
        SessionState known = new SessionState(SessionState.State.DIVED, MS - 5000, null, null, 3, VehicleEvent.DIVED,
                MS * 1000 - 7);
        SessionState s = SessionStates.apply(known, event(VehicleEvent.SURFACED, MS, MS * 1000));
        s = SessionStates.apply(s, event(VehicleEvent.DIVED, MS, MS * 1000 + 1));
        assertThat(s.state()).isEqualTo(SessionState.State.DIVED);
        assertThat(s.calls()).isEqualTo(4);
        assertThat(s.lastSeq()).isEqualTo(MS * 1000 + 1);

        // a SURFACED made in the very millisecond the server's state was taken, after it
        SessionState server = new SessionState(SessionState.State.DIVED, MS, null, null, 4, VehicleEvent.DIVED, MS * 1000 + 1);
        SessionState again = SessionStates.apply(server, event(VehicleEvent.SURFACED, MS, MS * 1000 + 2));
        assertThat(again.state()).isEqualTo(SessionState.State.ON_CALL);
        assertThat(again.calls()).isEqualTo(5);
    }

    @Test
    void aReplayOfCountedEntriesCountsNothing() {
        ConsoleEntry surfaced = event(VehicleEvent.SURFACED, MS, MS * 1000);
        ConsoleEntry dived = event(VehicleEvent.DIVED, MS, MS * 1000 + 1);
        SessionState s = SessionStates.apply(SessionStates.apply(null, surfaced), dived);
        // a watch replays the recent entries: an entry one millisecond later but already counted
        // by number is no news, and neither is either event again
        assertThat(SessionStates.apply(s, surfaced)).isSameAs(s);
        assertThat(SessionStates.apply(s, dived)).isSameAs(s);
        assertThat(s.calls()).isEqualTo(1);
    }

    @Test
    void withoutNumbersTheTimeStillDecides() {
        SessionState s = new SessionState(SessionState.State.ON_CALL, MS, null, null, 1, VehicleEvent.SURFACED);
        assertThat(SessionStates.apply(s, event(VehicleEvent.DIVED, MS - 1, 0))).isSameAs(s);
        assertThat(SessionStates.apply(s, event(VehicleEvent.DIVED, MS + 1, 0)).state()).isEqualTo(SessionState.State.DIVED);
    }
}
