package org.ripv.it;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Processes a test starts as the {@code ripv} launcher does ({@code bash ripv service serial …}),
 * or any other helper process it hands over, each with a home of the test's own; closing stops
 * them and their children.
 */
final class LaunchedJars implements AutoCloseable {
    static final Path ROOT = Path.of(System.getProperty("user.dir")).toAbsolutePath().getParent();

    private final Path dir;
    private final List<Process> started = new ArrayList<>();

    LaunchedJars(Path dir) {
        this.dir = dir;
    }

    /** {@code ripv ARGS…} in the test's folder, its output to {@code log}. */
    Process launch(Path log, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of("bash", ROOT.resolve("ripv").toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        pb.environment().put("HOME", dir.resolve("home").toString());
        // Java takes its home from the password file, not $HOME: the CLI's known_hosts must be the test's own
        pb.environment().put("JAVA_TOOL_OPTIONS", "-Duser.home=" + dir.resolve("home"));
        pb.environment().put("JAVA", TestJvms.java());
        pb.environment().remove("DISPLAY");
        return add(pb.start());
    }

    /** Another process to stop with the rest (socat, the simulator). */
    Process add(Process p) {
        started.add(p);
        return p;
    }

    @Override
    public void close() throws InterruptedException {
        for (Process p : started) {
            p.descendants().forEach(ProcessHandle::destroy);
            p.destroy();
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
        started.clear();
    }
}
