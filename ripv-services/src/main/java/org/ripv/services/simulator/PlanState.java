package org.ripv.services.simulator;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Pattern;

import org.ripv.plans.BArg;
import org.ripv.plans.BehaviorFile;
import org.ripv.plans.BehaviorFileReader;
import org.ripv.plans.PlanCheck;
import org.ripv.plans.PlanLimits;
import org.ripv.plans.Waypoint;

/**
 * What the simulated glider's plan makes its dialog print, so that a plan sent to it shows as a
 * real glider's would (docs/plans.md): its mission's goto_list reads {@code goto_l10.ma}
 * ({@code args_from_file 10}), so the first waypoint it heads for — {@code initial_wpt} when that
 * is one, else the first — is {@code c_wpt_lat}/{@code c_wpt_lon}; a file of another name is on
 * its disk but never read. Values set with {@code put} at its PicoDOS-like prompt are printed as
 * sensors under the next dialog. (GliderDOS keeps its own sensors: {@link GliderDos}.)
 */
final class PlanState {
    /** The file the simulated mission's goto_list reads. */
    static final String GOTO_FILE = "goto_l10.ma";
    /** Where it heads with no readable goto file: 41° 45' N, 70° 25' W. */
    private static final String[] NO_PLAN = {"4145.000", "-7025.000"};
    private static final Pattern SENSOR = Pattern.compile("[a-z][a-z0-9_]{0,39}");
    private static final Pattern NUMBER = Pattern.compile("[+-]?(\\d{1,15}(\\.\\d{0,15})?|\\.\\d{1,15})");

    private final Path dir;
    private final Map<String, String> puts = new TreeMap<>();

    PlanState(Path dir) {
        this.dir = dir;
    }

    /** The waypoint lines of a dialog. */
    String waypointLines() {
        String[] wpt = waypoint();
        return "   sensor:c_wpt_lat(lat)=" + wpt[0] + "\r\n   sensor:c_wpt_lon(lon)=" + wpt[1] + "\r\n";
    }

    /** The waypoint lines and the values set with {@code put}, as the dialog prints them. */
    synchronized String dialogLines() {
        StringBuilder b = new StringBuilder(waypointLines());
        puts.forEach((k, v) -> b.append("   sensor:").append(k).append('=').append(v).append("\r\n"));
        return b.toString();
    }

    /** {@code put NAME VALUE} at the PicoDOS-like prompt: what it prints. */
    synchronized String put(String[] words) {
        if (words.length != 3) {
            return "usage: put NAME VALUE\r\n";
        }
        String name = words[1].toLowerCase(Locale.ROOT);
        if (!SENSOR.matcher(name).matches() || !NUMBER.matcher(words[2]).matches()) {
            return "put: not a sensor name and a number: " + words[1] + " " + words[2] + "\r\n";
        }
        if (puts.size() >= 100 && !puts.containsKey(name)) {
            return "put: too many sensors set\r\n";
        }
        puts.put(name, words[2]);
        return "   sensor:" + name + "=" + words[2] + "\r\n";
    }

    private String[] waypoint() {
        Path file = gotoFile();
        if (file == null) {
            return NO_PLAN;
        }
        PlanCheck c;
        try {
            c = BehaviorFileReader.check(GOTO_FILE, Files.readAllBytes(file), PlanLimits.DEFAULT.withMaxWaypoints(100));
        } catch (IOException e) {
            return NO_PLAN;
        }
        if (!c.ok() || !c.file().isGoto() || c.file().waypoints().isEmpty()) {
            return NO_PLAN; // a glider refuses such a file when the mission loads; the simulator keeps going
        }
        BehaviorFile f = c.file();
        int at = f.barg("initial_wpt").map(BArg::value).map(Double::intValue)
                .filter(i -> i >= 0 && i < f.waypoints().size()).orElse(0);
        Waypoint w = f.waypoints().get(at);
        return new String[] {w.latText(), w.lonText()};
    }

    /** goto_l10.ma, found without regard to case as on a FAT volume, or null. */
    private Path gotoFile() {
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir)) {
            for (Path p : ds) {
                if (p.getFileName().toString().equalsIgnoreCase(GOTO_FILE) && Files.isRegularFile(p)) {
                    return p;
                }
            }
        } catch (IOException e) {
            return null;
        }
        return null;
    }
}
