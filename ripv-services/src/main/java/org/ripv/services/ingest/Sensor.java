package org.ripv.services.ingest;

import java.util.Locale;
import java.util.Set;

/**
 * One column of a DBA file: its label-line name, unit and bytes per value, and what kind of
 * value it holds.
 *
 * @param index the 0-based column
 */
public record Sensor(int index, String name, String unit, int bytes, Kind kind) {
    /** What the ingest does with a column's values. */
    public enum Kind {
        /** A latitude, DDMM.MMMM on the wire, decimal degrees after the reader. */
        LATITUDE,
        /** A longitude, likewise. */
        LONGITUDE,
        /** Anything else: stored as written. */
        PLAIN
    }

    private static final Set<String> LATITUDES = Set.of("m_gps_lat", "m_lat", "c_wpt_lat");
    private static final Set<String> LONGITUDES = Set.of("m_gps_lon", "m_lon", "c_wpt_lon");

    /** The kind a sensor of this name and unit has: a known position name, or the unit {@code lat}/{@code lon}. */
    public static Kind kindOf(String name, String unit) {
        String n = name.toLowerCase(Locale.ROOT);
        String u = unit.toLowerCase(Locale.ROOT);
        if (LATITUDES.contains(n) || u.equals("lat")) {
            return Kind.LATITUDE;
        }
        if (LONGITUDES.contains(n) || u.equals("lon")) {
            return Kind.LONGITUDE;
        }
        return Kind.PLAIN;
    }
}
