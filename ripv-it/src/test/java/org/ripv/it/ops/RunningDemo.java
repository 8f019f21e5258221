package org.ripv.it.ops;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.ripv.probe.FreePorts;

/**
 * {@code ./ripv demo} as the README runs it, headless, on free ports and in a folder of its own
 * (its RIPV_* variables), with HOME a test folder: started, waited for until it says it is
 * running, and stopped with {@code ./ripv demo --stop}.
 */
final class RunningDemo implements AutoCloseable {
    static final String RUNNING = "RIPV demo is running";

    final Path root;
    final Path dir;
    final Path home;
    final Path log;
    final int port;
    final int registryPort;
    final int httpPort;
    final int gliderPort;
    final int outboundPort;
    final int webhookPort;
    final ProcessWatch watch = new ProcessWatch();
    final Process process;

    private RunningDemo(Path root, Path dir, Path home, Path log, int[] ports, Map<String, String> extra) throws IOException {
        this.root = root;
        this.dir = dir;
        this.home = home;
        this.log = log;
        this.port = ports[0];
        this.registryPort = ports[1];
        this.httpPort = ports[2];
        this.gliderPort = ports[3];
        this.outboundPort = ports[4];
        this.webhookPort = ports[5];
        ProcessBuilder pb = new ProcessBuilder("bash", root.resolve("ripv").toString(), "demo").directory(root.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.environment().putAll(environment());
        pb.environment().putAll(extra);
        pb.environment().remove("DISPLAY");
        pb.environment().remove("RIPV_KNOWN_HOSTS");
        pb.environment().remove("RIPV_PASSWORD");
        pb.environment().put(ProcessWatch.VARIABLE, watch.mark);
        process = pb.start();
    }

    /** What makes a {@code ./ripv demo} this one: its folder, ports, HOME and no GUI. */
    Map<String, String> environment() {
        Map<String, String> env = new LinkedHashMap<>();
        env.put("RIPV_DEMO_DIR", dir.toString());
        env.put("RIPV_PORT", "" + port);
        env.put("RIPV_REGISTRY_PORT", "" + registryPort);
        env.put("RIPV_HTTP_PORT", "" + httpPort);
        env.put("RIPV_GLIDER_PORT", "" + gliderPort);
        env.put("RIPV_OUTBOUND_PORT", "" + outboundPort);
        env.put("RIPV_WEBHOOK_PORT", "" + webhookPort);
        env.put("RIPV_DEMO_HEADLESS", "1");
        env.put("HOME", home.toString());
        env.put("JAVA", org.ripv.it.TestJvms.java());
        return env;
    }

    /**
     * Starts {@code ROOT/ripv demo} and waits (up to {@code max}: a first run builds the jars) until
     * it says it is running; fails with its output if it ends or the time is up first.
     */
    static RunningDemo start(Path root, Path dir, Path home, Duration max, Map<String, String> extra) throws Exception {
        Files.createDirectories(home);
        Path log = Files.createTempFile(home.getParent(), "demo", ".log");
        RunningDemo demo = new RunningDemo(root, dir, home, log, FreePorts.several(6), extra);
        long end = System.nanoTime() + max.toNanos();
        while (!demo.output().contains(RUNNING)) {
            if (!demo.process.isAlive() || System.nanoTime() > end) {
                String out = demo.output();
                demo.close();
                throw new AssertionError("./ripv demo did not say it is running (" + (demo.process.isAlive() ? "timed out" : "it ended, "
                        + demo.process.exitValue()) + "):\n" + out + "\nserver.log:\n" + demo.logOf("server"));
            }
            demo.process.waitFor(200, TimeUnit.MILLISECONDS);
        }
        return demo;
    }

    String output() throws IOException {
        return Files.readString(log, StandardCharsets.UTF_8);
    }

    String logOf(String name) {
        try {
            return Files.readString(dir.resolve("logs/" + name + ".log"), StandardCharsets.UTF_8);
        } catch (IOException e) {
            return "(no " + name + ".log: " + e.getMessage() + ")";
        }
    }

    /** {@code ./ripv demo ARGS} with this demo's environment (other values from {@code extra}); exit status and output. */
    Result run(Map<String, String> extra, String... args) throws Exception {
        List<String> cmd = new java.util.ArrayList<>(List.of("bash", root.resolve("ripv").toString(), "demo"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(root.toFile()).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.environment().putAll(environment());
        pb.environment().putAll(extra);
        pb.environment().remove("DISPLAY");
        ProcessWatch other = new ProcessWatch();
        pb.environment().put(ProcessWatch.VARIABLE, other.mark);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        boolean ended = p.waitFor(120, TimeUnit.SECONDS);
        for (String s : other.processes()) {
            ProcessHandle.of(Long.parseLong(s.substring(0, s.indexOf(' ')))).ifPresent(ProcessHandle::destroyForcibly);
        }
        if (!ended) {
            p.destroyForcibly();
            throw new AssertionError("./ripv demo " + String.join(" ", args) + " still running after 120 s:\n" + out);
        }
        return new Result(p.exitValue(), out);
    }

    record Result(int exit, String output) {}

    /** {@code ./ripv demo --stop}, then anything of this demo still alive is killed. */
    @Override
    public void close() throws IOException {
        try {
            if (process.isAlive()) {
                run(Map.of(), "--stop");
                process.waitFor(60, TimeUnit.SECONDS);
            }
        } catch (Exception e) {
            // killed below
        } finally {
            for (String s : watch.processes()) {
                ProcessHandle.of(Long.parseLong(s.substring(0, s.indexOf(' ')))).ifPresent(ProcessHandle::destroyForcibly);
            }
            process.destroyForcibly();
        }
    }
}
