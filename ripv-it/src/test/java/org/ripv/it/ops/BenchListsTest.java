package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.ripv.bench.BenchMain;

/**
 * One list of benchmarks: {@code ripv bench --help} (BenchMain) is the source; the launcher's usage,
 * the README's table and docs/performance.md's list name exactly the same ones.
 */
class BenchListsTest {
    static final Path ROOT = RipvScriptHelpTest.ROOT;

    static Set<String> all(Pattern p, String text) {
        Set<String> names = new TreeSet<>();
        Matcher m = p.matcher(text);
        while (m.find()) {
            names.add(m.group(1));
        }
        return names;
    }

    static Set<String> source() {
        return all(Pattern.compile("(?m)^  ([a-z]+)\\s"), BenchMain.usage());
    }

    @Test
    void theSourceListsEveryBenchmark() throws Exception {
        assertThat(source()).contains("broker", "connections", "workflow", "hosts").hasSizeGreaterThanOrEqualTo(12);
        String main = Files.readString(ROOT.resolve("ripv-it/src/main/java/org/ripv/bench/BenchMain.java"), StandardCharsets.UTF_8);
        assertThat(all(Pattern.compile("case \"([a-z]+)\" ->"), main)).as("every benchmark BenchMain runs is in its usage")
                .isEqualTo(source());
    }

    @Test
    void theLaunchersUsageNamesTheSameBenchmarks() throws Exception {
        String script = Files.readString(ROOT.resolve("ripv"), StandardCharsets.UTF_8);
        int from = script.indexOf("  bench     NAME");
        int to = script.indexOf("(docs/performance.md)", from);
        assertThat(from).as("the launcher's bench line").isPositive();
        Set<String> names = all(Pattern.compile("\\b([a-z]+)\\b"), script.substring(from + "  bench     NAME".length(), to));
        names.remove("or");
        assertThat(names).isEqualTo(source());
    }

    @Test
    void theReadmesTableNamesTheSameBenchmarks() throws Exception {
        String readme = Files.readString(ROOT.resolve("README.md"), StandardCharsets.UTF_8);
        assertThat(all(Pattern.compile("(?m)^\\| `\\./ripv bench ([a-z]+)`"), readme)).isEqualTo(source());
        assertThat(readme).as("no second, inline list").doesNotContainPattern("ripv bench [a-z]+\\|");
    }

    @Test
    void performanceMdNamesTheSameBenchmarks() throws Exception {
        String perf = Files.readString(ROOT.resolve("docs/performance.md"), StandardCharsets.UTF_8);
        assertThat(all(Pattern.compile("(?m)^    \\./ripv bench ([a-z]+)"), perf)).isEqualTo(source());
    }
}
