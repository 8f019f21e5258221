package org.ripv.surfacing;

import java.time.DateTimeException;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.Month;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads a Slocum surface dialog as it streams and hands each one, parsed, to its {@link Listener}.
 *
 * <p>Feed it text in any pieces ({@link #feed}): CR, LF and CR LF end lines, a line split across
 * reads is joined, control bytes are dropped, and a line longer than {@link #MAX_LINE} characters
 * is cut there (the rest only counted), so a megabyte without a line end costs one line's memory.
 * A dialog starts at {@code Glider NAME at surface.} (or, for vehicles that print no such line, at
 * its first field: {@code Because:}, {@code Vehicle Name:}, {@code GPS Location:}, …) and ends at
 * the dive countdown, a shell prompt, the next dialog, {@link #end()} (the call ended), or after
 * {@link #MAX_DIALOG_LINES} lines. Outside dialogs, text is only watched for the countdown and the
 * prompt. All patterns are anchored and bounded, so each line costs time linear in its length.
 *
 * <p>Not thread-safe: one parser per link, fed by one thread at a time.
 *
 * <p>Longer than 400 lines for one job: the line joining, the dialog's start and end, and the fields
 * are one state machine over the same bounded buffer.
 */
public final class SurfaceDialogParser {
    /** Characters of a line kept; the rest is counted ({@link Surfacing#linesCut()}). */
    public static final int MAX_LINE = 4096;
    /** Distinct sensors kept per dialog. */
    public static final int MAX_SENSORS = 1000;
    /** Unknown lines kept per dialog, each cut at {@link #MAX_UNKNOWN_CHARS}. */
    public static final int MAX_UNKNOWN = 100;
    static final int MAX_UNKNOWN_CHARS = 240;
    /** A dialog that goes on longer than this is ended ({@link Surfacing.End#TOO_LONG}). */
    public static final int MAX_DIALOG_LINES = 20_000;

    /** Where parsed dialogs and the countdown go. Called on the feeding thread. */
    public interface Listener {
        /** A dialog ended; here is what it said. */
        void surfacing(Surfacing s);

        /** "Hit Control-C within N seconds to abort the mission": the vehicle dives in N seconds. */
        default void countdown(long seconds) {
        }

        /** A shell prompt, in a dialog or not. */
        default void prompt(Surfacing.Prompt p) {
        }
    }

    private static final String NUM = "[-+]?(?:\\d{1,20}(?:\\.\\d{0,20})?|\\.\\d{1,20})(?:[eE][-+]?\\d{1,4})?";
    private static final Pattern GLIDER = Pattern.compile("Glider (\\S{1,64}) at surface\\.?");
    private static final Pattern COUNTDOWN = Pattern.compile("Hit Control-C within (\\d{1,9}) sec", Pattern.CASE_INSENSITIVE);
    private static final Pattern GLIDERDOS = Pattern.compile("(GliderDOS) ([A-Za-z]) (-?\\d{1,9}) ?>.*", Pattern.CASE_INSENSITIVE);
    private static final Pattern PICODOS = Pattern.compile("[A-Z]:\\\\>.*");
    private static final Pattern BECAUSE = Pattern.compile("Because:\\s*(.*)");
    private static final Pattern MISSION = Pattern.compile("MissionName:\\s*(\\S{0,128})(?:\\s+MissionNum:\\s*(.*))?");
    private static final Pattern VEHICLE = Pattern.compile("Vehicle Name:\\s*(\\S{1,64}).*");
    private static final Pattern TIME = Pattern.compile("Curr Time:\\s*(.{0,64}?)\\s+MT:\\s*(-?\\d{1,15})(?!\\d).*");
    private static final Pattern PLACE = Pattern.compile("(GPS\\s*(Location|Invalid|TooFar)|DR\\s+Location)\\s*:\\s*(" + NUM
            + ")\\s*([NS])\\s+(" + NUM + ")\\s*([EW])(?:\\s+measured\\s+(" + NUM + ")\\s+secs?\\s+ago)?.*");
    private static final Pattern SENSOR = Pattern.compile("sensor:\\s*([A-Za-z_][A-Za-z0-9_]{0,63})(?:\\(([^)]{0,32})\\))?\\s*=\\s*(\\S{1,64})"
            + "(?:\\s+(" + NUM + ")\\s+secs?\\s+ago)?.*");
    private static final String C3 = "\\s*(\\d{1,15})\\s*/\\s*(\\d{1,15})\\s*/\\s*(\\d{1,15})";
    private static final Pattern DEVICES = Pattern.compile("devices:\\s*\\(t/m/s\\)\\s*errs:" + C3 + "\\s*warn:" + C3 + "\\s*oddity:" + C3 + ".*");
    private static final Pattern ABORT = Pattern.compile("ABORT HISTORY:\\s*(.*)");
    private static final Pattern ABORT_TOTAL = Pattern.compile("total since reset:\\s*(\\d{1,15})(?!\\d).*");
    private static final Pattern ABORT_LAST = Pattern.compile("last abort (cause|details|time|segment|mission):\\s*(.*)");
    private static final Pattern NUMBER = Pattern.compile(NUM);

    private final Listener listener;
    private final StringBuilder partial = new StringBuilder();
    private long partialCut;
    private boolean afterCr;
    private Dialog dialog;

    public SurfaceDialogParser(Listener listener) {
        this.listener = listener;
    }

    /** The seconds of a dive countdown line ("Hit Control-C within 50 seconds …"), or -1 when it is none. */
    public static long countdownSeconds(String line) {
        Matcher m = COUNTDOWN.matcher(line.strip());
        return line.length() <= MAX_LINE && m.lookingAt() ? Long.parseLong(m.group(1)) : -1;
    }

    /** True while a dialog has begun and not ended. */
    public boolean inDialog() {
        return dialog != null;
    }

    /** Text as it arrives, in any pieces. */
    public void feed(CharSequence text) {
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\n' && afterCr) {
                afterCr = false;
                continue;
            }
            afterCr = c == '\r';
            if (c == '\r' || c == '\n') {
                flushLine();
            } else if (c == '\t') {
                append(' ');
            } else if (c >= 0x20 && (c < 0x7F || c > 0x9F)) {
                append(c);
            } // other control bytes carry nothing a dialog says
        }
    }

    private void append(char c) {
        if (partial.length() < MAX_LINE) {
            partial.append(c);
        } else {
            partialCut++;
        }
    }

    private void flushLine() {
        String text = partial.toString();
        boolean cut = partialCut > 0;
        partial.setLength(0);
        partialCut = 0;
        line(text, cut);
    }

    /** One whole line (no line end), as a console entry carries it. */
    public void line(String text) {
        feed(text);
        if (partial.length() > 0 || partialCut > 0) {
            flushLine();
        }
        afterCr = false;
    }

    /** The call ended: a partial line counts, and a dialog under way ends with what it said. */
    public void end() {
        if (partial.length() > 0 || partialCut > 0) {
            flushLine();
        }
        finish(Surfacing.End.CALL_ENDED);
    }

    private void line(String raw, boolean cut) {
        String s = raw.strip();
        if (s.isEmpty()) {
            return;
        }
        if (dialog != null) {
            dialog.lines++;
            if (cut) {
                dialog.linesCut++;
            }
        }
        Matcher m;
        if ((m = COUNTDOWN.matcher(s)).lookingAt()) {
            long seconds = Long.parseLong(m.group(1));
            if (dialog != null) {
                dialog.countdown = seconds;
                finish(Surfacing.End.COUNTDOWN);
            }
            listener.countdown(seconds);
            return;
        }
        Surfacing.Prompt prompt = prompt(s);
        if (prompt != null) {
            if (dialog != null) {
                dialog.prompt = prompt;
                finish(Surfacing.End.PROMPT);
            }
            listener.prompt(prompt);
            return;
        }
        if ((m = GLIDER.matcher(s)).matches()) {
            finish(Surfacing.End.NEXT_DIALOG);
            dialog = new Dialog();
            dialog.vehicle = m.group(1);
            dialog.gliderLine = true;
            return;
        }
        if (dialog == null) {
            if (!startsDialog(s)) {
                return; // outside a dialog only the countdown and prompts matter
            }
            dialog = new Dialog();
        } else if (repeats(s)) {
            finish(Surfacing.End.NEXT_DIALOG);
            dialog = new Dialog();
        }
        dialog.field(s);
        if (dialog != null && dialog.lines >= MAX_DIALOG_LINES) {
            finish(Surfacing.End.TOO_LONG);
        }
    }

    private static Surfacing.Prompt prompt(String s) {
        Matcher m = GLIDERDOS.matcher(s);
        if (m.matches()) {
            return new Surfacing.Prompt("GliderDOS", m.group(2).toUpperCase(Locale.ROOT), Integer.valueOf(m.group(3)));
        }
        return PICODOS.matcher(s).matches() ? new Surfacing.Prompt("PicoDOS", null, null) : null;
    }

    private static boolean startsDialog(String s) {
        return s.startsWith("Because:") || s.startsWith("Vehicle Name:") || s.startsWith("MissionName:")
                || s.startsWith("Curr Time:") || s.startsWith("GPS Location") || s.startsWith("GPS Invalid")
                || s.startsWith("GPS TooFar") || s.startsWith("DR  Location") || s.startsWith("DR Location");
    }

    /** A field the dialog under way has already had: the next dialog began without a "Glider … at surface." line. */
    private boolean repeats(String s) {
        return (s.startsWith("Because:") && dialog.becauseText != null)
                || (s.startsWith("Curr Time:") && dialog.timeSeen)
                || (s.startsWith("Vehicle Name:") && dialog.vehicleNameSeen)
                || (s.startsWith("MissionName:") && dialog.mission != null);
    }

    private void finish(Surfacing.End end) {
        Dialog d = dialog;
        dialog = null;
        if (d != null) {
            listener.surfacing(d.build(end));
        }
    }

    /**
     * One {@code sensor:NAME(UNITS)=VALUE} line read on its own, as the dialog reads it, for a
     * line outside any dialog (a {@code put}'s echo {@code sensor:NAME=VALUE}); the name as printed.
     */
    public static Optional<Surfacing.Sensor> sensorLine(String line) {
        if (line == null || line.length() > MAX_LINE) {
            return Optional.empty();
        }
        Matcher m = SENSOR.matcher(line.strip());
        if (!m.matches()) {
            return Optional.empty();
        }
        return Optional.of(new Surfacing.Sensor(m.group(1), m.group(2) == null ? "" : m.group(2), m.group(3),
                number(m.group(3)), number(m.group(4))));
    }

    static Double number(String s) {
        if (s == null || !NUMBER.matcher(s).matches()) {
            return null;
        }
        try {
            return Double.valueOf(s);
        } catch (NumberFormatException e) {
            return null;
        }
    }

    /** {@code Sat Mar 28 20:40:38 2026} (ctime, in English whatever the locale), or null. */
    static Instant ctime(String s) {
        String[] w = s.trim().split("\\s+");
        if (w.length != 5) {
            return null;
        }
        Month month = null;
        for (Month candidate : Month.values()) {
            if (candidate.name().substring(0, 3).equalsIgnoreCase(w[1])) {
                month = candidate;
            }
        }
        String[] hms = w[3].split(":");
        if (month == null || hms.length != 3) {
            return null;
        }
        try {
            return LocalDateTime.of(Integer.parseInt(w[4]), month, Integer.parseInt(w[2]), Integer.parseInt(hms[0]),
                    Integer.parseInt(hms[1]), Integer.parseInt(hms[2])).toInstant(ZoneOffset.UTC);
        } catch (NumberFormatException | DateTimeException e) {
            return null;
        }
    }

    /** What one dialog has said so far. */
    private static final class Dialog {
        int lines;
        int linesCut;
        int dropped;
        boolean gliderLine;
        boolean vehicleNameSeen;
        boolean timeSeen;
        String vehicle;
        String because;
        String becauseText;
        String mission;
        String missionNum;
        Instant vehicleTime;
        Long missionTime;
        Surfacing.Position gps;
        Surfacing.Position dr;
        final List<String> gpsNotes = new ArrayList<>();
        final Map<String, Surfacing.Sensor> sensors = new LinkedHashMap<>();
        Surfacing.Devices devices;
        Long abortTotal;
        final Map<String, String> abortLast = new LinkedHashMap<>();
        Surfacing.Prompt prompt;
        Long countdown;
        final List<String> unknown = new ArrayList<>();

        void field(String s) {
            Matcher m;
            if ((m = SENSOR.matcher(s)).matches()) {
                String name = m.group(1);
                if (sensors.size() >= MAX_SENSORS && !sensors.containsKey(name)) {
                    dropped++;
                    return;
                }
                sensors.put(name, new Surfacing.Sensor(name, m.group(2) == null ? "" : m.group(2), m.group(3),
                        number(m.group(3)), number(m.group(4))));
            } else if ((m = PLACE.matcher(s)).matches()) {
                place(m, s);
            } else if ((m = BECAUSE.matcher(s)).matches()) {
                becauseText = m.group(1).strip();
                int bracket = becauseText.indexOf('[');
                because = (bracket <= 0 ? becauseText : becauseText.substring(0, bracket)).strip();
            } else if ((m = MISSION.matcher(s)).matches()) {
                mission = m.group(1);
                missionNum = m.group(2) == null ? null : m.group(2).strip();
            } else if ((m = VEHICLE.matcher(s)).matches()) {
                vehicleNameSeen = true;
                if (vehicle == null) {
                    vehicle = m.group(1);
                }
            } else if ((m = TIME.matcher(s)).matches()) {
                timeSeen = true;
                vehicleTime = ctime(m.group(1));
                missionTime = Long.valueOf(m.group(2));
                if (vehicleTime == null) {
                    unknown(s);
                }
            } else if ((m = DEVICES.matcher(s)).matches()) {
                devices = new Surfacing.Devices(counts(m, 1), counts(m, 4), counts(m, 7));
            } else if ((m = ABORT.matcher(s)).matches()) {
                abort(m.group(1).strip(), s);
            } else {
                unknown(s);
            }
        }

        private void place(Matcher m, String s) {
            Double ddLat = number(m.group(3));
            Double ddLon = number(m.group(5));
            double lat = ddLat == null ? Double.NaN : DegreesMinutes.degrees(ddLat, m.group(4).charAt(0));
            double lon = ddLon == null ? Double.NaN : DegreesMinutes.degrees(ddLon, m.group(6).charAt(0));
            Double age = number(m.group(7));
            boolean valid = DegreesMinutes.valid(lat, lon);
            String kind = m.group(2);
            if (kind == null) { // DR
                if (valid) {
                    dr = new Surfacing.Position(lat, lon, age);
                } else {
                    unknown(s);
                }
            } else if (kind.equals("Location") && valid) {
                gps = new Surfacing.Position(lat, lon, age);
            } else {
                gpsNotes.add(cut(s));
            }
        }

        private void abort(String rest, String s) {
            Matcher m;
            if ((m = ABORT_TOTAL.matcher(rest)).matches()) {
                abortTotal = Long.valueOf(m.group(1));
            } else if ((m = ABORT_LAST.matcher(rest)).matches()) {
                abortLast.put(m.group(1), cut(m.group(2).strip()));
            } else {
                unknown(s);
            }
        }

        private static Surfacing.Counts counts(Matcher m, int from) {
            return new Surfacing.Counts(Long.parseLong(m.group(from)), Long.parseLong(m.group(from + 1)),
                    Long.parseLong(m.group(from + 2)));
        }

        private void unknown(String s) {
            if (unknown.size() >= MAX_UNKNOWN) {
                dropped++;
            } else {
                unknown.add(cut(s));
            }
        }

        private static String cut(String s) {
            return s.length() <= MAX_UNKNOWN_CHARS ? s : s.substring(0, MAX_UNKNOWN_CHARS) + "…";
        }

        Surfacing build(Surfacing.End end) {
            String problem = null;
            if (gps == null) {
                problem = gpsNotes.isEmpty() ? "no GPS line in the dialog" : "no valid fix: " + String.join("; ", gpsNotes);
            }
            Surfacing.AbortHistory aborts = abortTotal == null && abortLast.isEmpty() ? null
                    : new Surfacing.AbortHistory(abortTotal, abortLast.get("cause"), abortLast.get("details"),
                    abortLast.get("time"), abortLast.get("segment"), abortLast.get("mission"));
            return new Surfacing(vehicle, because, becauseText, mission, missionNum, vehicleTime, missionTime, gps, problem,
                    dr, sensors, devices, aborts, prompt, countdown, unknown, dropped, linesCut, end);
        }
    }
}
