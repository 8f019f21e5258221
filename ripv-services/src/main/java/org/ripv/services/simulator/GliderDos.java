package org.ripv.services.simulator;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Pattern;

/**
 * The part of a Slocum's GliderDOS a pilot needs to rehearse a surfacing: sensors set with
 * {@code put NAME VALUE} and read with {@code get NAME}, a report list ({@code report ++ NAME}),
 * the mission to run ({@code sequence NAME.MI}), {@code callback MINUTES}, and {@code exit} to
 * PicoDOS. It keeps its state across calls, as the glider does; what a command ends (the call, to
 * dive or to call back) is the simulator's business: {@link #execute} only says so.
 */
final class GliderDos {
    /** GliderDOS's prompt, as the simulator prints it. */
    static final String PROMPT = "GliderDOS I -3 >";
    private static final Pattern SENSOR = Pattern.compile("[a-z][a-z0-9_]{0,39}");
    private static final Pattern MISSION = Pattern.compile("(?i)([a-z0-9_]{1,8}\\.mi)(\\(\\d{1,3}\\))?");

    /** What a command asks of the call. */
    sealed interface End permits Resume, CallBack {}

    /** Dive: the mission goes on. */
    record Resume(String why) implements End {}

    /** Hang up and call again after this long, staying at the surface. */
    record CallBack(Duration after) implements End {}

    private final Map<String, String> sensors = new TreeMap<>();
    private final Set<String> report = new LinkedHashSet<>();
    private final Path dir;
    private final Duration minute;
    private String mission = "SIM.MI";
    private boolean inGliderDos = true;

    /**
     * @param dir    the glider's files (sequence looks for its missions there)
     * @param minute how long a {@code callback} minute lasts (a minute, or less in tests and demos)
     */
    GliderDos(Path dir, Duration minute) {
        this.dir = dir;
        this.minute = minute;
        sensors.put("c_climb_target_depth", "5");
        sensors.put("c_dive_target_depth", "200");
        sensors.put("m_battery", "15.20");
        sensors.put("m_depth", "0.32");
        sensors.put("m_vacuum", "7.21");
        sensors.put("u_hd_fin_ap_gain", "1.5");
    }

    /** The prompt of the shell the pilot is in: GliderDOS, or PicoDOS after {@code exit}. */
    String prompt() {
        return inGliderDos ? PROMPT : GliderSimulator.PROMPT;
    }

    /** The mission the glider runs, for the surface dialog. */
    synchronized String mission() {
        return mission;
    }

    /** Back in GliderDOS, as when the glider surfaces from a mission. */
    void surfaced() {
        inGliderDos = true;
    }

    /** The report list's lines, as the glider prints them under its surface dialog. */
    synchronized String reportLines() {
        StringBuilder b = new StringBuilder();
        for (String name : report) {
            b.append("   sensor:").append(name).append('=').append(sensors.getOrDefault(name, "0")).append("\r\n");
        }
        return b.toString();
    }

    /**
     * Runs a GliderDOS command ({@code words[0]} upper-cased in {@code verb}); null when the command
     * is not one of these (the simulator's file commands come next).
     */
    synchronized Answer execute(String verb, String[] words) throws IOException {
        if (!inGliderDos) {
            if (verb.equals("GLIDERDOS")) {
                inGliderDos = true;
                return new Answer("", null);
            }
            return null;
        }
        return switch (verb) {
            case "PUT" -> put(words);
            case "GET" -> words.length == 2 && sensors.containsKey(words[1])
                    ? new Answer(words[1] + "=" + sensors.get(words[1]) + "\r\n", null)
                    : new Answer("usage: get NAME (a known sensor; put sets one)\r\n", null);
            case "REPORT" -> report(words);
            case "SEQUENCE" -> sequence(words);
            case "CALLBACK" -> callback(words);
            case "EXIT" -> {
                inGliderDos = false;
                yield new Answer("Exiting GliderDOS to PicoDOS (gliderdos returns)\r\n", null);
            }
            case "HELP", "?" -> new Answer("put NAME VALUE, get NAME, report ++|-- NAME, report list|clearall,"
                    + " sequence [NAME.MI], callback MINUTES, exit; dir, type NAME, del NAME, ys NAME..., yr,"
                    + " zs NAME..., zr, monitor [SECONDS], go\r\n", null);
            default -> null;
        };
    }

    /** What a command printed, and whether it ends the call. */
    record Answer(String text, End end) {}

    private Answer put(String[] words) {
        if (words.length != 3) {
            return new Answer("usage: put NAME VALUE\r\n", null);
        }
        String name = words[1].toLowerCase(Locale.ROOT);
        if (!SENSOR.matcher(name).matches()) {
            return new Answer("put: '" + words[1] + "' is not a sensor name (letters, digits, '_')\r\n", null);
        }
        try {
            Double.parseDouble(words[2]);
        } catch (NumberFormatException e) {
            return new Answer("put: '" + words[2] + "' is not a number for " + name + "\r\n", null);
        }
        sensors.put(name, words[2]);
        return new Answer("   sensor:" + name + "=" + words[2] + "\r\n", null);
    }

    private Answer report(String[] words) {
        if (words.length == 2 && words[1].equalsIgnoreCase("list")) {
            return new Answer("report list: " + (report.isEmpty() ? "(empty)" : String.join(" ", report)) + "\r\n", null);
        }
        if (words.length == 2 && words[1].equalsIgnoreCase("clearall")) {
            report.clear();
            return new Answer("report list cleared\r\n", null);
        }
        if (words.length != 3 || !(words[1].equals("++") || words[1].equals("--"))) {
            return new Answer("usage: report ++ NAME | report -- NAME | report list | report clearall\r\n", null);
        }
        String name = words[2].toLowerCase(Locale.ROOT);
        if (!sensors.containsKey(name)) {
            return new Answer("report: no sensor '" + words[2] + "'\r\n", null);
        }
        if (words[1].equals("++")) {
            report.add(name);
            return new Answer("   sensor:" + name + "=" + sensors.get(name) + "\r\n", null);
        }
        report.remove(name);
        return new Answer("report list: " + (report.isEmpty() ? "(empty)" : String.join(" ", report)) + "\r\n", null);
    }

    private Answer sequence(String[] words) throws IOException {
        if (words.length == 1) {
            return new Answer("sequence: " + mission + "\r\n", null);
        }
        var m = MISSION.matcher(words[1]);
        if (words.length != 2 || !m.matches()) {
            return new Answer("usage: sequence [NAME.MI] (a mission file on the glider)\r\n", null);
        }
        String file = m.group(1);
        List<String> names = new ArrayList<>();
        try (var list = Files.list(dir)) {
            list.map(p -> p.getFileName().toString()).filter(n -> n.equalsIgnoreCase(file)).forEach(names::add);
        }
        if (names.isEmpty()) {
            return new Answer("sequence: no mission file " + file + " on the glider\r\n", null);
        }
        mission = file.toUpperCase(Locale.ROOT);
        return new Answer("Mission " + mission + " sequenced: running it\r\n", new Resume("mission " + mission));
    }

    private Answer callback(String[] words) {
        long minutes;
        try {
            minutes = words.length == 2 ? Long.parseLong(words[1]) : -1;
        } catch (NumberFormatException e) {
            minutes = -1;
        }
        if (minutes < 1 || minutes > 1440) {
            return new Answer("usage: callback MINUTES (1-1440)\r\n", null);
        }
        Duration after = minute.multipliedBy(minutes);
        return new Answer("Hanging up: calling back in " + minutes + " minute(s)\r\n", new CallBack(after));
    }
}
