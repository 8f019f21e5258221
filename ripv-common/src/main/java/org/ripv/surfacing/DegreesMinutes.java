package org.ripv.surfacing;

/**
 * Slocum positions: degrees and minutes run together ({@code 4137.994} is 41° 37.994'), with a
 * hemisphere letter. The sign of the number and the letter both count, so {@code -7032.188 E} is
 * 70° 32.188' west.
 */
public final class DegreesMinutes {
    /** What a Slocum prints when it has no fix: {@code 69696969}. */
    public static final double NO_FIX = 69696969;

    private DegreesMinutes() {
    }

    /**
     * DDMM.MMM with its hemisphere letter ({@code N}, {@code S}, {@code E}, {@code W}, or a blank
     * for none) as decimal degrees, north and east positive; NaN when it is no position: minutes
     * of 60 or more, Slocum's no-fix value, not finite.
     */
    public static double degrees(double ddmm, char hemisphere) {
        if (!Double.isFinite(ddmm) || Math.abs(ddmm) >= NO_FIX - 1) {
            return Double.NaN;
        }
        double v = Math.abs(ddmm);
        double deg = Math.floor(v / 100);
        double min = v - deg * 100;
        if (min >= 60) {
            return Double.NaN;
        }
        double sign = ddmm < 0 ? -1 : 1;
        if (hemisphere == 'S' || hemisphere == 'W' || hemisphere == 's' || hemisphere == 'w') {
            sign = -sign;
        }
        return sign * (deg + min / 60);
    }

    /** True when {@code lat}, {@code lon} is a place on Earth. */
    public static boolean valid(double lat, double lon) {
        return Double.isFinite(lat) && Double.isFinite(lon) && Math.abs(lat) <= 90 && Math.abs(lon) <= 180;
    }
}
