package org.ripv.services.ingest;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A Slocum sensor list, as a binary file or a cache file ({@code CRC.cac}) writes it: one line a
 * sensor, {@code s: T|F INDEX CYCLE_INDEX BYTES NAME UNITS}. Sensors marked {@code T} with a cycle
 * index of 0 or more are in every cycle of the files that use the list, in cycle-index order.
 */
public final class SensorList {
    /** More than any glider has (about 2,500 on a recent one); a header claiming more is refused. */
    public static final int MAX_SENSORS = 65_536;
    private static final Pattern LINE = Pattern.compile("s:\\s+([TF])\\s+(\\d{1,6})\\s+(-1|\\d{1,6})\\s+([1248])\\s+([A-Za-z0-9_]{1,64})\\s+(\\S{1,64})\\s*");

    private SensorList() {}

    /** True for a line that looks like a sensor-list line (for telling a cache file from anything else). */
    static boolean isSensorLine(String line) {
        return LINE.matcher(line).matches();
    }

    /**
     * The sensors of the cycle, in cycle order, from {@code total} list lines.
     *
     * @throws IllegalArgumentException naming the line and what is wrong, or the counts that do not match
     */
    public static List<SlocumSensor> cycle(List<String> lines, int total, int perCycle) {
        if (lines.size() != total) {
            throw new IllegalArgumentException("the sensor list has " + lines.size() + " sensors, the header says "
                    + "total_num_sensors " + total);
        }
        SlocumSensor[] cycle = new SlocumSensor[perCycle];
        int found = 0;
        for (int i = 0; i < lines.size(); i++) {
            Matcher m = LINE.matcher(lines.get(i));
            if (!m.matches()) {
                throw new IllegalArgumentException("sensor line " + (i + 1) + " is not 's: T|F INDEX CYCLE_INDEX BYTES NAME UNITS': '"
                        + cut(lines.get(i)) + "'");
            }
            int at = Integer.parseInt(m.group(3));
            if (!m.group(1).equals("T") || at < 0) {
                continue;
            }
            if (at >= perCycle || cycle[at] != null) {
                throw new IllegalArgumentException("sensor line " + (i + 1) + " (" + m.group(5) + ") has cycle index " + at
                        + ", which is " + (at >= perCycle ? "not below sensors_per_cycle " + perCycle : "taken twice"));
            }
            cycle[at] = new SlocumSensor(m.group(5), m.group(6), Integer.parseInt(m.group(4)));
            found++;
        }
        if (found != perCycle) {
            throw new IllegalArgumentException("the sensor list has " + found + " sensors in the cycle, the header says "
                    + "sensors_per_cycle " + perCycle);
        }
        return List.of(cycle);
    }

    static String cut(String s) {
        return s.length() <= 80 ? s : s.substring(0, 80) + "...";
    }

    /** The lines of a sensor list, one a sensor. */
    static List<String> lines(String text) {
        List<String> out = new ArrayList<>();
        for (String l : text.split("\r?\n")) {
            if (!l.isBlank()) {
                out.add(l);
            }
        }
        return out;
    }
}
