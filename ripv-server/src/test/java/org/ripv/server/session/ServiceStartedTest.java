package org.ripv.server.session;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.SessionState;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.EmbeddedStateStore;

/**
 * A new instance of a service ends the calls the server still has open from before it started,
 * and only those: its own, well-formed MailBoxes, from the list it gave (which is its word only).
 */
class ServiceStartedTest {
    static final String SERVICE = "<SerialPortServer>::<shore>";
    static final String RU29 = SERVICE + "ru29";
    static final String RU30 = SERVICE + "ru30";
    static final String OTHER = "<SerialPortServer>::<elsewhere>ru31";

    @TempDir
    Path data;

    @Test
    void callsFromBeforeTheInstanceStartedAreLostAndNoOthers() throws Exception {
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            ConsoleHub hub = new ConsoleHub(data.resolve("transcripts"), store, 90, m -> new byte[0]);
            hub.publish(SERVICE, List.of(ConsoleEntry.event(RU29, VehicleEvent.SURFACED, "", null, null),
                    ConsoleEntry.event(RU30, VehicleEvent.SURFACED, "", null, null)));
            hub.publish("<SerialPortServer>::<elsewhere>", List.of(ConsoleEntry.event(OTHER, VehicleEvent.SURFACED, "", null, null)));
            long started = System.currentTimeMillis() + 1;
            Thread.sleep(5);
            hub.publish(SERVICE, List.of(ConsoleEntry.line(RU30, "heard after the new instance started")));

            List<String> claimed = new ArrayList<>(List.of(RU29, RU30, OTHER, SERVICE + "../../etc", "not an address", RU29));
            for (int i = 0; i < 5_000; i++) {
                claimed.add(SERVICE + "junk" + i); // more than a service may have: the rest is not looked up
            }
            claimed.add(null);
            assertThat(ConsoleHub.claimed(SERVICE, claimed)).hasSize(ConsoleHub.MAX_MAILBOXES_PER_SERVICE)
                    .contains(RU29, RU30).doesNotContain(OTHER, "not an address").doesNotHaveDuplicates();
            List<ConsoleEntry> lost = hub.serviceStarted(SERVICE, started, claimed);

            assertThat(lost).extracting(ConsoleEntry::mailbox).containsExactly(RU29);
            assertThat(lost.get(0).event()).isEqualTo(VehicleEvent.LINK_LOST);
            assertThat(hub.state(RU29).state()).isEqualTo(SessionState.State.LOST);
            assertThat(hub.state(RU30).state()).isEqualTo(SessionState.State.ON_CALL); // heard since
            assertThat(hub.state(OTHER).state()).isEqualTo(SessionState.State.ON_CALL); // not this service's
            assertThat(hub.serviceStarted(SERVICE, 0, List.of(RU30))).isEmpty(); // an older service: not given
            hub.close();
        }
    }

    @Test
    void callsAreCountedPerRunOfTheServiceAndARegistrationOfTheSameRunKeepsTheCount() throws Exception {
        try (EmbeddedStateStore store = new EmbeddedStateStore(data, 1 << 20)) {
            ConsoleHub hub = new ConsoleHub(data.resolve("transcripts"), store, 90, m -> new byte[0]);
            long first = System.currentTimeMillis() - 10_000;
            hub.serviceStarted(SERVICE, first, List.of(RU29));
            assertThat(hub.state(RU29)).as("nothing heard yet").isNull();
            for (int i = 0; i < 3; i++) {
                hub.publish(SERVICE, List.of(ConsoleEntry.event(RU29, VehicleEvent.SURFACED, "", null, null)));
                Thread.sleep(2);
                hub.publish(SERVICE, List.of(ConsoleEntry.event(RU29, VehicleEvent.DIVED, "", null, null)));
                Thread.sleep(2);
            }
            assertThat(hub.state(RU29).calls()).isEqualTo(3);
            hub.serviceStarted(SERVICE, first, List.of(RU29)); // the same instance again (the server restarted)
            assertThat(hub.state(RU29).calls()).isEqualTo(3);
            hub.serviceStarted(SERVICE, System.currentTimeMillis(), List.of(RU29)); // a new run of the service
            assertThat(hub.state(RU29).calls()).isZero();
            assertThat(hub.state(RU29).state()).isEqualTo(SessionState.State.DIVED);
            hub.publish(SERVICE, List.of(ConsoleEntry.event(RU29, VehicleEvent.SURFACED, "", null, null)));
            assertThat(hub.state(RU29).calls()).as("call 1 of this run, as the service says").isEqualTo(1);
            // The server squares its calls with a new instance in the background: a call taken before that still counts.
            Thread.sleep(2); // the third instance starts after the last call (in another millisecond)
            long third = System.currentTimeMillis();
            Thread.sleep(2);
            hub.publish(SERVICE, List.of(ConsoleEntry.event(RU29, VehicleEvent.SURFACED, "", null, null)));
            hub.serviceStarted(SERVICE, third, List.of(RU29));
            assertThat(hub.state(RU29).calls()).isEqualTo(1);
            hub.close();
        }
    }
}
