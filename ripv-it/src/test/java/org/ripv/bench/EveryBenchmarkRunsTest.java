package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.ripv.it.NetnsAssume;
import org.ripv.testing.Tools;
import org.ripv.it.Shared;
import org.junit.jupiter.api.parallel.ResourceLock;

/**
 * No benchmark may rot (issue 26): every benchmark the launcher lists runs once as
 * {@code ./ripv bench NAME --short} runs it ({@link BenchMain#run}, on this build's classes, since
 * this module's jar is packaged only after its tests), and must exit 0 with its report, saying its
 * figures are not measurements; the ones with a floor must report the CPU per operation of the path
 * against the floor's. The counts are shrunk ({@link ShortMode}), so the figures mean nothing here;
 * that the benchmark still runs does.
 *
 * <p>They run in {@value #LANES} JVMs of their own side by side ({@link ShortRuns}; issue 38: a JVM
 * each made this the slowest class of the suite, and one after the other in one JVM it still was),
 * each JVM running its share one after the other, started once before the checks. The runs share
 * nothing (each its own folder, ports from 0, network namespaces of its own) and most of a short run
 * is a fixed start-up or a phase paced by the clock, not a core; their figures are not measurements
 * anyway, so a neighbour's load costs the check nothing.
 */
@ResourceLock(Shared.CPU)
class EveryBenchmarkRunsTest {
    private static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
    /** Under a loaded machine a shrunk benchmark still takes tens of seconds; hung ones are stopped here. */
    private static final long LIMIT_SECONDS = 1500;
    private static final Path LOGS = ROOT.resolve("ripv-it/target/bench-short");
    /** How many ShortRuns JVMs share the runs ({@code -Dripv.bench.lanes=1} runs them one after the other in one). */
    static final int LANES = Integer.getInteger("ripv.bench.lanes", 2);
    /**
     * Each short run's seconds, one after the other in one JVM at load average 6-18 (28 November,
     * docs/performance.md), only to share them fairly between the lanes (longest first into the
     * least loaded lane); a run not named counts 5 s.
     */
    private static final Map<String, Double> EXPECTED_SECONDS = Map.ofEntries(
            Map.entry("slocum", 50.0), Map.entry("web", 34.0), Map.entry("hosts", 32.0), Map.entry("ingest", 32.0),
            Map.entry("firststart", 25.0), Map.entry("console", 18.0), Map.entry("database", 17.0), Map.entry("webload", 16.0),
            Map.entry("broker", 16.0), Map.entry("connections", 15.0), Map.entry("ymodem", 9.0), Map.entry("calls", 8.0),
            Map.entry("workflow", 6.0), Map.entry("zmodem", 5.0), Map.entry("store", 5.0), Map.entry("datavis", 3.0),
            Map.entry("dac", 1.0), Map.entry("surfacing", 1.0), Map.entry("plans", 1.0));
    /** What ShortRuns printed: each run's exit and time. */
    private static String summary = "";

    /** The NAMEs of "ripv help"'s bench line: "broker, database, ... or hosts". */
    static List<String> launcherNames() throws Exception {
        Process p = new ProcessBuilder("bash", ROOT.resolve("ripv").toString(), "help").redirectErrorStream(true).start();
        String help = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        p.waitFor(60, TimeUnit.SECONDS);
        Matcher m = Pattern.compile("(?m)^  bench +NAME +(.*(?:\\n {20,}.*)*)").matcher(help);
        assertThat(m.find()).as("the launcher's usage has a bench line: " + help).isTrue();
        String list = m.group(1).replaceAll("\\(.*?\\)", " ").replaceAll("\\s+", " ").trim();
        return Arrays.stream(list.split(",\\s*|\\s+or\\s+")).map(String::trim).filter(s -> !s.isEmpty()).toList();
    }

    static Stream<String> names() throws Exception {
        return launcherNames().stream();
    }

    @Test
    void everyBenchmarkTheLauncherListsHasAShortMode() throws Exception {
        assertThat(launcherNames()).containsExactlyInAnyOrderElementsOf(ShortMode.names());
    }

    /** Every benchmark this machine can run, in one JVM, before the checks below read their logs. */
    @BeforeAll
    static void runThemAllOnce() throws Exception {
        List<String> runnable = new ArrayList<>();
        for (String name : launcherNames()) {
            try {
                needs(name);
                runnable.add(name);
            } catch (org.opentest4j.TestAbortedException skipped) {
                // its own check says why
            }
        }
        Files.createDirectories(LOGS);
        for (String name : runnable) {
            Files.deleteIfExists(LOGS.resolve(name + ".exit"));
        }
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<Process> running = new ArrayList<>();
        List<List<String>> lanes = lanes(runnable, LANES);
        for (int i = 0; i < lanes.size(); i++) {
            // C1 only and the serial collector, as the tests' launched jars (TestJvms): a short run is mostly start-up,
            // where C2's compiling costs CPU the classes beside it need, and its figures are no measurements anyway.
            List<String> cmd = new ArrayList<>(List.of(java, "-Xmx1g", "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-Xshare:auto",
                    "-cp", System.getProperty("java.class.path"), ShortRuns.class.getName(), LOGS.toString()));
            cmd.addAll(lanes.get(i));
            running.add(new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(LOGS.resolve("short-runs-" + i + ".log").toFile())
                    .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null"))).start());
        }
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(LIMIT_SECONDS);
        StringBuilder all = new StringBuilder();
        for (int i = 0; i < running.size(); i++) {
            Process p = running.get(i);
            if (!p.waitFor(Math.max(0, end - System.nanoTime()), TimeUnit.NANOSECONDS)) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly().waitFor(30, TimeUnit.SECONDS);
            }
            all.append("lane ").append(i).append(' ').append(lanes.get(i)).append(":\n")
                    .append(Files.readString(LOGS.resolve("short-runs-" + i + ".log"), StandardCharsets.UTF_8));
        }
        summary = all.toString();
    }

    /** The runs shared between {@code count} lanes: longest expected first, each into the lane with least so far. */
    static List<List<String>> lanes(List<String> runs, int count) {
        List<List<String>> lanes = new ArrayList<>();
        double[] load = new double[Math.max(1, Math.min(count, runs.size()))];
        for (int i = 0; i < load.length; i++) {
            lanes.add(new ArrayList<>());
        }
        List<String> longestFirst = new ArrayList<>(runs);
        longestFirst.sort(java.util.Comparator.comparingDouble((String r) -> EXPECTED_SECONDS.getOrDefault(r, 5.0)).reversed());
        for (String r : longestFirst) {
            int least = 0;
            for (int i = 1; i < load.length; i++) {
                if (load[i] < load[least]) {
                    least = i;
                }
            }
            lanes.get(least).add(r);
            load[least] += EXPECTED_SECONDS.getOrDefault(r, 5.0);
        }
        return lanes;
    }

    @ParameterizedTest(name = "ripv bench {0} --short")
    @MethodSource("names")
    void runsToTheEndInShortMode(String name) throws Exception {
        needs(name);
        Path log = LOGS.resolve(name + ".log");
        Path exit = LOGS.resolve(name + ".exit");
        String out = Files.exists(log) ? Files.readString(log, StandardCharsets.UTF_8) : "";
        assertThat(Files.exists(exit)).as("ripv bench " + name + " --short ended within the " + LIMIT_SECONDS
                + " s all runs may take; the runs:\n" + summary + "\nits output:\n" + out).isTrue();
        assertThat(Files.readString(exit).trim()).as("ripv bench " + name + " --short exit status; its output:\n" + out).isEqualTo("0");
        assertThat(out).as("no exception in the output").doesNotContain("Exception in thread").doesNotContain("\tat org.ripv.");
        assertThat(out).as("the machine's load is reported").contains(CpuClock.LOAD_PREFIX);
        assertThat(out.indexOf(ShortMode.NOT_MEASUREMENTS)).as("a --short run says, before and after its figures, that they"
                + " are not measurements:\n" + out).isGreaterThanOrEqualTo(0).isLessThan(out.lastIndexOf(ShortMode.NOT_MEASUREMENTS));
        if (List.of("broker", "database", "console", "workflow", "web", "slocum", "ingest", "surfacing", "plans", "webload").contains(name)
                && !(name.equals("webload") && HeadlessChromium.missing() != null)) {
            assertThat(out).as("CPU per operation against the floor's").containsPattern(
                    "cpu per op: .* [0-9.]+ us, floor [0-9.]+ us \\(CPU [0-9.]+×; wall [0-9.]+×\\)");
        }
        if (name.equals("broker")) {
            assertThat(out).as("the TLS floor, with its cipher suite").containsPattern("floor: TLS socket round trip \\(TLS");
        }
        if (name.equals("database")) {
            assertThat(out).as("the time to the first row").containsPattern("first row, median ms: direct JDBC [0-9.]+");
        }
        if (name.equals("web")) {
            assertThat(out).as("the server's CPU per delivery against the WebSocket floor's")
                    .containsPattern("cpu per op: server per delivery to each of [0-9]+ web watchers");
        }
    }

    /** The benchmarks that need what a developer's machine may lack: skipped, or failed under RIPV_REQUIRE_TOOLS. */
    private static void needs(String name) {
        switch (name) {
            case "hosts" -> {
                NetnsAssume.usable();
                NetnsAssume.postgres();
                Tools.require("ss");
            }
            // These run without the tool (their lrzsz, Octave or PostgreSQL rows say "skipped"); CI wants those rows.
            case "zmodem" -> requiredInCi(Tools.onPath("sz") && Tools.onPath("rz"), "lrzsz");
            case "ymodem" -> requiredInCi(Tools.onPath("sb") && Tools.onPath("rb") && Tools.onPath("socat"), "lrzsz and socat");
            case "datavis" -> requiredInCi(Tools.onPath("octave-cli"), "octave-cli");
            case "webload" -> requiredInCi(HeadlessChromium.missing() == null, "Chromium");
            case "store" -> requiredInCi(System.getenv("RIPV_PG_URL") != null, "PostgreSQL (RIPV_PG_URL)");
            default -> { }
        }
    }

    private static void requiredInCi(boolean present, String what) {
        if (!present && System.getenv("RIPV_REQUIRE_TOOLS") != null) {
            throw new AssertionError("RIPV_REQUIRE_TOOLS is set but " + what + " is missing, so ripv bench would skip its rows");
        }
    }
}
