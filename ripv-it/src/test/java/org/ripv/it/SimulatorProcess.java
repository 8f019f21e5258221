package org.ripv.it;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The glider simulator as its own process, started as the {@code ripv} launcher starts it
 * ({@code java -jar ripv-services.jar simulator ...}; from the test class path when the jar has not
 * been built), its output in a log file.
 */
final class SimulatorProcess {
    static final Path ROOT = Path.of("..").toAbsolutePath().normalize();

    private SimulatorProcess() {
    }

    static Process start(Path log, List<String> options) throws IOException {
        String java = TestJvms.java();
        Path jar = ROOT.resolve("ripv-services/target/ripv-services.jar");
        List<String> cmd = new ArrayList<>(Files.isRegularFile(jar) ? List.of(java, "-jar", jar.toString())
                : List.of(java, "-cp", System.getProperty("java.class.path"), "org.ripv.services.ServicesMain"));
        cmd.add("simulator");
        cmd.addAll(options);
        return new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
    }

    /** SIGTERM, then SIGKILL if it has not gone in 20 s. */
    static void stop(Process p) throws InterruptedException {
        if (p != null) {
            p.destroy();
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
    }
}
