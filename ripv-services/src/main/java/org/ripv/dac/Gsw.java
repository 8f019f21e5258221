package org.ripv.dac;

/**
 * The few TEOS-10 (Gibbs SeaWater) functions a glider profile needs, from their published
 * formulas: Practical Salinity from conductivity (PSS-78 with the Hill et al. extension below 2),
 * Absolute Salinity, Conservative Temperature, in-situ density (the 75-term polynomial of
 * Roquet et al. 2015) and height from pressure. Each agrees with the GSW check values
 * ({@code GswTest}). Inputs and outputs are GSW's units: conductivity mS/cm, pressure dbar
 * (sea pressure), temperature ITS-90 °C, salinity g/kg (SA) or unitless (SP). A value outside
 * what the formula takes gives NaN (GSW's "invalid value").
 *
 * <p>Absolute Salinity here is SP × uPS × (1 + SAAR) with the Absolute Salinity Anomaly Ratio
 * passed in: GSW looks SAAR up in a 3-D atlas (of order 10⁻⁴), which RIPV does not ship. With
 * SAAR = 0 it is Reference Salinity (GSW's {@code gsw_SR_from_SP}); docs/dac.md says what that
 * changes (density by at most a few thousandths of kg m⁻³).
 */
public final class Gsw {
    private Gsw() {
    }

    static final double SSO = 35.16504;
    static final double UPS = SSO / 35.0;
    private static final double SFAC = 0.0248826675584615;
    private static final double OFFSET = 5.971840214030754e-1;
    private static final double CP0 = 3991.86795711963;
    private static final double T0 = 273.15;
    private static final double C3515 = 42.9140;
    private static final double GAMMA = 2.26e-7;
    private static final double DB2PA = 1.0e4;

    // PSS-78
    private static final double A0 = 0.0080, A1 = -0.1692, A2 = 25.3851, A3 = 14.0941, A4 = -7.0261, A5 = 2.7081;
    private static final double B0 = 0.0005, B1 = -0.0056, B2 = -0.0066, B3 = -0.0375, B4 = 0.0636, B5 = -0.0144;
    private static final double C0 = 0.6766097, C1 = 2.00564e-2, C2 = 1.104259e-4, C3 = -6.9698e-7, C4 = 1.0031e-9;
    private static final double D1 = 3.426e-2, D2 = 4.464e-4, D3 = 4.215e-1, D4 = -3.107e-3;
    private static final double E1 = 2.070e-5, E2 = -6.370e-10, E3 = 3.989e-15, K = 0.0162;

    /** Practical Salinity (PSS-78) from conductivity C (mS/cm), in-situ temperature t (°C) and sea pressure p (dbar). */
    public static double spFromC(double c, double t, double p) {
        double t68 = t * 1.00024;
        double ft68 = (t68 - 15) / (1 + K * (t68 - 15));
        double r = c / C3515;
        double rtLc = C0 + (C1 + (C2 + (C3 + C4 * t68) * t68) * t68) * t68;
        double rp = 1 + (p * (E1 + E2 * p + E3 * p * p)) / (1 + D1 * t68 + D2 * t68 * t68 + (D3 + D4 * t68) * r);
        double rt = r / (rp * rtLc);
        if (!(rt >= 0)) {
            return Double.NaN;
        }
        double rtx = Math.sqrt(rt);
        double sp = pss78(rtx, ft68);
        if (sp < 2) {
            // Hill et al. (1986), scaled to meet PSS-78 at SP = 2
            double x = 400 * rt;
            double sqrty = 10 * rtx;
            double part1 = 1 + x * (1.5 + x);
            double part2 = 1 + sqrty * (1 + sqrty * (1 + sqrty));
            sp = hillRatioAtSp2(t) * (sp - A0 / part1 - B0 * ft68 / part2);
        }
        return sp < 0 ? Double.NaN : sp;
    }

    private static double pss78(double rtx, double ft68) {
        return A0 + (A1 + (A2 + (A3 + (A4 + A5 * rtx) * rtx) * rtx) * rtx) * rtx
                + ft68 * (B0 + (B1 + (B2 + (B3 + (B4 + B5 * rtx) * rtx) * rtx) * rtx) * rtx);
    }

    private static double dPss78(double rtx, double ft68) {
        return A1 + (2 * A2 + (3 * A3 + (4 * A4 + 5 * A5 * rtx) * rtx) * rtx) * rtx
                + ft68 * (B1 + (2 * B2 + (3 * B3 + (4 * B4 + 5 * B5 * rtx) * rtx) * rtx) * rtx);
    }

    /** The Hill ratio at SP = 2: one modified Newton-Raphson step for Rt there from a polynomial first guess. */
    private static double hillRatioAtSp2(double t) {
        double t68 = t * 1.00024;
        double ft68 = (t68 - 15) / (1 + K * (t68 - 15));
        double rtx0 = 2.641463563366498e-1 + t68 * (2.007883247811176e-4 + t68 * (-4.107694432853053e-6
                + t68 * (8.401670882091225e-8 + t68 * (-1.711392021989210e-9 + t68 * (3.374193893377380e-11
                + t68 * (-5.923731174730784e-13 + t68 * (8.057771569962299e-15 + t68 * (-7.054313817447962e-17
                + t68 * 2.859992717347235e-19))))))));
        double spEst = pss78(rtx0, ft68);
        double rtx = rtx0 - (spEst - 2) / dPss78(rtx0, ft68);
        rtx = rtx0 - (spEst - 2) / dPss78(0.5 * (rtx + rtx0), ft68);
        double x = 400 * rtx * rtx;
        double sqrty = 10 * rtx;
        double part1 = 1 + x * (1.5 + x);
        double part2 = 1 + sqrty * (1 + sqrty * (1 + sqrty));
        return 2 / (2 - A0 / part1 - B0 * ft68 / part2);
    }

    /** Reference Salinity (g/kg) from Practical Salinity. */
    public static double srFromSp(double sp) {
        return sp * UPS;
    }

    /** Absolute Salinity (g/kg) from Practical Salinity and the Absolute Salinity Anomaly Ratio (0: Reference Salinity). */
    public static double saFromSp(double sp, double saar) {
        return UPS * sp * (1 + saar);
    }

    /** Conservative Temperature (°C) from Absolute Salinity, in-situ temperature and sea pressure. */
    public static double ctFromT(double sa, double t, double p) {
        return ctFromPt(sa, pt0FromT(sa, t, p));
    }

    static double ctFromPt(double sa, double pt) {
        double x2 = SFAC * sa;
        double x = Math.sqrt(x2);
        double y = pt * 0.025;
        double potEnthalpy = 61.01362420681071 + y * (168776.46138048015 + y * (-2735.2785605119625
                + y * (2574.2164453821433 + y * (-1536.6644434977543 + y * (545.7340497931629
                + (-50.91091728474331 - 18.30489878927802 * y) * y)))))
                + x2 * (268.5520265845071 + y * (-12019.028203559312 + y * (3734.858026725145
                + y * (-2046.7671145057618 + y * (465.28655623826234 + (-0.6370820302376359
                - 10.650848542359153 * y) * y))))
                + x * (937.2099110620707 + y * (588.1802812170108 + y * (248.39476522971285
                + (-3.871557904936333 - 2.6268019854268356 * y) * y))
                + x * (-1687.914374187449 + x * (246.9598888781377 + x * (123.59576582457964
                - 48.5891069025409 * x))
                + y * (936.3206544460336 + y * (-942.7827304544439 + y * (369.4389437509002
                + (-33.83664947895248 - 9.987880382780322 * y) * y))))));
        return potEnthalpy / CP0;
    }

    /** Potential temperature referred to 0 dbar: a first guess, then two modified Newton-Raphson steps on entropy. */
    static double pt0FromT(double sa, double t, double p) {
        double s1 = sa / UPS;
        double pt0 = t + p * (8.65483913395442e-6 - s1 * 1.41636299744881e-6 - p * 7.38286467135737e-9
                + t * (-8.38241357039698e-6 + s1 * 2.83933368585534e-8 + t * 1.77803965218656e-8
                + p * 1.71155619208233e-10));
        double dentropyDt = CP0 / ((T0 + pt0) * (1 - 0.05 * (1 - sa / SSO)));
        double trueEntropyPart = entropyPart(sa, t, p);
        for (int i = 0; i < 2; i++) {
            double old = pt0;
            double dentropy = entropyPartZeroP(sa, old) - trueEntropyPart;
            pt0 = old - dentropy / dentropyDt;
            dentropyDt = -gibbsPt0Pt0(sa, 0.5 * (pt0 + old));
            pt0 = old - dentropy / dentropyDt;
        }
        return pt0;
    }

    static double entropyPart(double sa, double t, double p) {
        double x2 = SFAC * sa;
        double x = Math.sqrt(x2);
        double y = t * 0.025;
        double z = p * 1e-4;
        double g03 = z * (-270.983805184062 + z * (776.153611613101 + z * (-196.51255088122
                + (28.9796526294175 - 2.13290083518327 * z) * z)))
                + y * (-24715.571866078 + z * (2910.0729080936 + z * (-1513.116771538718
                + z * (546.959324647056 + z * (-111.1208127634436 + 8.68841343834394 * z))))
                + y * (2210.2236124548363 + z * (-2017.52334943521 + z * (1498.081172457456
                + z * (-718.6359919632359 + (146.4037555781616 - 4.9892131862671505 * z) * z)))
                + y * (-592.743745734632 + z * (1591.873781627888 + z * (-1207.261522487504
                + (608.785486935364 - 105.4993508931208 * z) * z))
                + y * (290.12956292128547 + z * (-973.091553087975 + z * (602.603274510125
                + z * (-276.361526170076 + 32.40953340386105 * z)))
                + y * (-113.90630790850321 + y * (21.35571525415769 - 67.41756835751434 * z)
                + z * (381.06836198507096 + z * (-133.7383902842754 + 49.023632509086724 * z)))))));
        double g08 = x2 * (z * (729.116529735046 + z * (-343.956902961561 + z * (124.687671116248
                + z * (-31.656964386073 + 7.04658803315449 * z))))
                + x * (x * (y * (-137.1145018408982 + y * (148.10030845687618 + y * (-68.5590309679152
                + 12.4848504784754 * y))) - 22.6683558512829 * z)
                + z * (-175.292041186547 + (83.1923927801819 - 29.483064349429 * z) * z)
                + y * (-86.1329351956084 + z * (766.116132004952 + z * (-108.3834525034224 + 51.2796974779828 * z))
                + y * (-30.0682112585625 - 1380.9597954037708 * z + y * (3.50240264723578 + 938.26075044542 * z))))
                + y * (1760.062705994408 + y * (-675.802947790203 + y * (365.7041791005036
                + y * (-108.30162043765552 + 12.78101825083098 * y)
                + z * (-1190.914967948748 + (298.904564555024 - 145.9491676006352 * z) * z))
                + z * (2082.7344423998043 + z * (-614.668925894709 + (340.685093521782 - 33.3848202979239 * z) * z)))
                + z * (-1721.528607567954 + z * (674.819060538734 + z * (-356.629112415276
                + (88.4080716616 - 15.84003094423364 * z) * z)))));
        return -(g03 + g08) * 0.025;
    }

    static double entropyPartZeroP(double sa, double pt0) {
        double x2 = SFAC * sa;
        double x = Math.sqrt(x2);
        double y = pt0 * 0.025;
        double g03 = y * (-24715.571866078 + y * (2210.2236124548363 + y * (-592.743745734632
                + y * (290.12956292128547 + y * (-113.90630790850321 + y * 21.35571525415769)))));
        double g08 = x2 * (x * (x * (y * (-137.1145018408982 + y * (148.10030845687618
                + y * (-68.5590309679152 + 12.4848504784754 * y))))
                + y * (-86.1329351956084 + y * (-30.0682112585625 + y * 3.50240264723578)))
                + y * (1760.062705994408 + y * (-675.802947790203 + y * (365.7041791005036
                + y * (-108.30162043765552 + 12.78101825083098 * y)))));
        return -(g03 + g08) * 0.025;
    }

    static double gibbsPt0Pt0(double sa, double pt0) {
        double x2 = SFAC * sa;
        double x = Math.sqrt(x2);
        double y = pt0 * 0.025;
        double g03 = -24715.571866078 + y * (4420.4472249096725 + y * (-1778.231237203896
                + y * (1160.5182516851419 + y * (-569.531539542516 + y * 128.13429152494615))));
        double g08 = x2 * (1760.062705994408 + x * (-86.1329351956084 + x * (-137.1145018408982
                + y * (296.20061691375236 + y * (-205.67709290374563 + 49.9394019139016 * y)))
                + y * (-60.136422517125 + y * 10.50720794170734))
                + y * (-1351.605895580406 + y * (1097.1125373015109 + y * (-433.20648175062206
                + 63.905091254154904 * y))));
        return (g03 + g08) * 0.000625;
    }

    /** In-situ density (kg m⁻³) from Absolute Salinity, Conservative Temperature and sea pressure (75-term polynomial). */
    public static double rho(double sa, double ct, double p) {
        return 1.0 / specvol(sa, ct, p);
    }

    static double specvol(double sa, double ct, double p) {
        double xs = Math.sqrt(SFAC * sa + OFFSET);
        double ys = ct * 0.025;
        double z = p * 1e-4;
        return 1.0769995862e-3
                + xs * (-3.1038981976e-4 + xs * (6.6928067038e-4 + xs * (-8.5047933937e-4 + xs * (5.8086069943e-4
                + xs * (-2.1092370507e-4 + 3.1932457305e-5 * xs)))))
                + ys * (-1.5649734675e-5 + xs * (3.5009599764e-5 + xs * (-4.3592678561e-5 + xs * (3.4532461828e-5
                + xs * (-1.1959409788e-5 + 1.3864594581e-6 * xs))))
                + ys * (2.7762106484e-5 + xs * (-3.7435842344e-5 + xs * (3.5907822760e-5 + xs * (-1.8698584187e-5
                + 3.8595339244e-6 * xs)))
                + ys * (-1.6521159259e-5 + xs * (2.4141479483e-5 + xs * (-1.4353633048e-5 + 2.2863324556e-6 * xs))
                + ys * (6.9111322702e-6 + xs * (-8.7595873154e-6 + 4.3703680598e-6 * xs)
                + ys * (-8.0539615540e-7 + -3.3052758900e-7 * xs + 2.0543094268e-7 * ys)))))
                + z * (-6.0799143809e-5 + xs * (2.4262468747e-5 + xs * (-3.4792460974e-5 + xs * (3.7470777305e-5
                + xs * (-1.7322218612e-5 + 3.0927427253e-6 * xs))))
                + ys * (1.8505765429e-5 + xs * (-9.5677088156e-6 + xs * (1.1100834765e-5 + xs * (-9.8447117844e-6
                + 2.5909225260e-6 * xs)))
                + ys * (-1.1716606853e-5 + xs * (-2.3678308361e-7 + xs * (2.9283346295e-6 + -4.8826139200e-7 * xs))
                + ys * (7.9279656173e-6 + xs * (-3.4558773655e-6 + 3.1655306078e-7 * xs)
                + ys * (-3.4102187482e-6 + 1.2956717783e-6 * xs + 5.0736766814e-7 * ys))))
                + z * (9.9856169219e-6 + xs * (-5.8484432984e-7 + xs * (-4.8122251597e-6 + xs * (4.9263106998e-6
                + -1.7811974727e-6 * xs)))
                + ys * (-1.1736386731e-6 + xs * (-5.5699154557e-6 + xs * (5.4620748834e-6 + -1.3544185627e-6 * xs))
                + ys * (2.1305028740e-6 + xs * (3.9137387080e-7 + -6.5731104067e-7 * xs)
                + ys * (-4.6132540037e-7 + 7.7618888092e-9 * xs + -6.3352916514e-8 * ys)))
                + z * (-1.1309361437e-6 + xs * (3.6310188515e-7 + 1.6746303780e-8 * xs)
                + ys * (-3.6527006553e-7 + -2.7295696237e-7 * xs + 2.8695905159e-7 * ys)
                + z * (1.0531153080e-7 + -1.1147125423e-7 * xs + 3.1454099902e-7 * ys
                + z * (-1.2647261286e-8 + 1.9613503930e-9 * z)))));
    }

    /** Height z (m, negative in the ocean) from sea pressure and latitude, for a zero dynamic height anomaly. */
    public static double zFromP(double p, double lat) {
        double x = Math.sin(Math.toRadians(lat));
        double sin2 = x * x;
        double b = 9.780327 * (1.0 + (5.2792e-3 + (2.32e-5 * sin2)) * sin2);
        double a = -0.5 * GAMMA * b;
        double c = enthalpySso0(p);
        return -2.0 * c / (b + Math.sqrt(b * b - 4.0 * a * c));
    }

    static double enthalpySso0(double p) {
        double z = p * 1.0e-4;
        double dynamic = z * (9.726613854843870e-4 + z * (-2.252956605630465e-5 + z * (2.376909655387404e-6
                + z * (-1.664294869986011e-7 + z * (-5.988108894465758e-9 + z * (-2.10787688100e-9
                + 2.80192913290e-10 * z))))));
        return dynamic * DB2PA * 1.0e4;
    }
}
