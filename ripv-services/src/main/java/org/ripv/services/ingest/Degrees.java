package org.ripv.services.ingest;

/**
 * Slocum positions: degrees and minutes packed as DDMM.MMMM ({@code 3950.8632} is 39° 50.8632′,
 * {@code -7046.3354} is -70° 46.3354′), and {@value #NO_FIX} for "no fix".
 */
public final class Degrees {
    /** What a glider writes in a position sensor when it has no fix. */
    public static final double NO_FIX = 69696969;

    private Degrees() {}

    /** Decimal places kept: 1e-9 degrees is a tenth of a millimetre, far below any glider's fix. */
    static final double SCALE = 1e9;

    /**
     * DDMM.MMMM to decimal degrees, or NaN when the value is not a position: minutes of 60 or
     * more, or more degrees than {@code maxDegrees} (90 for a latitude, 180 for a longitude).
     * Rounded to 9 decimals, so that 3950.8632 is stored and shown as 39.84772, not as the
     * division's 39.847719999999995 (short decimals are also what the database and the plot
     * workers print and parse fastest).
     */
    public static double fromDdmm(double packed, double maxDegrees) {
        if (!Double.isFinite(packed)) {
            return Double.NaN;
        }
        double a = Math.abs(packed);
        double degrees = Math.floor(a / 100);
        double minutes = a - degrees * 100;
        if (minutes >= 60 || degrees > maxDegrees) {
            return Double.NaN;
        }
        double d = degrees + minutes / 60;
        if (d > maxDegrees) {
            return Double.NaN;
        }
        return Math.copySign(Math.round(d * SCALE) / SCALE, packed);
    }
}
