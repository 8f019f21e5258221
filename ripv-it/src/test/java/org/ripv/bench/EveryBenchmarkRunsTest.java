package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.ripv.it.NetnsAssume;
import org.ripv.testing.Tools;

/**
 * No benchmark may rot (issue 26): every benchmark the launcher lists runs once, in a process of
 * its own as {@code ./ripv bench NAME --short} runs it ({@code java -jar ripv-it.jar}, whose main
 * is {@link BenchMain}; here on this build's classes, since this module's jar is packaged only after
 * its tests), and must exit 0 with its report; the ones with a floor must report the CPU per operation of the
 * path against the floor's. The counts are shrunk ({@link ShortMode}), so the figures mean
 * nothing here; that the benchmark still runs does.
 */
class EveryBenchmarkRunsTest {
    private static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();
    /** Under a loaded machine a shrunk benchmark still takes tens of seconds; a hung one is stopped here. */
    private static final long LIMIT_SECONDS = 400;

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

    @ParameterizedTest(name = "ripv bench {0} --short")
    @MethodSource("names")
    void runsToTheEndInShortMode(String name) throws Exception {
        needs(name);
        Path log = Files.createDirectories(ROOT.resolve("ripv-it/target/bench-short")).resolve(name + ".log");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        ProcessBuilder pb = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"), BenchMain.class.getName(),
                name, "--short")
                .redirectErrorStream(true).redirectOutput(log.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        Process p = pb.start();
        boolean ended = p.waitFor(LIMIT_SECONDS, TimeUnit.SECONDS);
        if (!ended) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly().waitFor(30, TimeUnit.SECONDS);
        }
        String out = Files.readString(log, StandardCharsets.UTF_8);
        assertThat(ended).as("ripv bench " + name + " --short still running after " + LIMIT_SECONDS + " s:\n" + out).isTrue();
        assertThat(p.exitValue()).as("ripv bench " + name + " --short exit status; its output:\n" + out).isZero();
        assertThat(out).as("no exception in the output").doesNotContain("Exception in thread").doesNotContain("\tat org.ripv.");
        assertThat(out).as("the machine's load is reported").contains(CpuClock.LOAD_PREFIX);
        assertThat(out.split(Pattern.quote(BenchMain.NOT_MEASUREMENTS), -1))
                .as("a --short run says before and after its figures that they are not measurements").hasSize(3);
        if (List.of("broker", "database", "console", "workflow", "web", "slocum", "ingest").contains(name)) {
            assertThat(out).as("CPU per operation against the floor's").containsPattern(
                    "cpu per op: .* [0-9.]+ us, floor [0-9.]+ us \\(CPU [0-9.]+×; wall [0-9.]+×\\)");
        }
        if (name.equals("broker")) {
            assertThat(out).as("the TLS floor, with its cipher suite").containsPattern("floor: TLS socket round trip \\(TLS");
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
