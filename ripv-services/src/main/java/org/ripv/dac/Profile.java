package org.ripv.dac;

/**
 * One dive or climb, ready to write: per-sample values in time order (NaN where there is none)
 * and the profile's own scalars. Pressure is in dbar, depth in m (positive down), temperature
 * in °C, conductivity in S m⁻¹, salinity PSS-78, density kg m⁻³.
 */
public record Profile(String vehicle, String segment, boolean delayed, int id, int direction,
                      double[] time, double[] lat, double[] lon, double[] pressure, double[] depth,
                      double[] temperature, double[] conductivity, double[] salinity, double[] density,
                      double profileTime, double profileLat, double profileLon,
                      double uvTime, double latUv, double lonUv, double u, double v) {

    public int size() {
        return time.length;
    }

    /** A variable's values by its DAC name. */
    public double[] values(String variable) {
        return switch (variable) {
            case "time" -> time;
            case "lat" -> lat;
            case "lon" -> lon;
            case "pressure" -> pressure;
            case "depth" -> depth;
            case "temperature" -> temperature;
            case "conductivity" -> conductivity;
            case "salinity" -> salinity;
            case "density" -> density;
            default -> throw new IllegalArgumentException("no per-sample variable " + variable);
        };
    }

    /** A scalar variable by its DAC name. */
    public double scalar(String variable) {
        return switch (variable) {
            case "profile_time" -> profileTime;
            case "profile_lat" -> profileLat;
            case "profile_lon" -> profileLon;
            case "time_uv" -> uvTime;
            case "lat_uv" -> latUv;
            case "lon_uv" -> lonUv;
            case "u" -> u;
            case "v" -> v;
            default -> throw new IllegalArgumentException("no scalar variable " + variable);
        };
    }
}
