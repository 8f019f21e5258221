package org.ripv.bench;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

/**
 * {@code ripv bench NAME --short}: the same benchmark with its counts and times shrunk so that
 * every benchmark runs in seconds. Its figures mean little; it exists so that CI runs each
 * benchmark once and a benchmark that throws is caught the day it breaks, not the day someone
 * wants its figures (issue 26: {@code bench database} had rotted unnoticed).
 *
 * <p>The shrunk options are added only where the user gave none of the same name, so
 * {@code --short --clients 2,4} still measures 2 and 4 clients.
 */
final class ShortMode {
    static final String FLAG = "--short";

    /**
     * Per benchmark: options, each followed by its value unless it is a flag; a list that starts
     * with a value is the positional arguments, used when the user gave none.
     */
    private static final Map<String, List<String>> SHRUNK = Map.ofEntries(
            Map.entry("broker", List.of("--seconds", "0.5", "--warmup", "0.5", "--clients", "1,4")),
            // the 12-s wait makes a measurement of idle clients; a short run only proves the path (issue 38)
            Map.entry("connections", List.of("--clients", "20", "--idle-seconds", "1")),
            Map.entry("database", List.of("--rows", "20000", "--runs", "3", "--warmup", "1")), // the floor must span several 10-ms CPU ticks
            Map.entry("ymodem", List.of("115200:8192")),
            Map.entry("zmodem", List.of("--bytes", "8192", "--skip-iridium")),
            // the phases at their shortest (1 s each): a short run proves the paths, its p99s mean nothing anyway
            Map.entry("console", List.of("--watchers", "20", "--rate", "20", "--seconds", "1", "--baseline-seconds", "1",
                    "--warmup", "1", "--full-clients", "2")),
            Map.entry("web", List.of("--watchers", "50", "--rate", "20", "--seconds", "1", "--baseline-seconds", "1",
                    "--warmup", "1", "--vehicles", "10", "--fleet-runs", "1", "--heap", "256m")),
            // a 300-sensor wide file: the 2,136-sensor one made this the longest short run (26 s of 198 on a quiet machine)
            Map.entry("ingest", List.of("--runs", "1", "--wide-runs", "1", "--track-runs", "1", "--rows", "500",
                    "--wide-sensors", "300")),
            Map.entry("datavis", List.of("--points", "2000", "--runs", "2")),
            Map.entry("firststart", List.of("--runs", "1")),
            Map.entry("calls", List.of("--vehicles", "4", "--spread", "2", "--surface", "3")),
            Map.entry("hosts", List.of("--requests", "30", "--takeovers", "1")),
            Map.entry("store", List.of("--entries", "2000")),
            Map.entry("slocum", List.of("--mb", "1", "--runs", "1", "--ingest-rows", "300")),
            Map.entry("dac", List.of("--yos", "3", "--runs", "1", "--not-a-measurement")),
            Map.entry("surfacing", List.of("--dialogs", "300", "--runs", "1")),
            Map.entry("plans", List.of("--files", "100", "--runs", "1")),
            Map.entry("webload", List.of("--vehicles", "10", "--runs", "2")),
            Map.entry("workflow", List.of("--files", "2", "--get-bytes", "8192", "--put-bytes", "4096", "--report-only")));

    /** What every {@value #FLAG} run prints first and last, so its figures are never read as measurements. */
    static final String NOT_MEASUREMENTS = "--short: counts and times shrunk to check that this benchmark runs;"
            + " its figures are NOT measurements (docs/performance.md has measured ones)";

    private ShortMode() {}

    /**
     * When {@code args} hold {@value #FLAG}: prints {@link #NOT_MEASUREMENTS} to {@code out}
     * ({@link BenchMain#run} prints it again under the figures).
     *
     * @return whether the run is short
     */
    static boolean announce(String[] args, PrintStream out) {
        if (!Arrays.asList(args).contains(FLAG)) {
            return false;
        }
        out.println(NOT_MEASUREMENTS);
        return true;
    }

    /** The benchmarks {@code ripv bench} knows, each with a short mode. */
    static List<String> names() {
        return SHRUNK.keySet().stream().sorted().toList();
    }

    /** The arguments without {@value #FLAG}, and with the shrunk options the user did not give when it was there. */
    static String[] apply(String name, String[] args) {
        List<String> given = new ArrayList<>(Arrays.asList(args));
        if (!given.remove(FLAG)) {
            return args;
        }
        List<String> shrunk = SHRUNK.get(name);
        if (shrunk == null) {
            return given.toArray(String[]::new);
        }
        List<String> out = new ArrayList<>(given);
        if (!shrunk.get(0).startsWith("--")) {
            return given.isEmpty() ? shrunk.toArray(String[]::new) : given.toArray(String[]::new);
        }
        for (int i = 0; i < shrunk.size(); i++) {
            String option = shrunk.get(i);
            boolean hasValue = i + 1 < shrunk.size() && !shrunk.get(i + 1).startsWith("--");
            if (!given.contains(option)) {
                out.add(option);
                if (hasValue) {
                    out.add(shrunk.get(i + 1));
                }
            }
            if (hasValue) {
                i++;
            }
        }
        return out.toArray(String[]::new);
    }
}
