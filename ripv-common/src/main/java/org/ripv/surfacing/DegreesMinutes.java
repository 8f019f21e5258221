package org.ripv.surfacing;

import java.math.BigDecimal;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Slocum positions: degrees and minutes run together ({@code 4137.994} is 41° 37.994'), with a
 * hemisphere letter. The sign of the number and the letter both count, so {@code -7032.188 E} is
 * 70° 32.188' west. The one place both the dialog parser and the behaviour-file reader
 * ({@code org.ripv.plans}) turn DDMM.mmmm into degrees.
 */
public final class DegreesMinutes {
    /** What a Slocum prints when it has no fix: {@code 69696969}. */
    public static final double NO_FIX = 69696969;
    /** Plain decimals only: no exponent, no hex, at most 24 characters (a hostile word cannot cost more). */
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d{1,8}(\\.\\d{0,12})?|\\.\\d{1,12})");
    private static final BigDecimal HUNDRED = BigDecimal.valueOf(100);
    private static final BigDecimal SIXTY = BigDecimal.valueOf(60);

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

    /**
     * A file's DDMM.mmmm text (DDDMM.mmmm for longitude, signed: west and south negative) as
     * decimal degrees, checked strictly, or an exception whose message says what is wrong (for a
     * {@code FILE:LINE:}). Exact: the split is done on the decimal text, so {@code 4159.9999}
     * never becomes 60 minutes by rounding.
     */
    public static double parse(String text, boolean latitude) {
        String what = latitude ? "latitude" : "longitude";
        if (!DECIMAL.matcher(text).matches()) {
            String cut = text.length() <= 40 ? text : text.substring(0, 40) + "…";
            throw new IllegalArgumentException(what + " '" + cut + "' is not a number in DDMM.mmmm");
        }
        BigDecimal v = new BigDecimal(text);
        BigDecimal a = v.abs();
        BigDecimal degrees = a.divideToIntegralValue(HUNDRED);
        BigDecimal minutes = a.subtract(degrees.multiply(HUNDRED));
        if (minutes.compareTo(SIXTY) >= 0) {
            throw new IllegalArgumentException(what + " '" + text + "' has " + minutes.stripTrailingZeros().toPlainString()
                    + " minutes: minutes must be under 60 (DDMM.mmmm)");
        }
        double deg = degrees.doubleValue() + minutes.doubleValue() / 60.0;
        int max = latitude ? 90 : 180;
        if (deg > max) {
            throw new IllegalArgumentException(what + " '" + text + "' is " + String.format(Locale.ROOT, "%.5f", deg)
                    + "°, over " + max + "°");
        }
        return v.signum() < 0 ? -deg : deg;
    }
}
