package org.ripv.server.surfacing;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import org.ripv.surfacing.Surfacing;

/**
 * A call record: one surfacing as named columns ({@code time_utc}, {@code because}, …, then every
 * other surface sensor by its own name), kept as one JSON object per surfacing. Numbers that are
 * not finite are null; a record is at most {@link #MAX_CHARS} characters (sensors past that are
 * counted in {@code sensors_left_out}).
 */
final class CallRecord {
    /** The named columns, in the order {@code ?surfacings} shows them. */
    static final List<String> COLUMNS = List.of("time_utc", "vehicle", "because", "mission", "gps_lat", "gps_lon", "gps_age_s",
            "dr_lat", "dr_lon", "battery_v", "vacuum_inhg", "leak", "leak_v", "water_vx", "water_vy", "abort_total",
            "abort_cause", "abort_details", "abort_time", "new_abort", "device_errors", "gps_problem", "prompt", "dives_in_s");
    /** Sensors shown as named columns above rather than by their own names. */
    private static final List<String> RENAMED = List.of("m_battery", "m_vacuum", "m_water_vx", "m_water_vy");
    static final int MAX_CHARS = 32_000;
    static final String LEAK_SENSOR = "m_leakdetect_voltage";

    private CallRecord() {
    }

    /**
     * The record of {@code s}, which began at {@code time} (epoch ms), given the vehicle's previous
     * record (null for its first) and the leak threshold in force.
     */
    static Map<String, Object> of(Surfacing s, long time, Map<String, Object> previous, double leakMin) {
        Map<String, Object> r = new LinkedHashMap<>();
        r.put("time_utc", Instant.ofEpochMilli(time).toString());
        r.put("vehicle", s.vehicle());
        r.put("because", s.becauseText());
        r.put("mission", s.mission());
        r.put("gps_lat", s.gps() == null ? null : round(s.gps().lat(), 6));
        r.put("gps_lon", s.gps() == null ? null : round(s.gps().lon(), 6));
        r.put("gps_age_s", s.gps() == null ? null : finite(s.gps().ageSeconds()));
        r.put("dr_lat", s.dr() == null ? null : round(s.dr().lat(), 6));
        r.put("dr_lon", s.dr() == null ? null : round(s.dr().lon(), 6));
        r.put("battery_v", finite(s.value("m_battery")));
        r.put("vacuum_inhg", finite(s.value("m_vacuum")));
        Double leakV = leakVoltage(s);
        r.put("leak", leakV != null && leakV < leakMin);
        r.put("leak_v", leakV);
        r.put("water_vx", finite(s.value("m_water_vx")));
        r.put("water_vy", finite(s.value("m_water_vy")));
        Surfacing.AbortHistory a = s.aborts();
        r.put("abort_total", a == null ? null : a.total());
        r.put("abort_cause", a == null ? null : a.cause());
        r.put("abort_details", a == null ? null : a.details());
        r.put("abort_time", a == null ? null : a.time());
        r.put("new_abort", newAbort(s, previous));
        r.put("device_errors", s.devices() == null ? null : s.devices().errors().total());
        r.put("gps_problem", s.gpsProblem());
        r.put("prompt", s.prompt() == null ? null : (s.prompt().shell() + (s.prompt().status() == null ? ""
                : " " + s.prompt().status() + " " + s.prompt().code())));
        r.put("dives_in_s", s.countdown());
        int size = r.toString().length();
        int left = 0;
        for (Surfacing.Sensor sensor : s.sensors().values()) {
            if (RENAMED.contains(sensor.name()) || r.containsKey(sensor.name())) {
                continue;
            }
            Object v = sensor.value() != null ? finite(sensor.value()) : sensor.text();
            size += sensor.name().length() + String.valueOf(v).length() + 8;
            if (size > MAX_CHARS) {
                left++;
            } else {
                r.put(sensor.name(), v);
            }
        }
        if (left > 0 || s.dropped() > 0) {
            r.put("sensors_left_out", left + s.dropped());
        }
        return r;
    }

    /** The lowest of the vehicle's leak-detect voltages (one, or forward and aft), or null. */
    static Double leakVoltage(Surfacing s) {
        Double low = null;
        for (Surfacing.Sensor sensor : s.sensors().values()) {
            if (sensor.name().startsWith(LEAK_SENSOR) && sensor.value() != null && Double.isFinite(sensor.value())) {
                low = low == null ? sensor.value() : Math.min(low, sensor.value());
            }
        }
        return low;
    }

    /**
     * True when the abort history shows an abort not seen at an earlier surfacing: more aborts since
     * reset than last time, or another last abort. With no earlier record, only when the vehicle
     * says it surfaced because of an abort.
     */
    static boolean newAbort(Surfacing s, Map<String, Object> previous) {
        Surfacing.AbortHistory a = s.aborts();
        if (a == null || a.total() == null || a.total() == 0) {
            return false;
        }
        if (previous == null) {
            return s.because() != null && s.because().toLowerCase(Locale.ROOT).contains("abort");
        }
        Object before = previous.get("abort_total");
        if (!(before instanceof Number n)) {
            return true;
        }
        if (a.total() != n.longValue()) {
            return a.total() > n.longValue() || !Objects.equals(a.time(), previous.get("abort_time"));
        }
        return a.time() != null && previous.get("abort_time") != null && !a.time().equals(previous.get("abort_time"));
    }

    /** A column's type name for the table result: the named columns' own, else {@code VARCHAR}. */
    static String type(String column) {
        return switch (column) {
            case "leak", "new_abort" -> "BOOLEAN";
            case "abort_total", "device_errors", "dives_in_s" -> "BIGINT";
            case "time_utc", "vehicle", "because", "mission", "abort_cause", "abort_details", "abort_time", "gps_problem",
                 "prompt" -> "VARCHAR";
            default -> column.contains("_") && COLUMNS.contains(column) ? "DOUBLE" : "VARCHAR";
        };
    }

    static Double finite(Double d) {
        return d == null || !Double.isFinite(d) ? null : d;
    }

    private static Double round(double d, int places) {
        double f = Math.pow(10, places);
        return Double.isFinite(d) ? Math.round(d * f) / f : null;
    }
}
