package org.ripv.dac;

/**
 * What one segment's flight and science files hold that profiles need, decoded. Science samples
 * are the rows with a pressure, in time order ({@code sci_m_present_time}); pressure is as the
 * glider writes it, in bar. Positions: GPS fixes and dead-reckoned positions (decimal degrees)
 * of the flight file; the depth-averaged current is the segment's last {@code m_water_vx/vy}.
 *
 * @param name     the header's {@code full_filename}, e.g. {@code rosie_713-2019-166-0-157}
 * @param vehicle  the glider's name (the name before the first '-')
 * @param delayed  true for the full files of a recovered glider ({@code .dbd/.ebd}), false for a call's ({@code .sbd/.tbd})
 */
public record Segment(String name, String vehicle, boolean delayed, String scienceFile,
                      double[] time, double[] pressureBar, double[] temperature, double[] conductivity,
                      Track gps, Track deadReckoned,
                      double uvTime, double u, double v) {

    /** Positions in time order. */
    public record Track(double[] time, double[] lat, double[] lon) {
        public int size() {
            return time.length;
        }
    }
}
