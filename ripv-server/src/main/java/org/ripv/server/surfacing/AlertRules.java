package org.ripv.server.surfacing;

import com.google.re2j.Pattern;
import com.google.re2j.PatternSyntaxException;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import org.ripv.surfacing.CallInterval;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The thresholds alerts are raised against: fleet defaults, overridden per vehicle, from a
 * permit-style file ({@code DATA/surfacing-alerts.conf}), one rule a line:
 * <pre>
 * # VEHICLE  KEY              VALUE
 * *          battery.min      10.5
 * ru29       battery.min      13.8
 * ru29       overdue          2h
 * </pre>
 * {@code *} is the fleet; a vehicle is named by its MailBox handle ({@code ru29}) or full address.
 * The file is read again when it changes; a line that does not parse is logged and skipped, the
 * others stay in force. Patterns are RE2 (linear time on whatever a vehicle prints).
 */
final class AlertRules {
    private static final Logger log = LoggerFactory.getLogger(AlertRules.class);
    /** Lines of a rules file read at most (a hostile or broken file costs no more). */
    private static final int MAX_LINES = 10_000;

    /**
     * What one vehicle is held to.
     *
     * @param leakMin      a leak-detect voltage below this is a leak (a dry sensor reads about 2.5 V)
     * @param batteryMin   a battery below this many volts
     * @param batteryDrop  a battery falling faster than this many volts a day
     * @param vacuumMin    the vacuum band's low end (inHg)
     * @param vacuumMax    its high end
     * @param routine      a {@code because} that matches is routine; any other raises an alert
     * @param overdue      the expected interval between calls, or null to learn it
     * @param grace        how late a call may be before OVERDUE
     * @param every        the same cause of the same vehicle alerts at most once per this
     */
    record Thresholds(double leakMin, double batteryMin, double batteryDrop, double vacuumMin, double vacuumMax,
                      Pattern routine, Duration overdue, Duration grace, Duration every) {}

    static final Thresholds DEFAULTS = new Thresholds(2.0, 10.5, 1.0, 4.0, 11.0,
            Pattern.compile("(?i)^(surface interval|hit (a )?waypoint|mission (done|complete)|callback|every \\d+ ?(s|min|minutes|h|hours)\\b|sequence|user)"),
            null, Duration.ofMinutes(10), Duration.ofMinutes(30));

    private final Path file;
    private FileTime read;
    private long looked;
    private Map<String, Map<String, String>> rules = Map.of();

    AlertRules(Path file) {
        this.file = file;
    }

    /** The thresholds for the vehicle of {@code mailbox} (its handle is {@code name}). */
    synchronized Thresholds of(String mailbox, String name) {
        reloadIfChanged();
        Map<String, String> merged = new HashMap<>(rules.getOrDefault("*", Map.of()));
        merged.putAll(rules.getOrDefault(name.toLowerCase(Locale.ROOT), Map.of()));
        merged.putAll(rules.getOrDefault(mailbox.toLowerCase(Locale.ROOT), Map.of()));
        Thresholds d = DEFAULTS;
        return new Thresholds(number(merged, "leak.min", d.leakMin()), number(merged, "battery.min", d.batteryMin()),
                number(merged, "battery.drop", d.batteryDrop()), number(merged, "vacuum.min", d.vacuumMin()),
                number(merged, "vacuum.max", d.vacuumMax()),
                merged.containsKey("because.routine") ? Pattern.compile(merged.get("because.routine")) : d.routine(),
                merged.containsKey("overdue") && !merged.get("overdue").equalsIgnoreCase("learn")
                        ? duration(merged.get("overdue")) : d.overdue(),
                merged.containsKey("overdue.grace") ? duration(merged.get("overdue.grace")) : d.grace(),
                merged.containsKey("alert.every") ? duration(merged.get("alert.every")) : d.every());
    }

    private static double number(Map<String, String> m, String key, double fallback) {
        return m.containsKey(key) ? Double.parseDouble(m.get(key)) : fallback;
    }

    private void reloadIfChanged() {
        long nanos = System.nanoTime();
        if (looked != 0 && nanos - looked < 1_000_000_000L) {
            return; // a stat a second at most, however many vehicles ask
        }
        looked = nanos;
        try {
            FileTime now = Files.exists(file) ? Files.getLastModifiedTime(file) : null;
            if (Objects.equals(now, read)) {
                return;
            }
            read = now;
            rules = now == null ? Map.of() : parse(file.toString(), readLines());
        } catch (IOException e) {
            log.warn("cannot read the alert rules {}: {}; keeping the rules read before", file, e.toString());
        }
    }

    private List<String> readLines() throws IOException {
        List<String> lines = new ArrayList<>();
        try (var in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            String line;
            while ((line = in.readLine()) != null && lines.size() < MAX_LINES) {
                lines.add(line.length() > 2000 ? "" : line);
            }
        }
        return lines;
    }

    /** The rules of a file's lines: vehicle (lower case) → key → value. Bad lines are logged and skipped. */
    static Map<String, Map<String, String>> parse(String where, List<String> lines) {
        Map<String, Map<String, String>> out = new HashMap<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] w = line.split("\\s+", 3);
            String why = w.length < 3 ? "needs VEHICLE KEY VALUE" : check(w[1], w[2].strip());
            if (why != null) {
                log.warn("{} line {}: '{}' skipped: {}", where, i + 1, line.length() > 80 ? line.substring(0, 80) + "…" : line, why);
                continue;
            }
            out.computeIfAbsent(w[0].toLowerCase(Locale.ROOT), k -> new HashMap<>()).put(w[1].toLowerCase(Locale.ROOT), w[2].strip());
        }
        return out;
    }

    /** Why a rule's value is not of its key's kind, or null. */
    static String check(String key, String value) {
        try {
            switch (key.toLowerCase(Locale.ROOT)) {
                case "leak.min", "battery.min", "battery.drop", "vacuum.min", "vacuum.max" -> {
                    if (!Double.isFinite(Double.parseDouble(value))) {
                        return "not a number: " + value;
                    }
                }
                case "because.routine" -> Pattern.compile(value);
                case "overdue" -> {
                    if (!value.equalsIgnoreCase("learn")) {
                        duration(value);
                    }
                }
                case "overdue.grace", "alert.every" -> duration(value);
                default -> {
                    return "unknown key '" + key + "' (leak.min, battery.min, battery.drop, vacuum.min, vacuum.max,"
                            + " because.routine, overdue, overdue.grace, alert.every)";
                }
            }
            return null;
        } catch (NumberFormatException e) {
            return "not a number: " + value;
        } catch (PatternSyntaxException e) {
            return "not an RE2 pattern: " + e.getMessage();
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
    }

    /** {@code 90s}, {@code 10m}, {@code 2h}, {@code 1d}, or ISO-8601 ({@code PT2H}); positive. */
    static Duration duration(String s) {
        return CallInterval.parse(s);
    }
}
