package org.ripv.plans;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.List;

import org.junit.jupiter.api.Test;

class ForecastTest {
    private static BehaviorFile file(String initial, String legs, String... wpts) {
        StringBuilder b = new StringBuilder("behavior_name=goto_list\n<start:b_arg>\nb_arg: initial_wpt(enum) " + initial
                + "\nb_arg: num_legs_to_run(nodim) " + legs + "\nb_arg: num_waypoints(nodim) " + wpts.length
                + "\n<end:b_arg>\n<start:waypoints>\n");
        for (String w : wpts) {
            b.append(w).append('\n');
        }
        b.append("<end:waypoints>\n");
        PlanCheck c = BehaviorFileReader.check("goto_l10.ma", b.toString().getBytes(StandardCharsets.US_ASCII), PlanLimits.DEFAULT);
        assertThat(c.problems()).isEmpty();
        return c.file();
    }

    @Test
    void distancesAndBearingsAreGreatCircle() {
        // one minute of latitude is a nautical mile, 1852 m, due north
        assertThat(Forecast.distance(41.0, -70.0, 41.0 + 1.0 / 60, -70.0)).isCloseTo(1853.2, offset(1.0));
        assertThat(Forecast.bearing(41.0, -70.0, 42.0, -70.0)).isCloseTo(0.0, offset(1e-9));
        assertThat(Forecast.bearing(0.0, 0.0, 0.0, 1.0)).isCloseTo(90.0, offset(1e-9));
        assertThat(Forecast.bearing(41.0, -70.0, 40.0, -70.0)).isCloseTo(180.0, offset(1e-9));
        assertThat(Forecast.bearing(0.0, 1.0, 0.0, 0.0)).isCloseTo(270.0, offset(1e-9));
    }

    @Test
    void aCurrentAlongTheTrackHelpsAndOneAcrossIsCrabbedInto() {
        assertThat(Forecast.groundSpeed(0, 0.3, 0, 0.1)).isCloseTo(0.4, offset(1e-12)); // north, with a north current
        assertThat(Forecast.groundSpeed(0, 0.3, 0.18, 0)).isCloseTo(0.24, offset(1e-12)); // crab: sqrt(.09-.0324)
        assertThat(Forecast.groundSpeed(90, 0.3, 0, 0.3)).isLessThanOrEqualTo(0); // across, as strong as the glider
        assertThat(Forecast.groundSpeed(180, 0.3, 0, 0.4)).isLessThan(0); // against, stronger
    }

    @Test
    void legsFollowInitialWptAndTheLoopAndEtasAddUp() {
        Instant t0 = Instant.parse("2026-11-28T06:00:00Z");
        // from 41N 70W: waypoints a nautical mile north, then a mile east of that, then back
        BehaviorFile f = file("1", "-1", "-7000.000 4101.000", "-6958.672 4101.000", "-7000.000 4100.000");
        List<Forecast.Leg> legs = Forecast.legs(f, 41.0, -70.0, t0, 0.5, 0, 0);
        assertThat(legs).extracting(Forecast.Leg::n).containsExactly(1, 2, 0); // loops: each once, starting at initial_wpt
        assertThat(legs.get(2).bearing()).isCloseTo(0.0, offset(0.5));
        double total = legs.get(2).totalMetres();
        assertThat(legs.get(2).eta()).isEqualTo(t0.plusMillis(Math.round(total / 0.5 * 1000)));
        // traverse once from the closest: only the rest of the list
        BehaviorFile once = file("-2", "-2", "-7000.000 4101.000", "-6958.672 4101.000", "-7000.000 4110.000");
        assertThat(Forecast.legs(once, 41.0, -69.98, t0, 0.5, 0, 0)).extracting(Forecast.Leg::n).containsExactly(1, 2);
        // a current the glider cannot stem: no ETA from that leg on
        List<Forecast.Leg> stemmed = Forecast.legs(f, 41.0, -70.0, t0, 0.2, 0, -0.5);
        assertThat(stemmed.get(0).eta()).isNull();
        assertThat(Forecast.render(stemmed, "test")).contains("not reachable");
    }
}
