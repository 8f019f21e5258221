package org.ripv.plans;

import java.math.BigDecimal;
import java.util.Map;

import org.ripv.surfacing.DegreesMinutes;

/**
 * What one surfacing's dialog showed, as the change follower needs it: the sensors it printed
 * ({@code sensor:NAME(UNITS)=VALUE}, by lower-case name) and the waypoint it steers for
 * ({@code c_wpt_lat}/{@code c_wpt_lon}, decimal degrees, null when the dialog did not show them).
 * {@code time} is when the surfacing began (epoch ms): a change the glider got after that is
 * judged by a later surfacing. Any reader of surface dialogs can make one.
 */
public record SurfacingFacts(String mailbox, long time, Map<String, Double> sensors, Double wptLat, Double wptLon) {
    public SurfacingFacts {
        sensors = Map.copyOf(sensors);
    }

    /** Facts from a dialog's sensors alone: {@code c_wpt_lat}/{@code c_wpt_lon} read as DDMM.mmmm. */
    public static SurfacingFacts of(String mailbox, long time, Map<String, Double> sensors) {
        Double lat = ddmm(sensors.get("c_wpt_lat"), true);
        Double lon = ddmm(sensors.get("c_wpt_lon"), false);
        return new SurfacingFacts(mailbox, time, sensors, lat, lon);
    }

    private static Double ddmm(Double v, boolean latitude) {
        if (v == null || !Double.isFinite(v)) {
            return null;
        }
        try {
            return DegreesMinutes.parse(BigDecimal.valueOf(v).toPlainString(), latitude);
        } catch (IllegalArgumentException e) {
            return null; // Slocum's no-value (69696969) and other nonsense: no waypoint shown
        }
    }
}
