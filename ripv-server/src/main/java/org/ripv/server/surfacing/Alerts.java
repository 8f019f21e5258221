package org.ripv.server.surfacing;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.ripv.surfacing.Surfacing;

/**
 * What in a call record deserves an ALERT, each with its cause: a new abort, a leak, the battery
 * (low, or falling fast), the vacuum out of its band, no valid GPS fix, a reason to surface that
 * is not routine, device errors that grew. Pure: the record, the one before it and the thresholds
 * in, alerts out; the countdown text and sensor names are never alerts.
 */
final class Alerts {
    /** A reason to alert: {@code cause} is what rate limits count by (abort, leak, battery, …). */
    record Alert(String cause, String text) {}

    private static final long HOUR = 3_600_000L;

    private Alerts() {
    }

    static List<Alert> check(Surfacing s, Map<String, Object> rec, Map<String, Object> prev, AlertRules.Thresholds t) {
        List<Alert> out = new ArrayList<>();
        if (Boolean.TRUE.equals(rec.get("new_abort"))) {
            Surfacing.AbortHistory a = s.aborts();
            out.add(new Alert("abort", "new abort: " + (a.cause() == null ? "(no cause given)" : a.cause())
                    + (a.details() == null ? "" : ": " + a.details())
                    + (a.time() == null ? "" : " at " + a.time()) + " (" + a.total() + " since reset)"));
        }
        for (Surfacing.Sensor sensor : s.sensors().values()) {
            if (sensor.name().startsWith(CallRecord.LEAK_SENSOR) && sensor.value() != null && sensor.value() < t.leakMin()) {
                out.add(new Alert("leak", String.format(Locale.ROOT, "leak: %s %.2f V, below %.2f V", sensor.name(),
                        sensor.value(), t.leakMin())));
                break;
            }
        }
        Double battery = number(rec.get("battery_v"));
        if (battery != null && battery < t.batteryMin()) {
            out.add(new Alert("battery", String.format(Locale.ROOT, "battery %.2f V, below %.2f V", battery, t.batteryMin())));
        } else if (battery != null && prev != null && number(prev.get("battery_v")) != null) {
            long ms = millis(rec) - millis(prev);
            double before = number(prev.get("battery_v"));
            if (ms >= HOUR) {
                double perDay = (before - battery) / (ms / 86_400_000.0);
                if (perDay > t.batteryDrop()) {
                    out.add(new Alert("battery", String.format(Locale.ROOT,
                            "battery falling %.2f V a day (%.2f V to %.2f V in %.1f h), faster than %.2f V a day",
                            perDay, before, battery, ms / 3_600_000.0, t.batteryDrop())));
                }
            }
        }
        Double vacuum = number(rec.get("vacuum_inhg"));
        if (vacuum != null && (vacuum < t.vacuumMin() || vacuum > t.vacuumMax())) {
            out.add(new Alert("vacuum", String.format(Locale.ROOT, "vacuum %.2f inHg, outside %.2f-%.2f inHg", vacuum,
                    t.vacuumMin(), t.vacuumMax())));
        }
        if (s.gps() == null) {
            out.add(new Alert("gps", s.gpsProblem()));
        }
        if (s.becauseText() != null && !t.routine().matcher(s.becauseText()).find()) {
            out.add(new Alert("because", "surfaced because: " + s.becauseText()));
        }
        Double errors = number(rec.get("device_errors"));
        Double errorsBefore = prev == null ? null : number(prev.get("device_errors"));
        if (errors != null && errorsBefore != null && errors > errorsBefore) {
            out.add(new Alert("devices", String.format(Locale.ROOT, "device errors grew from %d to %d",
                    errorsBefore.longValue(), errors.longValue())));
        }
        return out;
    }

    private static Double number(Object o) {
        return o instanceof Number n ? n.doubleValue() : null;
    }

    private static long millis(Map<String, Object> rec) {
        try {
            return Instant.parse(String.valueOf(rec.get("time_utc"))).toEpochMilli();
        } catch (RuntimeException e) {
            return 0;
        }
    }
}
