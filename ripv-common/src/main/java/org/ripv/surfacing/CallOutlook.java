package org.ripv.surfacing;

import java.time.Duration;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.ripv.plans.Forecast;

/**
 * What a vehicle's call records say about what comes next (docs/surfacings.md#the-outlook): when
 * it should call again, how fast it goes over ground, the depth-averaged current, the distance,
 * bearing and ETA to the waypoint it steers for ({@code c_wpt_lat}/{@code c_wpt_lon}), the trend
 * series across calls, and the track with a current arrow at each surfacing. Records are the
 * server's call records as JSON objects (by column name), oldest first; the server sends the
 * result as {@code ?surfacings MAILBOX --outlook --json}'s {@code outlook}, so the web pages and
 * the CLI only show it.
 *
 * <p>Speed toward the waypoint: the ground velocity between the last two GPS fixes at least
 * {@link #MIN_FIX_GAP} apart is the glider's velocity through the water plus the current, so the
 * glider's own speed is the length of their difference; on the bearing to the waypoint the glider
 * crabs into the current's cross part ({@link Forecast#groundSpeed}). Without a current the
 * speed made good is the speed over ground.
 */
public final class CallOutlook {
    /**
     * Fixes closer in time than this give no speed: two fixes of one surfacing, seconds apart, are
     * mostly the GPS's own wander. Calls are usually hours apart; a simulator's, seconds.
     */
    public static final Duration MIN_FIX_GAP = Duration.ofSeconds(5);
    /** Calls whose intervals teach the expected one. */
    public static final int LEARN_FROM = 5;
    /** The trend series, in the order the vehicle page charts them. */
    public static final List<String> SERIES = List.of("battery_v", "vacuum_inhg", "leak_v", "coulomb_amphr", "current_mps");

    private CallOutlook() {
    }

    /**
     * The expected interval between calls learned from call start times (epoch ms, oldest first):
     * the median of the last {@link #LEARN_FROM} intervals, or null with fewer than two intervals.
     */
    public static Duration learned(List<Long> starts) {
        List<Long> last = starts.subList(Math.max(0, starts.size() - LEARN_FROM - 1), starts.size());
        if (last.size() < 3) {
            return null;
        }
        List<Long> gaps = new ArrayList<>();
        for (int i = 1; i < last.size(); i++) {
            gaps.add(last.get(i) - last.get(i - 1));
        }
        gaps.sort(null);
        return Duration.ofMillis(gaps.get(gaps.size() / 2));
    }

    /**
     * The outlook of {@code records} (oldest first). {@code interval} is the expected interval
     * between calls (null when not known), {@code intervalFrom} what it comes from, in words.
     */
    public static Map<String, Object> of(List<Map<String, Object>> records, Duration interval, String intervalFrom) {
        Map<String, Object> o = new LinkedHashMap<>();
        o.put("calls", records.size());
        Map<String, Object> last = records.isEmpty() ? Map.of() : records.get(records.size() - 1);
        Long lastCall = time(last);
        o.put("last_call_utc", lastCall == null ? null : Instant.ofEpochMilli(lastCall).toString());
        o.put("interval_s", interval == null ? null : interval.toSeconds());
        o.put("interval_from", interval == null ? null : intervalFrom);
        o.put("next_call_utc", interval == null || lastCall == null ? null : Instant.ofEpochMilli(lastCall).plus(interval).toString());

        List<Fix> fixes = new ArrayList<>();
        for (Map<String, Object> r : records) {
            Fix f = Fix.of(r);
            if (f != null) {
                fixes.add(f);
            }
        }
        Fix fix = fixes.isEmpty() ? null : fixes.get(fixes.size() - 1);
        o.put("fix_lat", fix == null ? null : fix.lat);
        o.put("fix_lon", fix == null ? null : fix.lon);
        o.put("fix_utc", fix == null ? null : Instant.ofEpochMilli(fix.time).toString());

        // Speed over ground: from the last fix back to the newest one at least MIN_FIX_GAP before it.
        Double sog = null;
        Double cog = null;
        double groundE = 0;
        double groundN = 0;
        for (int i = fixes.size() - 2; i >= 0 && fix != null; i--) {
            Fix before = fixes.get(i);
            long dt = fix.time - before.time;
            if (dt >= MIN_FIX_GAP.toMillis()) {
                double d = Forecast.distance(before.lat, before.lon, fix.lat, fix.lon);
                cog = Forecast.bearing(before.lat, before.lon, fix.lat, fix.lon);
                sog = d / (dt / 1000.0);
                groundE = sog * Math.sin(Math.toRadians(cog));
                groundN = sog * Math.cos(Math.toRadians(cog));
                break;
            }
        }
        o.put("sog_mps", round(sog, 4));
        o.put("cog_deg", round(cog, 1));

        Double currentE = null;
        Double currentN = null;
        for (int i = records.size() - 1; i >= 0 && currentE == null; i--) {
            Double e = number(records.get(i).get("water_vx"));
            Double n = number(records.get(i).get("water_vy"));
            if (e != null && n != null) {
                currentE = e;
                currentN = n;
            }
        }
        o.put("current_e_mps", currentE);
        o.put("current_n_mps", currentN);
        o.put("current_mps", currentE == null ? null : round(Math.hypot(currentE, currentN), 4));
        o.put("current_toward_deg", currentE == null ? null : round((Math.toDegrees(Math.atan2(currentE, currentN)) + 360) % 360, 1));

        double[] wpt = waypoint(last);
        o.put("wpt_lat", wpt == null ? null : round(wpt[0], 6));
        o.put("wpt_lon", wpt == null ? null : round(wpt[1], 6));
        Double distance = null;
        Double bearing = null;
        Double madeGood = null;
        String eta = null;
        if (wpt != null && fix != null) {
            distance = Forecast.distance(fix.lat, fix.lon, wpt[0], wpt[1]);
            bearing = Forecast.bearing(fix.lat, fix.lon, wpt[0], wpt[1]);
            if (sog != null) {
                double ce = currentE == null ? 0 : currentE;
                double cn = currentN == null ? 0 : currentN;
                double water = Math.hypot(groundE - ce, groundN - cn);
                madeGood = water > 0 ? Forecast.groundSpeed(bearing, water, ce, cn) : 0;
                if (madeGood > 0) {
                    eta = Instant.ofEpochMilli(fix.time).plusMillis(Math.round(distance / madeGood * 1000)).toString();
                }
            }
        }
        o.put("wpt_distance_m", round(distance, 1));
        o.put("wpt_bearing_deg", round(bearing, 1));
        o.put("wpt_made_good_mps", round(madeGood, 4));
        o.put("wpt_eta_utc", eta);
        o.put("coulomb_sensor", coulombSensor(records));
        o.put("series", series(records));
        o.put("track", track(records));
        return o;
    }

    /** A valid GPS fix of a record and when it was taken (the record's time less the fix's age). */
    private record Fix(double lat, double lon, long time) {
        static Fix of(Map<String, Object> r) {
            Double lat = number(r.get("gps_lat"));
            Double lon = number(r.get("gps_lon"));
            Long t = CallOutlook.time(r);
            if (lat == null || lon == null || t == null || !DegreesMinutes.valid(lat, lon)) {
                return null;
            }
            Double age = number(r.get("gps_age_s"));
            long ageMs = age == null || age < 0 || age > 86_400 ? 0 : Math.round(age * 1000);
            return new Fix(lat, lon, t - ageMs);
        }
    }

    /** The waypoint the record shows ({@code c_wpt_lat}/{@code c_wpt_lon}, DDMM.mmm as the GPS), or null. */
    static double[] waypoint(Map<String, Object> r) {
        Double lat = number(r.get("c_wpt_lat"));
        Double lon = number(r.get("c_wpt_lon"));
        if (lat == null || lon == null) {
            return null;
        }
        double la = DegreesMinutes.degrees(lat, ' ');
        double lo = DegreesMinutes.degrees(lon, ' ');
        return DegreesMinutes.valid(la, lo) ? new double[] {la, lo} : null;
    }

    /** The record's coulomb counter: {@code m_coulomb_amphr_total}, else another {@code m_coulomb_amphr*}. */
    static String coulombSensor(List<Map<String, Object>> records) {
        String found = null;
        for (Map<String, Object> r : records) {
            if (number(r.get("m_coulomb_amphr_total")) != null) {
                return "m_coulomb_amphr_total";
            }
            for (String k : r.keySet()) {
                if (found == null && k.startsWith("m_coulomb_amphr") && number(r.get(k)) != null) {
                    found = k;
                }
            }
        }
        return found;
    }

    /** One value per record for each of {@link #SERIES}, with the records' times (epoch ms): null where a record has none. */
    static Map<String, List<Object>> series(List<Map<String, Object>> records) {
        String coulombs = coulombSensor(records);
        Map<String, List<Object>> s = new LinkedHashMap<>();
        s.put("time_ms", new ArrayList<>());
        SERIES.forEach(k -> s.put(k, new ArrayList<>()));
        for (Map<String, Object> r : records) {
            Long t = time(r);
            if (t == null) {
                continue;
            }
            s.get("time_ms").add(t);
            s.get("battery_v").add(number(r.get("battery_v")));
            s.get("vacuum_inhg").add(number(r.get("vacuum_inhg")));
            s.get("leak_v").add(number(r.get("leak_v")));
            s.get("coulomb_amphr").add(coulombs == null ? null : number(r.get(coulombs)));
            Double e = number(r.get("water_vx"));
            Double n = number(r.get("water_vy"));
            s.get("current_mps").add(e == null || n == null ? null : round(Math.hypot(e, n), 4));
        }
        return s;
    }

    /**
     * Each surfacing's positions: its GPS fix ({@code gps} true) and its dead-reckoned position, with
     * the current it reported ({@code current_e}, {@code current_n}, m/s) on the GPS fix, else on the
     * dead-reckoned one.
     */
    static List<Map<String, Object>> track(List<Map<String, Object>> records) {
        List<Map<String, Object>> out = new ArrayList<>();
        for (Map<String, Object> r : records) {
            Long t = time(r);
            if (t == null) {
                continue;
            }
            Double e = number(r.get("water_vx"));
            Double n = number(r.get("water_vy"));
            boolean arrow = e != null && n != null;
            Map<String, Object> gps = point(r.get("gps_lat"), r.get("gps_lon"), t, true);
            Map<String, Object> dr = point(r.get("dr_lat"), r.get("dr_lon"), t, false);
            for (Map<String, Object> p : new Map[] {gps, dr}) {
                if (p != null) {
                    if (arrow) {
                        p.put("current_e", e);
                        p.put("current_n", n);
                        arrow = false;
                    }
                    out.add(p);
                }
            }
        }
        return out;
    }

    private static Map<String, Object> point(Object lat, Object lon, long t, boolean gps) {
        Double la = number(lat);
        Double lo = number(lon);
        if (la == null || lo == null || !DegreesMinutes.valid(la, lo)) {
            return null;
        }
        Map<String, Object> p = new LinkedHashMap<>();
        p.put("lat", la);
        p.put("lon", lo);
        p.put("t", t);
        p.put("gps", gps);
        return p;
    }

    static Long time(Map<String, Object> r) {
        if (!(r.get("time_utc") instanceof String s)) {
            return null;
        }
        try {
            return Instant.parse(s).toEpochMilli();
        } catch (DateTimeParseException e) {
            return null;
        }
    }

    static Double number(Object v) {
        if (v instanceof Number n && Double.isFinite(n.doubleValue())) {
            return n.doubleValue();
        }
        if (v instanceof String s && !s.isBlank() && s.length() < 40) {
            try {
                double d = Double.parseDouble(s.strip());
                return Double.isFinite(d) ? d : null;
            } catch (NumberFormatException e) {
                return null;
            }
        }
        return null;
    }

    private static Double round(Double d, int places) {
        if (d == null || !Double.isFinite(d)) {
            return null;
        }
        double f = Math.pow(10, places);
        return Math.round(d * f) / f;
    }
}
