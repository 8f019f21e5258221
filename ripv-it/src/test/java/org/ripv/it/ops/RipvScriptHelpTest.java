package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;

/**
 * {@code ./ripv X --help} and {@code -h} for every command X of the launcher: exit 0, print a usage,
 * name the program as users type it, and start nothing (no listening port, no build, no process
 * left behind). Runs the real script with the jars the reactor built (or, before a build, the
 * script's own usage lines, since help never builds).
 */
class RipvScriptHelpTest {
    static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();

    static Stream<Arguments> commands() {
        List<Arguments> all = new ArrayList<>();
        for (String c : List.of("", "help", "demo", "build", "server", "passwd", "service", "service serial",
                "service database", "service datavis", "service clock", "simulator", "slocum", "slocum decode", "plan", "plan check", "plan forecast", "dac", "dac profiles", "dac check", "dac push", "client", "cli",
                "bench", "bench broker", "bench database", "bench ymodem", "bench datavis", "bench firststart", "bench calls", "bench hosts", "bench workflow", "bench slocum")) {
            for (String flag : List.of("--help", "-h")) {
                all.add(Arguments.of(c, flag));
            }
        }
        return all.stream();
    }

    record Run(int exit, String output, Set<String> listened, Set<String> builds, Set<String> left) {}

    static Run run(String... args) throws Exception {
        assumeTrue(ProcessWatch.supported(), "needs Linux /proc to see the processes a command starts");
        assertThat(ROOT.resolve("ripv")).exists();
        ProcessWatch watch = new ProcessWatch();
        List<String> cmd = new ArrayList<>(List.of("bash", ROOT.resolve("ripv").toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.environment().put(ProcessWatch.VARIABLE, watch.mark);
        Process p = pb.start();
        Set<String> listened = new LinkedHashSet<>();
        Set<String> builds = new LinkedHashSet<>();
        // Sample while it runs: a server or a build would show up here.
        while (!p.waitFor(30, TimeUnit.MILLISECONDS)) {
            listened.addAll(watch.listening());
            watch.processes().stream().filter(s -> s.contains("mvn") || s.contains("plexus-classworlds")).forEach(builds::add);
            if (listened.size() + builds.size() > 0) {
                break;
            }
        }
        boolean ended = p.waitFor(60, TimeUnit.SECONDS);
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!ended) {
            p.destroyForcibly();
        }
        Set<String> left = watch.processes();
        // Leave nothing behind even when the test fails.
        for (String s : left) {
            ProcessHandle.of(Long.parseLong(s.substring(0, s.indexOf(' ')))).ifPresent(ProcessHandle::destroyForcibly);
        }
        assertThat(ended).as("still running after 60 s: " + out).isTrue();
        return new Run(p.exitValue(), out, listened, builds, left);
    }

    @ParameterizedTest(name = "ripv {0} {1}")
    @MethodSource("commands")
    void everyCommandAnswersHelpAndDoesNothingElse(String command, String flag) throws Exception {
        List<String> args = new ArrayList<>(command.isEmpty() ? List.of() : List.of(command.split(" ")));
        args.add(flag);
        Run r = run(args.toArray(String[]::new));
        assertThat(r.exit()).as(r.output()).isZero();
        assertThat(r.output()).as("usage").contains("Usage: ripv" + (command.isEmpty() || command.equals("help") ? "" : " "
                + command.split(" ")[0]));
        assertThat(r.output()).as("the program named as users type it").doesNotContainPattern("Usage: ripv-|Usage: (serial|database|datavis|simulator|broker|clock-service)");
        assertThat(r.listened()).as("listening ports opened").isEmpty();
        assertThat(r.builds()).as("builds started").isEmpty();
        assertThat(r.left()).as("processes left").isEmpty();
    }

    @Test
    void versionPrintsTheVersionAndTheCommitTheJarsWereBuiltFrom() throws Exception {
        for (String[] args : List.of(new String[] {"--version"}, new String[] {"version"}, new String[] {"cli", "--version"},
                new String[] {"server", "--version"}, new String[] {"service", "serial", "--version"})) {
            Run r = run(args);
            assertThat(r.exit()).as(String.join(" ", args) + ": " + r.output()).isZero();
            assertThat(r.left()).isEmpty();
            Matcher m = Pattern.compile("RIPV \\S+ \\(commit ([0-9a-f]{7,40}|unknown)\\)").matcher(r.output());
            if (!Files.isRegularFile(ROOT.resolve("ripv-common/target/ripv-common.jar"))) {
                assertThat(r.output()).contains("RIPV");
                continue;
            }
            assertThat(m.find()).as(String.join(" ", args) + " printed " + r.output()).isTrue();
            String commit = m.group(1);
            if (!commit.equals("unknown")) {
                Process git = new ProcessBuilder("git", "-C", ROOT.toString(), "cat-file", "-e", commit + "^{commit}").start();
                assertThat(git.waitFor()).as("a real commit: " + commit).isZero();
            } else {
                assertThat(gitWorks()).as("git works here, so the build should have baked in the commit").isFalse();
            }
        }
    }

    private static boolean gitWorks() {
        try {
            return new ProcessBuilder("git", "-C", ROOT.toString(), "rev-parse", "HEAD").start().waitFor() == 0;
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }
}
