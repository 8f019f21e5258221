package org.ripv.plans;

/**
 * One waypoint of a goto list: {@code n} is the glider's own index (0 to N-1, as
 * {@code initial_wpt} counts), {@code lonText}/{@code latText} the DDMM.mmmm words as written,
 * {@code lat}/{@code lon} decimal degrees (north and east positive).
 */
public record Waypoint(int n, int line, String lonText, String latText, double lat, double lon, String comment) {
}
