package org.ripv.plans;

import java.math.BigDecimal;
import java.util.Locale;
import java.util.regex.Pattern;

/**
 * Slocum's DDMM.mmmm (DDDMM.mmmm for longitude): degrees and minutes run together, the sign in
 * front ({@code -7032.188} is 70° 32.188' west = -70.53647). Exact: the split is done on the
 * decimal text, so {@code 4159.9999} never becomes 60 minutes by rounding.
 */
final class DegreesMinutes {
    /** Plain decimals only: no exponent, no hex, at most 24 characters (a hostile word cannot cost more). */
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d{1,8}(\\.\\d{0,12})?|\\.\\d{1,12})");
    private static final BigDecimal HUNDRED = BigDecimal.valueOf(100);
    private static final BigDecimal SIXTY = BigDecimal.valueOf(60);

    private DegreesMinutes() {
    }

    /** Decimal degrees of {@code text}, or an exception whose message says what is wrong (for a {@code FILE:LINE:}). */
    static double degrees(String text, boolean latitude) {
        String what = latitude ? "latitude" : "longitude";
        if (!DECIMAL.matcher(text).matches()) {
            throw new IllegalArgumentException(what + " '" + Quote.cut(text) + "' is not a number in DDMM.mmmm");
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
