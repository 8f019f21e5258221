package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.ripv.server.ServerMain;

/**
 * {@code ./ripv server} starts the server's JVM with {@link ServerMain#JVM_OPTIONS} (issue 38: the
 * parallel collector, which the web benchmark launches it with too), lets {@code RIPV_SERVER_JVM}
 * replace them and leaves a collector chosen in {@code JAVA_TOOL_OPTIONS} alone (java refuses two).
 * Runs the real script with {@code JAVA} set to a stand-in that prints the arguments it gets.
 */
class RipvServerJvmTest {
    private static final Path ROOT = RipvScriptHelpTest.ROOT;

    @TempDir
    Path dir;

    private List<String> javaArgs(Map<String, String> env, String command) throws Exception {
        assumeTrue(Files.isRegularFile(ROOT.resolve("ripv-server/target/ripv-server.jar")), "needs the built jars (mvn package)");
        Path fake = dir.resolve("java");
        Files.writeString(fake, "#!/bin/sh\nfor a in \"$@\"; do echo \"$a\"; done\n", StandardCharsets.UTF_8);
        Files.setPosixFilePermissions(fake, PosixFilePermissions.fromString("rwx------"));
        ProcessBuilder pb = new ProcessBuilder("bash", ROOT.resolve("ripv").toString(), command, "--port", "4444")
                .redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        pb.environment().remove("RIPV_SERVER_JVM");
        pb.environment().putAll(env);
        pb.environment().put("JAVA", fake.toString());
        Process p = pb.start();
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.exitValue()).as(out).isZero();
        List<String> args = out.lines().toList();
        return new ArrayList<>(args.subList(0, args.indexOf("-jar")));
    }

    @Test
    void theServerRunsWithTheProductsJvmOptionsAndOthersDoNot() throws Exception {
        assertThat(ServerMain.JVM_OPTIONS).contains("-XX:+UseParallelGC");
        assertThat(javaArgs(Map.of(), "server")).containsSubsequence(ServerMain.JVM_OPTIONS);
        assertThat(javaArgs(Map.of(), "passwd")).doesNotContainAnyElementsOf(ServerMain.JVM_OPTIONS);
    }

    @Test
    void ripvServerJvmReplacesThemAndAToolOptionsCollectorIsLeftAlone() throws Exception {
        List<String> replaced = javaArgs(Map.of("RIPV_SERVER_JVM", "-XX:+UseSerialGC -Xmx300m"), "server");
        assertThat(replaced).contains("-XX:+UseSerialGC", "-Xmx300m").doesNotContain("-XX:+UseParallelGC");
        assertThat(javaArgs(Map.of("JAVA_TOOL_OPTIONS", "-XX:+UseG1GC"), "server")).doesNotContain("-XX:+UseParallelGC");
    }

    @Test
    void javaTakesThem() throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(ServerMain.JVM_OPTIONS);
        cmd.add("-version");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        assertThat(p.waitFor(30, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8)).isZero();
    }
}
