package org.ripv.surfacing;

import java.time.Instant;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One surface dialog, as far as the vehicle printed it. Every part is null (or empty) when the
 * dialog did not say it; nothing here is ever invented.
 *
 * @param vehicle        from {@code Glider NAME at surface.} or {@code Vehicle Name: NAME}
 * @param because        why it surfaced, without the bracketed detail: {@code Surface interval}
 * @param becauseText    the whole text after {@code Because:}
 * @param mission        {@code MissionName:}
 * @param missionNum     {@code MissionNum:}
 * @param vehicleTime    the vehicle's clock ({@code Curr Time:}, UTC)
 * @param missionTime    seconds into the mission ({@code MT:})
 * @param gps            the valid fix of {@code GPS Location:}; null when there was none
 * @param gpsProblem     why there is no valid fix ({@code GPS Invalid}, {@code TooFar}, out of
 *                       range, no GPS line), the vehicle's own text quoted; null when there is one
 * @param dr             the dead-reckoned position ({@code DR  Location:})
 * @param sensors        the surface list's sensors by name, in the order printed
 * @param devices        {@code devices:(t/m/s) errs: … warn: … oddity: …}
 * @param aborts         the {@code ABORT HISTORY:} block
 * @param prompt         the GliderDOS prompt that ended the dialog
 * @param countdown      seconds of the dive countdown when the dialog ended on it
 * @param unknown        lines of the dialog the parser does not know (at most {@link SurfaceDialogParser#MAX_UNKNOWN})
 * @param dropped        sensors and unknown lines left out by the bounds
 * @param linesCut       lines cut at {@link SurfaceDialogParser#MAX_LINE} characters
 * @param end            what ended it
 */
public record Surfacing(String vehicle, String because, String becauseText, String mission, String missionNum,
                        Instant vehicleTime, Long missionTime, Position gps, String gpsProblem, Position dr,
                        Map<String, Sensor> sensors, Devices devices, AbortHistory aborts, Prompt prompt, Long countdown,
                        List<String> unknown, int dropped, int linesCut, End end) {

    public Surfacing {
        sensors = Collections.unmodifiableMap(new LinkedHashMap<>(sensors));
        unknown = List.copyOf(unknown);
    }

    /** What ended a dialog. */
    public enum End {
        /** The dive countdown ("Hit Control-C within N seconds …"). */
        COUNTDOWN,
        /** A shell prompt (GliderDOS, PicoDOS). */
        PROMPT,
        /** The next dialog began. */
        NEXT_DIALOG,
        /** The call ended ({@link SurfaceDialogParser#end()}). */
        CALL_ENDED,
        /** It ran past {@link SurfaceDialogParser#MAX_DIALOG_LINES} lines. */
        TOO_LONG
    }

    /** A position in decimal degrees, north and east positive; {@code ageSeconds} null when not printed. */
    public record Position(double lat, double lon, Double ageSeconds) {}

    /**
     * A surface-list sensor.
     *
     * @param units      as printed in brackets, or empty
     * @param text       the value as printed
     * @param value      the value as a number, null when it is none
     * @param ageSeconds how long ago it was measured, null when not printed
     */
    public record Sensor(String name, String units, String text, Double value, Double ageSeconds) {}

    /** Counts since reset, this mission, this segment ({@code t/m/s}). */
    public record Counts(long total, long mission, long segment) {}

    /** The device error, warning and oddity counts. */
    public record Devices(Counts errors, Counts warnings, Counts oddities) {}

    /**
     * The {@code ABORT HISTORY:} block: aborts since reset and the last one.
     *
     * @param time as printed (the vehicle's clock)
     */
    public record AbortHistory(Long total, String cause, String details, String time, String segment, String mission) {}

    /**
     * A shell prompt: {@code GliderDos A 8 >} is shell GliderDOS, status letter {@code A}, abort code 8.
     *
     * @param status the status letter, or null (PicoDOS has none)
     * @param code   the number after it, or null
     */
    public record Prompt(String shell, String status, Integer code) {}

    /** A sensor's value as a number, or null. */
    public Double value(String sensor) {
        Sensor s = sensors.get(sensor);
        return s == null ? null : s.value();
    }
}
