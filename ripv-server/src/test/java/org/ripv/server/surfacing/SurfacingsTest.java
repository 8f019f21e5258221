package org.ripv.server.surfacing;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.messages.ConsoleEntry;
import org.ripv.messages.VehicleEvent;
import org.ripv.server.store.EmbeddedStateStore;

/** The surface-dialog reader on real-format dialogs (ripv-common's test data) with the embedded store. */
class SurfacingsTest {
    static final String RU29 = "<SerialPortServer>::<shore>ru29";
    static final Path DIALOGS = Path.of("../ripv-common/src/test/resources/org/ripv/surfacing");

    @TempDir
    Path data;
    private EmbeddedStateStore store;
    private Surfacings surfacings;
    private final List<ConsoleEntry> events = new CopyOnWriteArrayList<>();

    private Surfacings start() {
        store = new EmbeddedStateStore(data, 1 << 20);
        surfacings = new Surfacings(store, data.resolve("surfacing-alerts.conf"), events::add);
        return surfacings;
    }

    @AfterEach
    void stop() {
        if (surfacings != null) {
            surfacings.close();
        }
        if (store != null) {
            store.close();
        }
    }

    /** One call: SURFACED, the dialog's lines as the service publishes them, DIVED. */
    private void call(String dialog, long time) throws Exception {
        String text = Files.readString(DIALOGS.resolve(dialog), StandardCharsets.ISO_8859_1);
        long t = time;
        for (String line : text.split("\r\n")) {
            if (!line.isBlank()) {
                surfacings.accept(List.of(new ConsoleEntry(++t, RU29, ConsoleEntry.Kind.LINE, "", line, null, null, null)));
            }
            if (line.startsWith("GPS Location")) { // the service's SURFACED waits for the fix: in the middle of the dialog
                surfacings.accept(List.of(new ConsoleEntry(t, RU29, ConsoleEntry.Kind.EVENT, "", "call", VehicleEvent.SURFACED,
                        null, null)));
            }
        }
        surfacings.accept(List.of(new ConsoleEntry(t + 1000, RU29, ConsoleEntry.Kind.EVENT, "", "the caller hung up",
                VehicleEvent.DIVED, null, null)));
        surfacings.sync();
    }

    private List<String> alerts() {
        return events.stream().filter(e -> e.event() == VehicleEvent.ALERT).map(ConsoleEntry::text).toList();
    }

    @Test
    void aRoutineSurfacingIsARecordAndNoAlert() throws Exception {
        start();
        call("fw7-surface-interval.txt", 1_700_000_000_000L);
        List<Map<String, Object>> r = surfacings.last(RU29, 10);
        assertThat(r).hasSize(1);
        Map<String, Object> rec = r.get(0);
        assertThat(rec).containsEntry("time_utc", "2023-11-14T22:13:20.001Z").containsEntry("because",
                "Surface interval [behavior surface_2 start_when = 8]").containsEntry("mission", "sa_slope.mi")
                .containsEntry("battery_v", 14.6134148573529).containsEntry("leak", false).containsEntry("new_abort", false)
                .containsEntry("abort_total", 0).containsEntry("dives_in_s", 10).containsEntry("m_coulomb_amphr_total", 38.2140273)
                .containsEntry("c_wpt_lat", 3848.6).doesNotContainKey("m_battery");
        assertThat((Double) rec.get("gps_lat")).isCloseTo(38.874163, org.assertj.core.data.Offset.offset(1e-6));
        assertThat(events).isEmpty(); // the countdown text, "abort it" and the sensor names are not alerts
    }

    @Test
    void anAbortALeakAndMoreEachNameTheirCauseOnceARateLimit() throws Exception {
        start();
        call("fw7-surface-interval.txt", 1_700_000_000_000L);
        call("fw8-abort-overdepth.txt", 1_700_000_000_000L + 3 * 3_600_000L);
        Map<String, Object> rec = surfacings.last(RU29, 1).get(0);
        assertThat(rec).containsEntry("new_abort", true).containsEntry("abort_cause", "MS_ABORT_OVERDEPTH")
                .containsEntry("abort_details", "dive_to: depth 1012.3 > max depth 1000.0").containsEntry("prompt", "GliderDOS A 8");
        assertThat(alerts()).containsExactlyInAnyOrder(
                "new abort: MS_ABORT_OVERDEPTH: dive_to: depth 1012.3 > max depth 1000.0 at 2026-11-23T13:02:41 (3 since reset)",
                "surfaced because: Abort [MS_ABORT_OVERDEPTH]",
                "device errors grew from 0 to 2");
        ConsoleEntry abort = events.stream().filter(e -> e.text().startsWith("new abort")).findFirst().orElseThrow();
        assertThat(abort.lat()).isNotNull();
        events.clear();
        call("fw10-device-error-no-fix.txt", 1_700_000_000_000L + 6 * 3_600_000L);
        assertThat(alerts()).containsExactlyInAnyOrder("leak: m_leakdetect_voltage_aft 1.21 V, below 2.00 V",
                "battery 10.42 V, below 10.50 V", "vacuum 3.18 inHg, outside 4.00-11.00 inHg",
                "no valid fix: GPS TooFar:   69696969.000 N 69696969.000 E measured     1e+308 secs ago; GPS Invalid :  -3352.2911 N 15117.5102 E measured     31.220 secs ago");
        // "because" and "devices" alerted at the call before, moments ago: held back (alert.every, 30 min)
        assertThat(surfacings.last(RU29, 1).get(0)).containsEntry("leak", true).containsEntry("gps_lat", null)
                .containsEntry("new_abort", false);
        // the same trouble at the next calls: held back, then counted in the next alert of its cause
        events.clear();
        for (int i = 0; i < 5; i++) {
            call("fw10-device-error-no-fix.txt", 1_700_000_000_000L + (7 + i) * 3_600_000L);
        }
        assertThat(alerts()).isEmpty();
        assertThat(surfacings.last(RU29, 100)).hasSize(8);
    }

    @Test
    void thresholdsPerVehicleWithFleetDefaults() throws Exception {
        Files.writeString(data.resolve("surfacing-alerts.conf"), """
                # VEHICLE KEY VALUE
                *     battery.min   15.0
                ru29  battery.min   9.0
                ru29  leak.min      1.0
                *     vacuum.min    nonsense
                ru29  because.routine (?i)device error|surface interval|abort
                ru29  alert.every   1ms
                """);
        start();
        call("fw10-device-error-no-fix.txt", 1_700_000_000_000L);
        assertThat(alerts()).containsExactlyInAnyOrder("vacuum 3.18 inHg, outside 4.00-11.00 inHg",
                "no valid fix: GPS TooFar:   69696969.000 N 69696969.000 E measured     1e+308 secs ago; GPS Invalid :  -3352.2911 N 15117.5102 E measured     31.220 secs ago");
        Thread.sleep(5);
        call("fw10-device-error-no-fix.txt", 1_700_000_000_000L + 3_600_000L);
        assertThat(alerts()).hasSize(4); // alert.every 1ms: no rate limit for ru29
    }

    @Test
    void aVehicleThatDoesNotCallInTimeIsOverdueAndSaysSoWhenItCalls() throws Exception {
        Files.writeString(data.resolve("surfacing-alerts.conf"), "ru29 overdue 1s\n* overdue.grace 500ms\n");
        start();
        long t0 = System.currentTimeMillis();
        call("fw7-surface-interval.txt", t0);
        long end = System.nanoTime() + Duration.ofSeconds(10).toNanos();
        while (events.stream().noneMatch(e -> e.event() == VehicleEvent.OVERDUE) && System.nanoTime() < end) {
            Thread.sleep(50);
        }
        long at = System.currentTimeMillis();
        ConsoleEntry late = events.stream().filter(e -> e.event() == VehicleEvent.OVERDUE).findFirst().orElseThrow();
        assertThat(late.text()).startsWith("no call for").contains("expected every 1 s (its overdue rule) + 0 s grace");
        assertThat(at - t0).isGreaterThanOrEqualTo(1400);
        Thread.sleep(600);
        assertThat(events.stream().filter(e -> e.event() == VehicleEvent.OVERDUE)).hasSize(1); // once
        call("fw7-surface-interval.txt", System.currentTimeMillis());
        assertThat(events.stream().filter(e -> e.event() == VehicleEvent.OVERDUE).map(ConsoleEntry::text))
                .hasSize(2).last().asString().startsWith("called again");
    }

    @Test
    void aLearnedIntervalNeedsThreeCalls() {
        Overdue o = new Overdue(m -> AlertRules.DEFAULTS);
        o.called(RU29, 0, null);
        o.ended(RU29);
        assertThat(o.check(10_000_000)).isEmpty();
        o.called(RU29, 3_600_000, null);
        o.ended(RU29);
        o.called(RU29, 7_200_000, null);
        o.ended(RU29);
        assertThat(o.check(7_200_000 + 3_600_000 + 500_000)).isEmpty(); // within the 10 min grace
        assertThat(o.check(7_200_000 + 3_600_000 + 700_000)).singleElement().extracting(Overdue.Late::text).asString()
                .contains("expected every 60 min (learned from its last 2 intervals) + 10 min grace");
    }

    @Test
    void aRestartedServerKnowsTheLearnedIntervalAndTheNextCall() throws Exception {
        start();
        long t0 = 1_700_000_000_000L;
        for (int i = 0; i < 3; i++) {
            call("fw7-surface-interval.txt", t0 + i * 3_600_000L);
        }
        surfacings.close();
        store.close();
        assertThat(events).extracting(ConsoleEntry::event).containsExactly(VehicleEvent.OVERDUE); // the first server said it
        events.clear();
        start(); // a new server on the same state store
        Map<String, Object> o = surfacings.outlook(RU29, surfacings.last(RU29, 20));
        assertThat(o).containsEntry("interval_s", 3600L).containsEntry("interval_from", "learned from its last 2 intervals")
                .containsEntry("next_call_utc", java.time.Instant.ofEpochMilli(t0 + 3 * 3_600_000L + 1).toString());
        assertThat(SurfacingCommands.words(o)).startsWith("next call: " + o.get("next_call_utc")
                + " (every 3600 s, learned from its last 2 intervals)").contains("\nwaypoint 38.81000, -74.22333: ") // fw7's c_wpt 3848.6, -7413.4
                .contains(" km at ").contains(" from the last fix");
        Thread.sleep(300);
        assertThat(events).isEmpty(); // long overdue before the restart: the server that ran then said so
    }

    @Test
    void aVehicleDueAfterTheRestartIsOverdueByWhatItsStoredCallsTaught() throws Exception {
        Files.writeString(data.resolve("surfacing-alerts.conf"), "* overdue.grace 500ms\n");
        start();
        long now = System.currentTimeMillis();
        for (int i = 3; i > 0; i--) {
            call("fw7-surface-interval.txt", now - i * 1000L);
        }
        surfacings.close();
        store.close();
        events.clear();
        start();
        long end = System.nanoTime() + Duration.ofSeconds(10).toNanos();
        while (events.stream().noneMatch(e -> e.event() == VehicleEvent.OVERDUE) && System.nanoTime() < end) {
            Thread.sleep(50);
        }
        assertThat(events).filteredOn(e -> e.event() == VehicleEvent.OVERDUE).singleElement().extracting(ConsoleEntry::text)
                .asString().contains("expected every 1 s (learned from its last 2 intervals) + 0 s grace");
    }

    /**
     * Records kept before the store wrote {@code KEY.mailbox} (issue 35's caveat): after an upgrade
     * the restarted server finds whose they are from the vehicle's transcript, so the interval it
     * learned still makes the silent vehicle OVERDUE.
     */
    @Test
    void recordsKeptBeforeTheirMailboxFileStillTeachTheIntervalAfterARestart() throws Exception {
        Files.writeString(data.resolve("surfacing-alerts.conf"), "* overdue.grace 500ms\n");
        start();
        long now = System.currentTimeMillis();
        for (int i = 3; i > 0; i--) {
            call("fw7-surface-interval.txt", now - i * 1000L);
        }
        // the server's transcript of those calls, as it writes one for every vehicle
        store.appendTranscript(List.of(new org.ripv.server.store.StateStore.TranscriptLine(RU29, now - 3000,
                "{\"time\":\"" + java.time.Instant.ofEpochMilli(now - 3000) + "\",\"mailbox\":\"" + RU29
                        + "\",\"kind\":\"EVENT\",\"event\":\"SURFACED\",\"text\":\"call\"}")));
        surfacings.close();
        store.close();
        try (var files = Files.list(data.resolve("surfacings"))) { // as the version before kept them: no KEY.mailbox
            for (Path p : files.filter(p -> p.toString().endsWith(".mailbox")).toList()) {
                Files.delete(p);
            }
        }
        events.clear();
        start();
        long end = System.nanoTime() + Duration.ofSeconds(10).toNanos();
        while (events.stream().noneMatch(e -> e.event() == VehicleEvent.OVERDUE) && System.nanoTime() < end) {
            Thread.sleep(50);
        }
        assertThat(events).filteredOn(e -> e.event() == VehicleEvent.OVERDUE).singleElement().extracting(ConsoleEntry::text)
                .asString().contains("expected every 1 s (learned from its last 2 intervals) + 0 s grace");
    }
}
