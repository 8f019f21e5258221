package org.ripv.dac;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * A segment's profiles with every value the DAC file holds: pressure in dbar (the glider's bar ×
 * 10), position per sample, depth from pressure and latitude ({@link Gsw#zFromP}), Practical
 * Salinity from conductivity (S m⁻¹ × 10 = mS cm⁻¹), temperature and pressure, and in-situ density
 * from Absolute Salinity (SAAR 0, see {@link Gsw}) and Conservative Temperature.
 *
 * <p>Positions: linear in time between the GPS fixes around a sample (fixes of every flight file
 * given); where no fix brackets it, between the dead-reckoned positions of its segment; failing
 * both, the nearest fix. {@code profile_time} is the mid-point of the profile's first and last
 * times, {@code profile_lat/lon} the position then. {@code u}/{@code v} are the segment's
 * depth-averaged current (its last {@code m_water_vx/vy}), placed at that time.
 * {@code profile_id} is the profile's first time in whole seconds since 1970: unique and
 * increasing within a deployment, and the same for a real-time and a delayed-mode file of the
 * same dive.
 */
public final class Profiles {
    private Profiles() {
    }

    public static List<Profile> of(Segment s, ProfileSplitter splitter) throws DacException {
        int n = s.time().length;
        double[] dbar = new double[n];
        for (int i = 0; i < n; i++) {
            dbar[i] = s.pressureBar()[i] * 10;
        }
        if (s.gps().size() == 0 && s.deadReckoned().size() == 0) {
            throw new DacException(s.scienceFile() + ": no position: neither a GPS fix nor a dead-reckoned position in the flight files given");
        }
        List<Profile> out = new ArrayList<>();
        for (ProfileSplitter.Range r : splitter.split(dbar, s.scienceFile())) {
            out.add(profile(s, dbar, r));
        }
        return out;
    }

    private static Profile profile(Segment s, double[] dbar, ProfileSplitter.Range r) {
        int m = r.size();
        double[] t = Arrays.copyOfRange(s.time(), r.from(), r.to() + 1);
        double[] p = Arrays.copyOfRange(dbar, r.from(), r.to() + 1);
        double[] temp = Arrays.copyOfRange(s.temperature(), r.from(), r.to() + 1);
        double[] cond = Arrays.copyOfRange(s.conductivity(), r.from(), r.to() + 1);
        double[] lat = new double[m], lon = new double[m], depth = new double[m], sal = new double[m], rho = new double[m];
        for (int i = 0; i < m; i++) {
            double[] pos = position(s, t[i]);
            lat[i] = pos[0];
            lon[i] = pos[1];
            depth[i] = -Gsw.zFromP(p[i], lat[i]);
            sal[i] = Gsw.spFromC(cond[i] * 10, temp[i], p[i]);
            double sa = Gsw.saFromSp(sal[i], 0);
            rho[i] = Gsw.rho(sa, Gsw.ctFromT(sa, temp[i], p[i]), p[i]);
        }
        double mid = (t[0] + t[m - 1]) / 2;
        double[] at = position(s, mid);
        double[] uv = Double.isFinite(s.uvTime()) ? position(s, s.uvTime()) : new double[] {Double.NaN, Double.NaN};
        return new Profile(s.vehicle(), s.name(), s.delayed(), (int) Math.floor(t[0]), r.direction(),
                t, lat, lon, p, depth, temp, cond, sal, rho, mid, at[0], at[1],
                s.uvTime(), uv[0], uv[1], s.u(), s.v());
    }

    static double[] position(Segment s, double t) {
        double[] p = interpolate(s.gps(), t);
        if (p == null) {
            p = interpolate(s.deadReckoned(), t);
        }
        if (p == null) {
            p = nearest(s.gps().size() > 0 ? s.gps() : s.deadReckoned(), t);
        }
        return p;
    }

    private static double[] interpolate(Segment.Track tr, double t) {
        double[] ts = tr.time();
        if (ts.length == 0 || t < ts[0] || t > ts[ts.length - 1]) {
            return null;
        }
        int i = Arrays.binarySearch(ts, t);
        if (i >= 0) {
            return new double[] {tr.lat()[i], tr.lon()[i]};
        }
        int hi = -i - 1;
        int lo = hi - 1;
        double f = (t - ts[lo]) / (ts[hi] - ts[lo]);
        return new double[] {tr.lat()[lo] + f * (tr.lat()[hi] - tr.lat()[lo]), tr.lon()[lo] + f * (tr.lon()[hi] - tr.lon()[lo])};
    }

    private static double[] nearest(Segment.Track tr, double t) {
        double[] ts = tr.time();
        int best = 0;
        for (int i = 1; i < ts.length; i++) {
            if (Math.abs(ts[i] - t) < Math.abs(ts[best] - t)) {
                best = i;
            }
        }
        return new double[] {tr.lat()[best], tr.lon()[best]};
    }
}
