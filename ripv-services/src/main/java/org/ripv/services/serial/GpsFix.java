package org.ripv.services.serial;

import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A position from a Slocum surface dialog's GPS line,
 * {@code GPS Location:  4137.994 N -7032.188 E measured 26.0 secs ago}: degrees and minutes run
 * together (DDMM.MMM, DDDMM.MMM), turned into decimal degrees with north and east positive. The
 * sign of the number and the hemisphere letter both count: {@code -7032.188 E} is 70° 32.188' west.
 *
 * @param lat decimal degrees, north positive
 * @param lon decimal degrees, east positive
 */
record GpsFix(double lat, double lon) {
    private static final Pattern LINE = Pattern.compile(
            "GPS Location:\\s*([-+]?\\d{1,5}(?:\\.\\d+)?)\\s*([NS])\\s+([-+]?\\d{1,5}(?:\\.\\d+)?)\\s*([EW])");

    /** The fix in {@code line}, if it is a GPS Location line with a valid position. */
    static Optional<GpsFix> parse(CharSequence line) {
        Matcher m = LINE.matcher(line);
        if (!m.find()) {
            return Optional.empty();
        }
        double lat = degrees(Double.parseDouble(m.group(1)), m.group(2).charAt(0));
        double lon = degrees(Double.parseDouble(m.group(3)), m.group(4).charAt(0));
        if (Double.isNaN(lat) || Double.isNaN(lon) || Math.abs(lat) > 90 || Math.abs(lon) > 180) {
            return Optional.empty(); // Slocum prints 69696969 when it has no fix
        }
        return Optional.of(new GpsFix(lat, lon));
    }

    /** DDMM.MMM with its hemisphere to decimal degrees; NaN when the minutes are 60 or more. */
    static double degrees(double ddmm, char hemisphere) {
        double v = Math.abs(ddmm);
        double deg = Math.floor(v / 100);
        double min = v - deg * 100;
        if (min >= 60) {
            return Double.NaN;
        }
        double sign = Math.signum(ddmm) < 0 ? -1 : 1;
        if (hemisphere == 'S' || hemisphere == 'W') {
            sign = -sign;
        }
        return sign * (deg + min / 60);
    }
}
