package org.ripv.plans;

import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Distance, bearing and ETA from a fix to each waypoint of a goto list, in the order the glider
 * flies it: from the waypoint {@code initial_wpt} names (-2: the closest; -1, which needs the last
 * achieved one, and anything else: the first) through the list, round to the start when the
 * list loops ({@code num_legs_to_run} -1), each waypoint once.
 *
 * <p>Speed: the glider's speed through the water and the depth-averaged current (east, north,
 * m/s). On each leg the glider crabs into the current's cross-track part, so its speed along the
 * track is {@code sqrt(s² - cross²) + along}; a leg whose cross current is at least the glider's
 * speed, or whose along-track speed is not positive, cannot be made good (no ETA from there on).
 * Distances are great-circle (haversine on a 6371 km sphere), bearings initial true bearings.
 */
public final class Forecast {
    static final double EARTH_M = 6_371_000.0;

    /** One leg: to waypoint {@code n}. {@code eta} is null when the leg, or one before it, cannot be made good. */
    public record Leg(int n, double lat, double lon, double legMetres, double bearing, double totalMetres,
                      double groundSpeed, Instant eta) {}

    private Forecast() {
    }

    /**
     * @param speed    the glider's speed through the water, m/s (&gt; 0)
     * @param currentE the depth-averaged current's east part, m/s (0 when not known)
     * @param currentN its north part
     */
    public static List<Leg> legs(BehaviorFile f, double lat, double lon, Instant at, double speed, double currentE, double currentN) {
        if (!(speed > 0) || !Double.isFinite(speed) || !Double.isFinite(currentE) || !Double.isFinite(currentN)) {
            throw new IllegalArgumentException("a speed over 0 m/s and a finite current are needed");
        }
        List<Waypoint> w = f.waypoints();
        List<Leg> legs = new ArrayList<>();
        if (w.isEmpty()) {
            return legs;
        }
        int start = first(f, lat, lon);
        boolean loops = f.barg("num_legs_to_run").map(b -> b.value() == -1).orElse(false);
        int count = loops ? w.size() : w.size() - start;
        double fromLat = lat;
        double fromLon = lon;
        double total = 0;
        double seconds = 0;
        boolean reachable = true;
        for (int k = 0; k < count; k++) {
            Waypoint to = w.get((start + k) % w.size());
            double d = distance(fromLat, fromLon, to.lat(), to.lon());
            double b = bearing(fromLat, fromLon, to.lat(), to.lon());
            double g = groundSpeed(b, speed, currentE, currentN);
            total += d;
            if (g <= 0) {
                reachable = false;
            }
            seconds += reachable ? d / g : 0;
            legs.add(new Leg(to.n(), to.lat(), to.lon(), d, b, total, g,
                    reachable ? at.plus(Duration.ofMillis(Math.round(seconds * 1000))) : null));
            fromLat = to.lat();
            fromLon = to.lon();
        }
        return legs;
    }

    /** The glider's speed along a track of bearing {@code b} (degrees true); 0 or less when it cannot make it good. */
    public static double groundSpeed(double b, double speed, double currentE, double currentN) {
        double r = Math.toRadians(b);
        double along = currentE * Math.sin(r) + currentN * Math.cos(r);
        double cross = currentE * Math.cos(r) - currentN * Math.sin(r);
        if (Math.abs(cross) >= speed) {
            return 0;
        }
        return Math.sqrt(speed * speed - cross * cross) + along;
    }

    private static int first(BehaviorFile f, double lat, double lon) {
        int initial = f.barg("initial_wpt").map(b -> (int) b.value()).orElse(0);
        List<Waypoint> w = f.waypoints();
        if (initial >= 0 && initial < w.size()) {
            return initial;
        }
        if (initial == -2) {
            int best = 0;
            for (int i = 1; i < w.size(); i++) {
                if (distance(lat, lon, w.get(i).lat(), w.get(i).lon()) < distance(lat, lon, w.get(best).lat(), w.get(best).lon())) {
                    best = i;
                }
            }
            return best;
        }
        return 0;
    }

    /** Great-circle distance in metres. */
    public static double distance(double lat1, double lon1, double lat2, double lon2) {
        double p1 = Math.toRadians(lat1);
        double p2 = Math.toRadians(lat2);
        double dp = p2 - p1;
        double dl = Math.toRadians(lon2 - lon1);
        double a = Math.sin(dp / 2) * Math.sin(dp / 2) + Math.cos(p1) * Math.cos(p2) * Math.sin(dl / 2) * Math.sin(dl / 2);
        return 2 * EARTH_M * Math.asin(Math.min(1, Math.sqrt(a)));
    }

    /** Initial true bearing in degrees, 0 to 360. */
    public static double bearing(double lat1, double lon1, double lat2, double lon2) {
        double p1 = Math.toRadians(lat1);
        double p2 = Math.toRadians(lat2);
        double dl = Math.toRadians(lon2 - lon1);
        double y = Math.sin(dl) * Math.cos(p2);
        double x = Math.cos(p1) * Math.sin(p2) - Math.sin(p1) * Math.cos(p2) * Math.cos(dl);
        return (Math.toDegrees(Math.atan2(y, x)) + 360) % 360;
    }

    /** The legs as a table for people. */
    public static String render(List<Leg> legs, String basis) {
        StringBuilder b = new StringBuilder("forecast " + basis);
        b.append(String.format(Locale.ROOT, "%n%4s  %10s  %11s  %8s  %7s  %9s  %6s  %s", "n", "lat", "lon", "leg km", "bearing",
                "total km", "m/s", "ETA"));
        for (Leg l : legs) {
            b.append(String.format(Locale.ROOT, "%n%4d  %10.5f  %11.5f  %8.2f  %6.0f°  %9.2f  %6.3f  %s", l.n(), l.lat(), l.lon(),
                    l.legMetres() / 1000, l.bearing(), l.totalMetres() / 1000, l.groundSpeed(),
                    l.eta() == null ? "not reachable: the current is stronger than the glider on this leg or one before"
                            : l.eta().truncatedTo(ChronoUnit.SECONDS).toString()));
        }
        return b.toString();
    }
}
