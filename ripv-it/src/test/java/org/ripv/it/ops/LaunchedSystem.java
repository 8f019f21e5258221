package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Predicate;
import java.util.regex.Pattern;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.ripv.it.InJvmCli;
import org.ripv.it.TestSystem;
import org.ripv.probe.FreePorts;
import org.ripv.server.permit.PermitFile;

/**
 * A RIPVServer and its services started from the jars the README starts ({@code java -jar
 * ripv-server.jar server …}, {@code java -jar ripv-services.jar serial|database|datavis|simulator …}),
 * each a process of its own: {@link TestSystem}'s launched counterpart. Every process writes to
 * {@code DIR/NAME.log} and has {@code DIR/home} for its home; the server keeps {@code DIR/ripv-data}.
 * Once {@link #startServer} returns, alice (an operator, password {@link TestSystem#PASSWORD}) can
 * log in, and {@link #cli} runs the CLI in the test's JVM as her.
 *
 * <p>A test class holds one as {@code @RegisterExtension final LaunchedSystem sys = new LaunchedSystem();}:
 * before each test it makes a new folder and picks free ports; after it, it stops every process, the
 * last started first, and deletes the folder unless the test failed (its logs are the evidence; the
 * path is printed).
 */
final class LaunchedSystem implements BeforeEachCallback, AfterEachCallback {
    static final Path ROOT = RipvScriptHelpTest.ROOT;
    static final Pattern MAILBOX = Pattern.compile("<(\\w+)>::<[^>]+>[A-Za-z0-9_.-]+");
    /** How long the server may take to say it is ready, and services to register. */
    static final Duration STARTUP = Duration.ofSeconds(120);

    Path dir;
    Path home;
    Path data;
    Path knownHosts;
    int clientPort;
    int registryPort;
    int outboundPort;
    /** A free port for the glider's link (the simulator listens or calls there). */
    int gliderPort;
    private final List<String> everyJvm;
    private CommandProcesses processes;
    private final Set<String> logs = new LinkedHashSet<>();
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();
    private Duration startup = STARTUP;

    /** {@code jvmOptions} go to every process started (as {@code -Dripv.host=localhost}). */
    LaunchedSystem(String... jvmOptions) {
        this.everyJvm = List.of(jvmOptions);
    }

    @Override
    public void beforeEach(ExtensionContext context) throws IOException {
        dir = Files.createTempDirectory("ripv-launched-");
        home = Files.createDirectories(dir.resolve("home"));
        data = dir.resolve("ripv-data");
        knownHosts = dir.resolve("known_hosts");
        int[] p = FreePorts.several(4);
        clientPort = p[0];
        registryPort = p[1];
        outboundPort = p[2];
        gliderPort = p[3];
        processes = new CommandProcesses(dir);
        logs.clear();
    }

    @Override
    public void afterEach(ExtensionContext context) throws Exception {
        close();
        if (context.getExecutionException().isPresent()) {
            System.out.println(context.getDisplayName() + " failed: the processes' logs are in " + dir);
            return;
        }
        try (var walk = Files.walk(dir)) {
            for (Path p : walk.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        }
    }

    /** Skips the test where the jars are not built ({@code mvn -DskipTests package} builds them). */
    static void assumeJars() {
        for (String m : List.of("ripv-server", "ripv-services")) {
            assumeTrue(Files.isRegularFile(Path.of(CommandProcesses.jar(m))), "needs the jars (mvn -DskipTests package builds them)");
        }
    }

    /** A longer wait than {@link #STARTUP} for the server's start and the services' registration. */
    LaunchedSystem startup(Duration patience) {
        this.startup = patience;
        return this;
    }

    /**
     * {@code java -Xmx256m [every process's options] JVM… -jar MODULE.jar ARGS…} in the test's folder,
     * its output to {@code NAME.log}. A {@code -Xmx} among {@code jvm} wins over the 256 MiB (the JVM takes the last).
     */
    Process launch(String name, String module, List<String> jvm, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(CommandProcesses.java(), "-Xmx256m", "-Duser.home=" + home));
        cmd.addAll(everyJvm);
        cmd.addAll(jvm);
        cmd.addAll(List.of("-jar", CommandProcesses.jar(module)));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile());
        pb.environment().put("HOME", home.toString());
        logs.add(name);
        return processes.start(pb, name + ".log");
    }

    /** Another process to stop with the rest (socat), its output to {@code NAME.log}. */
    Process start(String name, ProcessBuilder pb) throws IOException {
        logs.add(name);
        return processes.start(pb, name + ".log");
    }

    /**
     * The server on this system's data and ports (web console on any free port), once its log says
     * it is ready; alice's permit line is then written, for the server to read.
     */
    Process startServer(List<String> jvm, String... options) throws Exception {
        List<String> args = new ArrayList<>(List.of("server", "--data", data.toString(), "--port", "" + clientPort,
                "--registry-port", "" + registryPort, "--http-port", "0", "--outbound-port", "" + outboundPort));
        args.addAll(List.of(options));
        Process server = launch("server", "ripv-server", jvm, args.toArray(String[]::new));
        long end = System.nanoTime() + startup.toNanos();
        while (!log("server").contains("RIPVServer ready")) {
            assertThat(System.nanoTime()).as(log("server")).isLessThan(end);
            assertThat(server.isAlive()).as(log("server")).isTrue();
            Thread.sleep(200);
        }
        PermitFile.setUser(data.resolve("permit.txt"), "alice", TestSystem.PASSWORD.toCharArray(), List.of("operators"), 1000);
        return server;
    }

    /** {@code ripv-services.jar SERVICE --server localhost:REGISTRY --secret-file … OPTIONS…}, as {@code NAME.log}. */
    Process startService(String name, List<String> jvm, String service, String... options) throws IOException {
        List<String> args = new ArrayList<>(List.of(service, "--server", "localhost:" + registryPort,
                "--secret-file", data.resolve("service.secret").toString()));
        args.addAll(List.of(options));
        return launch(name, "ripv-services", jvm, args.toArray(String[]::new));
    }

    /** The glider simulator ({@code ripv-services.jar simulator OPTIONS…}), as {@code simulator.log}. */
    Process startSimulator(String... options) throws IOException {
        List<String> args = new ArrayList<>(List.of("simulator"));
        args.addAll(List.of(options));
        return launch("simulator", "ripv-services", List.of(), args.toArray(String[]::new));
    }

    /** What process {@code name} has written so far ("" if it was never started). */
    String log(String name) throws IOException {
        return processes.log(name + ".log");
    }

    /** Every process's log, each under its name: the evidence a failed wait shows. */
    String logs() throws IOException {
        StringBuilder b = new StringBuilder();
        for (String name : logs) {
            b.append("\n--- ").append(name).append(".log\n").append(log(name));
        }
        return b.toString();
    }

    /** The CLI as alice, running {@code lines} one {@code --exec} each; its exit code ({@link #out} has what it printed). */
    int cli(String... lines) {
        return InJvmCli.exec(out, out, InJvmCli.as("alice", "localhost:" + clientPort, "--timeout", "120",
                "--known-hosts", knownHosts.toString()), lines);
    }

    /** What the last {@link #cli} printed, output and errors. */
    String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    /** {@code command}'s answer once {@code done} holds for it, asking again every half second until {@code limit}. */
    String awaitAnswer(String command, Predicate<String> done, Duration limit) throws Exception {
        long end = System.nanoTime() + limit.toNanos();
        while (true) {
            cli(command);
            String text = out();
            if (done.test(text)) {
                return text;
            }
            assertThat(System.nanoTime()).as(command + " answers as awaited; last answer: " + text + "\nlogs:" + logs())
                    .isLessThan(end);
            Thread.sleep(500);
        }
    }

    /** {@code ?mailboxes} once every one of the services has a MailBox there. */
    String awaitServices(String... services) throws Exception {
        return awaitAnswer("?mailboxes", text -> {
            Set<String> seen = new java.util.HashSet<>();
            MAILBOX.matcher(text).results().forEach(r -> seen.add(r.group(1)));
            return seen.containsAll(List.of(services));
        }, startup);
    }

    /** {@code ?mailboxes} once each of {@code mailboxes} is there. */
    String awaitMailboxes(String... mailboxes) throws Exception {
        return awaitAnswer("?mailboxes", text -> List.of(mailboxes).stream().allMatch(text::contains), startup);
    }

    /** {@code ?history MAILBOX} once it has the event (services publish on a thread of their own). */
    String awaitHistory(String mailbox, String event) throws Exception {
        return awaitAnswer("?history " + mailbox, text -> text.contains(event), Duration.ofSeconds(60));
    }

    /** The first MailBox of {@code service} in a {@code ?mailboxes} answer. */
    static String mailbox(String mailboxes, String service) {
        return MAILBOX.matcher(mailboxes).results().filter(r -> r.group(1).equals(service)).findFirst().orElseThrow().group();
    }

    /** Stops every process, the last started first, each forcibly after 20 s. */
    void close() throws InterruptedException {
        processes.close();
    }
}
