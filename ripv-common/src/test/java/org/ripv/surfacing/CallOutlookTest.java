package org.ripv.surfacing;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import java.time.Duration;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The outlook's arithmetic against values worked by hand (a 6371 km sphere: 0.01° of latitude is 1111.95 m). */
class CallOutlookTest {
    private static Map<String, Object> record(String time, Object... pairs) {
        Map<String, Object> r = new HashMap<>();
        r.put("time_utc", time);
        for (int i = 0; i < pairs.length; i += 2) {
            r.put((String) pairs[i], pairs[i + 1]);
        }
        return r;
    }

    /** North 0.01° in an hour (0.308875 m/s) under a 0.1 m/s current to the east; the waypoint 0.1° further north. */
    private static List<Map<String, Object>> northbound(Object wptLat, Object wptLon) {
        return List.of(
                record("2026-11-23T00:00:00Z", "gps_lat", 0.0, "gps_lon", 0.0, "gps_age_s", 0.0, "water_vx", 0.1, "water_vy", 0.0,
                        "battery_v", 15.0, "vacuum_inhg", 7.0, "leak_v", 2.5, "m_coulomb_amphr_total", 1.0, "dr_lat", 0.001, "dr_lon", 0.0),
                record("2026-11-23T01:00:30Z", "gps_lat", 0.01, "gps_lon", 0.0, "gps_age_s", 30.0, "water_vx", 0.1, "water_vy", 0.0,
                        "battery_v", 14.9, "vacuum_inhg", 7.1, "leak_v", 2.49, "m_coulomb_amphr_total", 2.5,
                        "c_wpt_lat", wptLat, "c_wpt_lon", wptLon));
    }

    @Test
    void distanceBearingAndEtaToTheWaypointWorkedByHand() {
        // c_wpt_lat 0006.6 is 0° 6.6' = 0.11°: 0.1° north of the last fix, 11119.49 m at 0°.
        Map<String, Object> o = CallOutlook.of(northbound(6.6, 0.0), Duration.ofHours(1), "learned");
        assertThat((Double) o.get("wpt_lat")).isEqualTo(0.11);
        assertThat((Double) o.get("wpt_distance_m")).isCloseTo(11119.5, within(0.1));
        assertThat((Double) o.get("wpt_bearing_deg")).isEqualTo(0.0);
        assertThat((Double) o.get("sog_mps")).isCloseTo(1111.949 / 3600, within(1e-4)); // the fix's age counted: 1 h apart
        assertThat((Double) o.get("cog_deg")).isEqualTo(0.0);
        // Through the water: (0, 0.308875) - (0.1, 0) = 0.324659 m/s; crabbing into the 0.1 cross current leaves
        // sqrt(0.324659² - 0.1²) = 0.308875 along the track: 0.1° in ten hours from the fix at 01:00:00.
        assertThat((Double) o.get("wpt_made_good_mps")).isCloseTo(0.308875, within(1e-4));
        assertThat(o.get("wpt_eta_utc")).isEqualTo("2026-11-23T11:00:00Z");
        assertThat((Double) o.get("current_mps")).isEqualTo(0.1);
        assertThat((Double) o.get("current_toward_deg")).isEqualTo(90.0);
        assertThat(o.get("fix_utc")).isEqualTo("2026-11-23T01:00:00Z");
    }

    @Test
    void aCurrentAlongTheTrackToTheWaypointAddsToTheGlidersOwnSpeed() {
        // The waypoint 0.11° east (DDMM 0006.6 E, written as the glider prints west negative): bearing about 90°, the
        // 0.1 m/s current all along it: 0.324659 + 0.1 = 0.424659 m/s over 0.11° x cos(0.01°) = 12231.44 m.
        Map<String, Object> o = CallOutlook.of(northbound(0.6, 6.6), null, null);
        assertThat((Double) o.get("wpt_bearing_deg")).isCloseTo(90.0, within(0.1));
        assertThat((Double) o.get("wpt_distance_m")).isCloseTo(12231.4, within(0.5));
        assertThat((Double) o.get("wpt_made_good_mps")).isCloseTo(0.424659, within(1e-4));
        // 12231.44 / 0.424659 = 28803 s after the fix at 01:00:00: 09:00:03.
        assertThat(o.get("wpt_eta_utc").toString()).startsWith("2026-11-23T09:00:0");
        assertThat(o.get("next_call_utc")).isNull();
    }

    @Test
    void aCurrentTheGliderCannotStemGivesNoEta() {
        // Waypoint due west; the glider makes 0.308875 north through a current it crabs into; 0.324659 through the water,
        // 0.1 against it along the track: still 0.224659 > 0. A 0.5 m/s current east beats it.
        List<Map<String, Object>> r = northbound(0.6, -6.6);
        r.get(0).put("water_vx", 0.5);
        r.get(1).put("water_vx", 0.5);
        Map<String, Object> o = CallOutlook.of(r, null, null);
        // Through the water: |(0, 0.308875) - (0.5, 0)| = 0.587723; along the track west, -0.5: 0.087723 m/s.
        assertThat((Double) o.get("wpt_made_good_mps")).isCloseTo(0.0877, within(1e-3));
        r.get(1).put("gps_lat", 0.0); // no way made over ground, the glider only drifted: its own speed is the current's 0.5
        r.get(0).put("gps_lat", 0.0);
        r.get(1).put("gps_lon", 0.0018); // 200.4 m east in an hour: 0.0557 m/s; through the water |0.0557-0.5| = 0.4443
        o = CallOutlook.of(r, null, null);
        assertThat((Double) o.get("wpt_made_good_mps")).isLessThan(0);
        assertThat(o.get("wpt_eta_utc")).isNull();
    }

    @Test
    void theNextCallIsTheLastPlusTheExpectedInterval() {
        Map<String, Object> o = CallOutlook.of(northbound(6.6, 0.0), Duration.ofMinutes(90), "its overdue rule");
        assertThat(o.get("next_call_utc")).isEqualTo("2026-11-23T02:30:30Z");
        assertThat(o.get("interval_s")).isEqualTo(5400L);
        assertThat(o.get("interval_from")).isEqualTo("its overdue rule");
        assertThat(o.get("calls")).isEqualTo(2);
    }

    @Test
    void theLearnedIntervalIsTheMedianOfTheLastFive() {
        assertThat(CallOutlook.learned(List.of(0L, 3_600_000L))).isNull(); // one interval: not yet
        assertThat(CallOutlook.learned(List.of(0L, 3_600_000L, 7_200_000L))).isEqualTo(Duration.ofHours(1));
        // gaps 1 h, 1 h, 5 h, 2 h: the median (the upper middle of four) is 2 h; a call long ago is not counted.
        assertThat(CallOutlook.learned(Arrays.asList(-99_000_000L, 0L, 3_600_000L, 7_200_000L, 25_200_000L, 32_400_000L)))
                .isEqualTo(Duration.ofHours(2));
        assertThat(CallOutlook.learned(Arrays.asList(0L, 3_600_000L, 7_200_000L, 25_200_000L))).isEqualTo(Duration.ofHours(1));
    }

    @Test
    @SuppressWarnings("unchecked")
    void seriesAndTrackCarryEveryCallWithTheCurrentAsAnArrow() {
        List<Map<String, Object>> r = northbound(6.6, 0.0);
        r.get(1).remove("m_coulomb_amphr_total");
        r.get(1).put("m_coulomb_amphr", 2.5);
        r.get(0).remove("m_coulomb_amphr_total");
        r.get(0).put("m_coulomb_amphr", 1.0);
        Map<String, Object> o = CallOutlook.of(r, null, null);
        assertThat(o.get("coulomb_sensor")).isEqualTo("m_coulomb_amphr");
        Map<String, List<Object>> s = (Map<String, List<Object>>) o.get("series");
        assertThat(s.keySet()).containsExactly("time_ms", "battery_v", "vacuum_inhg", "leak_v", "coulomb_amphr", "current_mps");
        assertThat(s.get("time_ms")).containsExactly(1_795_392_000_000L, 1_795_392_000_000L + 3_630_000L);
        assertThat(s.get("battery_v")).containsExactly(15.0, 14.9);
        assertThat(s.get("coulomb_amphr")).containsExactly(1.0, 2.5);
        assertThat(s.get("current_mps")).containsExactly(0.1, 0.1);
        List<Map<String, Object>> track = (List<Map<String, Object>>) o.get("track");
        assertThat(track).hasSize(3); // two fixes and the first call's dead-reckoned position
        assertThat(track.get(0)).containsEntry("gps", true).containsEntry("current_e", 0.1).containsEntry("current_n", 0.0);
        assertThat(track.get(1)).containsEntry("gps", false).doesNotContainKey("current_e");
    }

    @Test
    void noFixNoWaypointAndNonsenseGiveNothingRatherThanAGuess() {
        Map<String, Object> o = CallOutlook.of(List.of(record("2026-11-23T00:00:00Z", "c_wpt_lat", 69696969.0, "c_wpt_lon", 0.0,
                "gps_lat", 91.0, "gps_lon", 0.0)), null, null);
        assertThat(o.get("wpt_lat")).isNull();
        assertThat(o.get("fix_lat")).isNull();
        assertThat(o.get("sog_mps")).isNull();
        assertThat(o.get("wpt_eta_utc")).isNull();
        assertThat(CallOutlook.of(List.of(), Duration.ofHours(1), "x").get("next_call_utc")).isNull();
    }
}
