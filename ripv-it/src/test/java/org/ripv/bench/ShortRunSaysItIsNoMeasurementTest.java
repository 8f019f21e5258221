package org.ripv.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * Issue 32, item 12: {@code ripv bench broker --short} printed {@code 2587×} as if it were a
 * figure. A short run, launched as a process as {@code ./ripv bench broker --short} runs it, says
 * before its figures and after them that they are not measurements; its --help does not.
 * {@link EveryBenchmarkRunsTest} checks every benchmark's short run in one JVM.
 */
class ShortRunSaysItIsNoMeasurementTest {
    static String run(String... args) throws Exception {
        String javaBin = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(javaBin, "-cp", System.getProperty("java.class.path"), BenchMain.class.getName()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")))
                .start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(300, TimeUnit.SECONDS)).as(out).isTrue();
        assertThat(p.exitValue()).as(out).isZero();
        return out;
    }

    @Test
    void brokerShortSaysItsFiguresAreNotMeasurementsBeforeAndAfterThem() throws Exception {
        String out = run("broker", "--short");
        int first = out.indexOf(ShortMode.NOT_MEASUREMENTS);
        int last = out.lastIndexOf(ShortMode.NOT_MEASUREMENTS);
        assertThat(first).as(out).isGreaterThanOrEqualTo(0);
        assertThat(last).as("said again after the figures:\n" + out).isGreaterThan(first);
        String figures = out.substring(first, last);
        assertThat(figures).as("the ratio comes between the two notes").containsPattern("[0-9.]+×");
        assertThat(run("broker", "--help")).doesNotContain("not measurements");
    }
}
