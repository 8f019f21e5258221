package org.ripv.services.simulator;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.Locale;

/**
 * What a Slocum glider prints when it surfaces and calls in: its name, the time, dead-reckoned
 * and GPS positions in degrees and minutes run together (DDMM.MMM, the sign and the hemisphere
 * letter both as the glider prints them), battery, and mission. The simulated glider drifts a
 * little north-east on every call and its battery runs down.
 */
final class SurfaceDialog {
    /** Where the first call is: 41° 37.994' N, 70° 32.188' W (off Woods Hole). */
    static final double START_LAT = 41 + 37.994 / 60;
    static final double START_LON = -(70 + 32.188 / 60);
    private static final DateTimeFormatter CTIME = DateTimeFormatter.ofPattern("EEE MMM dd HH:mm:ss yyyy", Locale.ROOT)
            .withZone(ZoneOffset.UTC);

    private final String name;
    private final long start = System.nanoTime();

    SurfaceDialog(String name) {
        this.name = name;
    }

    /** The position on call {@code n} (1 for the first). */
    static double[] position(int n) {
        return new double[] {START_LAT + (n - 1) * 0.01, START_LON + (n - 1) * 0.01};
    }

    /** DDMM.MMM as a glider prints it: {@code 4137.994}, {@code -7032.188}. */
    static String degreesMinutes(double decimal) {
        double v = Math.abs(decimal);
        int deg = (int) Math.floor(v);
        double min = (v - deg) * 60;
        if (min >= 59.9995) { // would print as 60.000
            deg++;
            min = 0;
        }
        return String.format(Locale.ROOT, "%s%d%06.3f", decimal < 0 ? "-" : "", deg, min);
    }

    String text(int call, Instant now) {
        return text(call, now, "SIM.MI", "");
    }

    /** The dialog of call {@code call} running {@code mission}, with the report list's lines under the sensors. */
    String text(int call, Instant now, String mission, String reportLines) {
        double[] p = position(call);
        long missionTime = (System.nanoTime() - start) / 1_000_000_000L;
        String gps = degreesMinutes(p[0]) + " N " + degreesMinutes(p[1]) + " E";
        String dr = degreesMinutes(p[0] - 0.0001) + " N " + degreesMinutes(p[1] + 0.0001) + " E";
        return String.join("\r\n",
                "",
                "Glider " + name + " at surface.",
                "Because:Surface interval [1]",
                String.format(Locale.ROOT, "MissionName:%s MissionNum:%s-%d (%04d.0000)", mission, name, call, call),
                "Vehicle Name: " + name,
                "Curr Time: " + CTIME.format(now) + " MT: " + missionTime,
                "DR  Location:  " + dr + " measured     30.0 secs ago",
                "GPS Location:  " + gps + " measured     26.0 secs ago",
                String.format(Locale.ROOT, "   sensor:m_battery(volts)=%.2f", Math.max(10.0, 15.2 - 0.05 * call)),
                "   sensor:m_vacuum(inHg)=7.21",
                "   sensor:m_depth(m)=0.32",
                "",
                "").replace("   sensor:m_depth(m)=0.32\r\n", "   sensor:m_depth(m)=0.32\r\n" + reportLines);
    }

    /**
     * The whole dialog of a Slocum's surfacing as GliderDOS prints it (firmware 8-10 shape: fix
     * lines with their ages, the surface list with ages, device counts, the ABORT HISTORY block),
     * with {@code reportLines} (the plan's waypoint, the report list) after its sensors and the
     * trouble asked for.
     */
    String fullText(int call, Instant now, String mission, String reportLines, SurfaceTrouble trouble) {
        double[] p = position(call);
        long missionTime = (System.nanoTime() - start) / 1_000_000_000L;
        boolean aborted = trouble.aborted(call, now, name, mission);
        String gps = degreesMinutes(p[0]) + " N " + degreesMinutes(p[1]) + " E";
        String invalid = degreesMinutes(p[0] + 0.0012) + " N " + degreesMinutes(p[1] - 0.0009) + " E";
        String dr = degreesMinutes(p[0] - 0.0001) + " N " + degreesMinutes(p[1] + 0.0001) + " E";
        StringBuilder b = new StringBuilder("\r\n");
        b.append("Glider ").append(name).append(" at surface.\r\n");
        b.append(aborted ? "Because:Abort [" + SurfaceTrouble.ABORT_CAUSE + "]" : "Because:Surface interval [1]").append("\r\n");
        b.append(String.format(Locale.ROOT, "MissionName:%s MissionNum:%s-%d (%04d.0000)\r\n", mission, name, call, call));
        b.append("Vehicle Name: ").append(name).append("\r\n");
        b.append("Curr Time: ").append(CTIME.format(now)).append(" MT: ").append(missionTime).append("\r\n");
        b.append("DR  Location:  ").append(dr).append(" measured     30.0 secs ago\r\n");
        b.append("GPS Invalid :  ").append(invalid).append(" measured     44.5 secs ago\r\n");
        b.append("GPS Location:  ").append(gps).append(" measured     26.0 secs ago\r\n");
        b.append(sensor("m_battery(volts)", String.format(Locale.ROOT, "%.2f", Math.max(10.0, 15.2 - 0.05 * call)), "2.1"));
        b.append(sensor("m_coulomb_amphr_total(amp-hrs)", String.format(Locale.ROOT, "%.2f", 1.5 * call), "3.0"));
        b.append(sensor("m_vacuum(inHg)", "7.21", "2.1"));
        b.append(sensor("m_leakdetect_voltage(volts)", "2.47", "2.4"));
        b.append(sensor("m_leakdetect_voltage_aft(volts)", trouble.leaks(call) ? "1.21" : "2.49", "2.4"));
        b.append(sensor("m_water_vx(m/s)", "0.112", "812.0"));
        b.append(sensor("m_water_vy(m/s)", "-0.048", "812.0"));
        b.append("   sensor:m_depth(m)=0.32\r\n");
        b.append(reportLines);
        b.append("devices:(t/m/s) errs:     0/  0/  0 warn:     0/  0/  0 oddity:     0/  0/  0\r\n");
        b.append(trouble.history());
        return b.append("\r\n").toString();
    }

    private static String sensor(String nameAndUnits, String value, String age) {
        return String.format(Locale.ROOT, "   sensor:%-40s %10s secs ago\r\n", nameAndUnits + "=" + value, age);
    }

    /**
     * What a Slocum prints after its dialog: the keys it listens for. (Worded after the real
     * glider's; not its exact text.)
     */
    static String keys(long extendSeconds) {
        return "Hit Control-R to RESUME the mission, or Control-C to abort it and go to GliderDOS.\r\n"
                + "Hit Control-E to extend the surface time by " + extendSeconds + " s, Control-F to re-read the mafiles.\r\n";
    }

    /** The countdown line, printed at first and every 10 s until a key comes or the time is up. */
    static String countdown(long secondsLeft) {
        return "Hit Control-C within " + Math.max(0, secondsLeft) + " seconds to abort the mission...\r\n";
    }

    /** A line the glider prints on its own now and then while it waits at the surface. */
    String chatter(long secondsLeft) {
        return "Glider " + name + " at surface: waiting for commands; diving in " + Math.max(0, secondsLeft) + " s";
    }
}
