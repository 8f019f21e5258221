package org.ripv.it.ops;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.ripv.probe.FreePorts;

/**
 * Every command in the docs' blocks marked runnable ({@code ```sh runnable}, see docs/README.md),
 * README.md's first, works as printed against a running {@code ./ripv demo} (headless, on free
 * ports, in a folder of its own): run through the real {@code ./ripv} with bash, with HOME a test
 * folder in which {@code ~/ripv-data} is the demo server's data directory. The users and files the
 * docs use are those the docs create: the README makes {@code ~/.ripv/pw} and adds alice with
 * {@code ripv passwd}. Every {@code ripv cli} is pointed at the demo's port; programs that run until
 * stopped ({@code ripv server}, {@code service}, {@code simulator}, {@code client}, {@code demo}) and
 * {@code ripv passwd} without input run with {@code RIPV_PARSE_ONLY=1} (their command line is
 * checked, nothing starts); {@code --follow} runs for a while and must still be following then.
 * Then the sample workflows run on the demo's glider, a second demo on the same folder is refused,
 * a launched CLI keeps its known_hosts under HOME, and {@code ./ripv demo --stop} stops it all.
 */
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class RunnableDocsTest {
    static final Path ROOT = RipvScriptHelpTest.ROOT;
    static final Pattern RIPV = Pattern.compile("(^|[|;&]\\s*)(\\./)?ripv(?=\\s|$)");
    static final Pattern LONG_RUNNING = Pattern.compile("(\\./)?ripv\\s+(server|service|simulator|client|demo)\\b");
    static final Pattern FOLLOW = Pattern.compile("--follow\\b");
    static final Duration FOLLOW_FOR = Duration.ofSeconds(20);
    static final String GLIDER = "<SerialPortServer>::<localhost>sim01";

    @TempDir
    static Path tmp;
    RunningDemo demo;
    Process clock;
    Path home;
    Path work;

    static Stream<RunnableDocs.Command> commands() throws Exception {
        List<RunnableDocs.Command> all = new ArrayList<>();
        for (Path doc : RunnableDocs.documents(ROOT)) {
            all.addAll(RunnableDocs.commands(doc));
        }
        return all.stream();
    }

    @BeforeAll
    void start() throws Exception {
        for (String m : List.of("ripv-common", "ripv-server", "ripv-services", "ripv-client")) {
            assumeTrue(Files.isRegularFile(ROOT.resolve(m + "/target/" + m + ".jar")),
                    "needs the jars (mvn package; mvn verify builds them before this module's tests)");
        }
        assumeTrue(ProcessWatch.supported(), "needs Linux /proc to find the processes a command starts");
        home = Files.createDirectories(tmp.resolve("home"));
        work = Files.createDirectories(tmp.resolve("work"));
        Files.createSymbolicLink(work.resolve("docs"), ROOT.resolve("docs")); // docs/samples/... as in the source tree
        Path demoDir = tmp.resolve("demo");
        Files.createSymbolicLink(home.resolve("ripv-data"), demoDir.resolve("server"));
        // A short call cycle, so that the sample workflows run within the test.
        demo = RunningDemo.start(ROOT, demoDir, home, Duration.ofMinutes(10),
                Map.of("RIPV_SURFACE_SECONDS", "40", "RIPV_DIVE_SECONDS", "5"));
        // extending.md's example service, as its page starts it (with the demo's secret and registry)
        Path clockLog = tmp.resolve("clock.log");
        ProcessBuilder pb = new ProcessBuilder("bash", ROOT.resolve("ripv").toString(), "service", "clock", "--server",
                "localhost:" + demo.registryPort, "--host", "localhost", "--secret-file", demoDir.resolve("server/service.secret").toString())
                .redirectErrorStream(true).redirectOutput(clockLog.toFile());
        pb.environment().put("HOME", home.toString());
        pb.environment().put("JAVA", org.ripv.it.TestJvms.java());
        pb.environment().put(ProcessWatch.VARIABLE, demo.watch.mark); // stopped with the demo's processes at the end
        clock = pb.start();
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (!Files.readString(clockLog, StandardCharsets.UTF_8).contains("registered with the RIPVServer")) {
            assertThat(clock.isAlive()).as(Files.readString(clockLog, StandardCharsets.UTF_8)).isTrue();
            assertThat(System.nanoTime()).as("the ClockService registers").isLessThan(end);
            clock.waitFor(200, TimeUnit.MILLISECONDS);
        }
    }

    @AfterAll
    void stop() throws Exception {
        for (Following f : following) {
            f.process().descendants().forEach(ProcessHandle::destroyForcibly);
            f.process().destroyForcibly();
        }
        if (clock != null) {
            clock.destroy();
        }
        if (demo != null) {
            demo.close();
        }
    }

    @Test
    @Order(0)
    void aTrailingCommentIsNoPartOfTheCommand() {
        assertThat(RunnableDocs.withoutComment("./ripv server --data ~/d   # clients on 4444")).isEqualTo("./ripv server --data ~/d   ");
        assertThat(RunnableDocs.withoutComment("./ripv cli --exec 'SELECT 1 # not a comment'")).endsWith("comment'");
        assertThat(RunnableDocs.withoutComment("echo a#b")).isEqualTo("echo a#b");
    }

    @Test
    @Order(0)
    void theDocsMarkARepresentativeSetOfCommandsRunnable() throws Exception {
        List<String> texts = commands().map(RunnableDocs.Command::text).toList();
        assertThat(texts).hasSizeGreaterThanOrEqualTo(15);
        for (String c : List.of(" cli ", " server", " passwd", " service ", " bench", "--json", "put ", "get ", "vis:", "SELECT",
                "--follow", "install -m 600")) {
            assertThat(texts).as("a runnable command with '" + c + "'").anyMatch(t -> t.contains(c));
        }
        assertThat(commands().findFirst().orElseThrow().file().getFileName().toString()).as("the README's first").isEqualTo("README.md");
    }

    /** A command that reads its password (ripv passwd) from a pipe or a file it is given. */
    static boolean hasInput(String text) {
        int passwd = text.indexOf("passwd");
        int pipe = text.indexOf('|');
        return pipe >= 0 && pipe < passwd || text.indexOf('<', passwd) > passwd;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("commands")
    @Order(1)
    void everyRunnableCommandInTheDocsWorks(RunnableDocs.Command command) throws Exception {
        String line = rewrite(command.text());
        boolean follow = FOLLOW.matcher(command.text()).find();
        boolean dryRun = !follow && (LONG_RUNNING.matcher(command.text()).find()
                || command.text().matches(".*\\bripv\\s+passwd\\b.*") && !hasInput(command.text()));
        Path log = Files.createTempFile(tmp, "command", ".log");
        ProcessBuilder pb = new ProcessBuilder("bash", "-o", "pipefail", "-c", line).directory(work.toFile())
                .redirectErrorStream(true).redirectOutput(log.toFile())
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        ProcessWatch watch = new ProcessWatch();
        pb.environment().put(ProcessWatch.VARIABLE, watch.mark);
        pb.environment().put("HOME", home.toString());
        pb.environment().put("JAVA", org.ripv.it.TestJvms.java());
        pb.environment().remove("RIPV_PASSWORD");
        pb.environment().remove("RIPV_KNOWN_HOSTS");
        pb.environment().remove("DISPLAY");
        if (dryRun) {
            pb.environment().put("RIPV_PARSE_ONLY", "1");
        }
        Process p = pb.start();
        if (follow) {
            // Judged by theFollowingCommandsStillFollow once FOLLOW_FOR has passed; the commands after it run meanwhile
            // (issue 38: two follows waited 40 s here, alone).
            following.add(new Following(command, line, p, watch, log, System.nanoTime()));
            return;
        }
        boolean ended = p.waitFor(120, TimeUnit.SECONDS);
        var left = watch.processes();
        for (String s : left) { // nothing a documented command started may outlive it
            ProcessHandle.of(Long.parseLong(s.substring(0, s.indexOf(' ')))).ifPresent(ProcessHandle::destroyForcibly);
        }
        p.destroyForcibly();
        String out = Files.readString(log, StandardCharsets.UTF_8);
        assertThat(out).as(command + "\nran as: " + line).doesNotContain("Exception").doesNotContain("Error:");
        assertThat(ended).as(command + " still running after 120 s:\n" + out).isTrue();
        assertThat(left).as(command + " left processes").isEmpty();
        assertThat(p.exitValue()).as(command + "\nran as: " + line + "\n" + out).isZero();
    }

    /** Points the command at this test's script and the demo. */
    String rewrite(String text) {
        String line = RIPV.matcher(text).replaceAll(m -> Matcher.quoteReplacement(m.group(1) + ROOT.resolve("ripv")));
        if (text.matches(".*\\bripv\\s+cli\\b.*")) {
            line = line.replaceAll("--server\\s+\\S+", "--server localhost:" + demo.port);
        } else if (text.matches(".*\\bripv\\s+service\\b.*")) {
            line = line.replaceAll("--server\\s+\\S+", "--server localhost:" + demo.registryPort);
        }
        return line;
    }

    /** {@code ./ripv cli} as the demo's operator, with these lines. */
    String cli(String... lines) throws Exception {
        List<String> cmd = new ArrayList<>(List.of("bash", ROOT.resolve("ripv").toString(), "cli", "--server", "localhost:" + demo.port,
                "--user", "demo", "--password-file", demo.dir.resolve("password").toString()));
        for (String l : lines) {
            cmd.addAll(List.of("--exec", l));
        }
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(work.toFile()).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.environment().put("HOME", home.toString());
        pb.environment().put("JAVA", org.ripv.it.TestJvms.java());
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        assertThat(p.exitValue()).as(String.join(" ; ", lines) + ":\n" + out).isZero();
        return out;
    }

    /**
     * The receipt of the last run of the named workflow file, once it has a result that ends it: a
     * run CUT by the end of a call is not over, the glider's next call resumes it at the cut step
     * (on a loaded machine the demo's call often ends between two steps).
     */
    static String lastReceipt(String receipts, String file) {
        String found = null;
        for (String r : receipts.split("(?m)^(?=receipt: )")) {
            if (r.startsWith("receipt: ") && r.contains("'" + file + "'") && r.contains("\nresult: ")
                    && !r.contains("result: RUNNING") && !r.contains("result: CUT")) {
                found = r;
            }
        }
        return found;
    }

    /** Every run's receipt of a workflow, oldest first: a call that ends mid-run leaves the rest to the next run. */
    static String allReceipts(String receipts, String file) {
        StringBuilder all = new StringBuilder();
        for (String r : receipts.split("(?m)^(?=receipt: )")) {
            if (r.startsWith("receipt: ") && r.contains("'" + file + "'")) {
                all.append(r);
            }
        }
        return all.toString();
    }

    /** A documented {@code --follow} started by everyRunnableCommandInTheDocsWorks, judged later. */
    record Following(RunnableDocs.Command command, String line, Process process, ProcessWatch watch, Path log, long started) {}

    final List<Following> following = new ArrayList<>();

    /**
     * Following runs until Ctrl-C: FOLLOW_FOR after its start (the sample workflows ran on the demo's
     * glider meanwhile) each {@code --follow} must still be at it, not have ended with an error.
     */
    @Test
    @Order(3)
    void theFollowingCommandsStillFollow() throws Exception {
        assertThat(following).as("the docs' --follow commands ran").isNotEmpty();
        try {
            for (Following f : following) {
                long left = f.started() + FOLLOW_FOR.toNanos() - System.nanoTime();
                boolean ended = f.process().waitFor(Math.max(0, left), TimeUnit.NANOSECONDS);
                String out = Files.readString(f.log(), StandardCharsets.UTF_8);
                assertThat(ended).as(f.command() + " ended within " + FOLLOW_FOR.toSeconds() + " s instead of following:\n" + out)
                        .isFalse();
                assertThat(out).as(f.command() + "\nran as: " + f.line()).doesNotContain("Exception").doesNotContain("Error:");
            }
        } finally {
            for (Following f : following) { // nothing a documented command started may outlive it
                for (String s : f.watch().processes()) {
                    ProcessHandle.of(Long.parseLong(s.substring(0, s.indexOf(' ')))).ifPresent(ProcessHandle::destroyForcibly);
                }
                f.process().destroyForcibly();
            }
        }
    }

    /** Whether the demo's server.log has a verdict of a run of {@code workflow} (RunEnd's event: "WORKFLOW_DONE workflow 3 'f.wf': done"). */
    private boolean verdictLogged(String workflow) {
        return Pattern.compile("WORKFLOW_(DONE|DONE_WITH_ERRORS|FAILED) workflow \\d+ '[^']*" + Pattern.quote(workflow) + "': ")
                .matcher(demo.logOf("server")).find();
    }

    @Test
    @Order(2)
    void theSampleWorkflowsRunOnTheDemosGlider() throws Exception {
        // As the samples' comments say; the demo has them (and goto_l10.ma) in its upload store.
        cli("put docs/samples/goto_l10.ma --replace", "put docs/samples/ru29-new-mission.wf --replace",
                "put docs/samples/ru29-every-call.wf --replace",
                "?queue add " + GLIDER + " ru29-new-mission.wf", "?queue add " + GLIDER + " ru29-every-call.wf");
        long end = System.nanoTime() + TimeUnit.MINUTES.toNanos(5);
        // The server logs each run's verdict (WORKFLOW_DONE workflow N 'NAME': done, ...): a file read, where asking ?receipts
        // every 3 s started a client JVM each time for the minute or more the samples take (issue 38); then
        // ?receipts as before, with a minute of its own.
        long logged = end - TimeUnit.MINUTES.toNanos(1);
        while (!(verdictLogged("ru29-new-mission.wf") && verdictLogged("ru29-every-call.wf")) && System.nanoTime() < logged) {
            Thread.sleep(250);
        }
        String receipts = cli("?receipts " + GLIDER + " --last 10");
        while (lastReceipt(receipts, "ru29-new-mission.wf") == null || lastReceipt(receipts, "ru29-every-call.wf") == null) {
            assertThat(System.nanoTime()).as("both samples ran on a call of the demo's glider:\n" + receipts).isLessThan(end);
            Thread.sleep(3_000);
            receipts = cli("?receipts " + GLIDER + " --last 10");
        }
        // The glider's call may end between two steps: the next call's run resumes at the cut step,
        // so the steps are looked for in every run's receipt and the verdict in the last one's.
        String mission = allReceipts(receipts, "ru29-new-mission.wf");
        assertThat(lastReceipt(receipts, "ru29-new-mission.wf")).as(mission).contains("result: DONE");
        assertThat(mission).as(mission).doesNotContain("FAILED")
                .contains("step 1/4 (line 8) ymodem:put goto_l10.ma: OK")
                .contains("step 3/4").contains("step 4/4");
        String everyCall = allReceipts(receipts, "ru29-every-call.wf");
        assertThat(lastReceipt(receipts, "ru29-every-call.wf")).as(everyCall).contains("result: DONE");
        assertThat(everyCall).as(everyCall).contains("ymodem:get *.LOG: OK")
                .doesNotContain("REJECTED").doesNotContain("SQLState");
        // Only the steps the demo cannot satisfy may fail, as the sample allows: the simulator's mission
        // logs are not Slocum DBA files (ingest says so), and its glider is sim01, not ru29.
        for (String l : everyCall.lines().filter(l -> l.startsWith("step ")).toList()) {
            assertThat(l).as(everyCall).matches(".*: OK in .*|.*(ingest|vis:track ru29).*FAILED \\(continue-on-error\\).*");
        }
        if (everyCall.contains("ingest to=<DatabaseServer>::<localhost>TTY1: FAILED")) {
            assertThat(everyCall).as(everyCall).contains("not a DBA file");
        }
    }

    @Test
    @Order(3)
    void aSecondDemoOnTheSameFolderSaysWhichProcessHoldsItAndTouchesNothing() throws Exception {
        String serverLog = demo.logOf("server");
        String[] names = {"RIPV_PORT", "RIPV_REGISTRY_PORT", "RIPV_HTTP_PORT", "RIPV_GLIDER_PORT"};
        int[] other = FreePorts.several(4);
        Map<String, String> otherPorts = new java.util.HashMap<>();
        for (int i = 0; i < 4; i++) {
            otherPorts.put(names[i], "" + other[i]);
        }
        for (Map<String, String> env : List.of(otherPorts, Map.<String, String>of())) {
            RunningDemo.Result second = demo.run(env);
            assertThat(second.exit()).as(second.output()).isEqualTo(1);
            assertThat(second.output()).contains("ripv demo: " + demo.dir + " is in use by the demo running as process " + demo.process.pid())
                    .contains("ripv demo --stop").doesNotContain("starting");
            assertThat(demo.logOf("server")).as("the running demo's log is not truncated").startsWith(serverLog);
            assertThat(demo.process.isAlive()).isTrue();
        }
    }

    @Test
    @Order(3)
    void aLaunchedCliKeepsItsFilesUnderHome() throws Exception {
        Path otherHome = Files.createDirectories(tmp.resolve("other-home"));
        List<String> base = List.of("bash", ROOT.resolve("ripv").toString(), "cli", "--server", "localhost:" + demo.port, "--user", "demo");
        List<String> ok = new ArrayList<>(base);
        ok.addAll(List.of("--password-file", demo.dir.resolve("password").toString(), "--exec", "?whoami"));
        RunningDemo.Result r = run(ok, otherHome);
        assertThat(r.exit()).as(r.output()).isZero();
        assertThat(otherHome.resolve(".ripv/known_hosts")).as(r.output()).exists();
        assertThat(Files.readString(otherHome.resolve(".ripv/known_hosts"), StandardCharsets.UTF_8)).contains("localhost:" + demo.port);

        List<String> missing = new ArrayList<>(base);
        Path pw = otherHome.resolve(".ripv/pw");
        missing.addAll(List.of("--password-file", pw.toString(), "--exec", "?whoami"));
        RunningDemo.Result m = run(missing, otherHome);
        assertThat(m.exit()).as(m.output()).isEqualTo(2);
        assertThat(m.output()).contains("Error: the password file " + pw + " does not exist")
                .contains("install -m 600 /dev/null " + pw).doesNotContain("Exception");
    }

    RunningDemo.Result run(List<String> cmd, Path withHome) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(work.toFile()).redirectErrorStream(true)
                .redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.environment().put("HOME", withHome.toString());
        pb.environment().put("JAVA", org.ripv.it.TestJvms.java());
        pb.environment().remove("RIPV_KNOWN_HOSTS");
        pb.environment().remove("RIPV_PASSWORD");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertThat(p.waitFor(120, TimeUnit.SECONDS)).isTrue();
        return new RunningDemo.Result(p.exitValue(), out);
    }

    @Test
    @Order(4)
    void demoStopStopsTheDemoOfThatFolder() throws Exception {
        clock.destroy();
        clock.waitFor(30, TimeUnit.SECONDS);
        RunningDemo.Result stop = demo.run(Map.of(), "--stop");
        assertThat(stop.exit()).as(stop.output()).isZero();
        assertThat(stop.output()).contains("stopping the demo (process " + demo.process.pid() + ")");
        assertThat(demo.process.waitFor(60, TimeUnit.SECONDS)).as("the demo ends").isTrue();
        assertThat(demo.watch.processes()).as("every process of the demo ends with it").isEmpty();
        assertThat(demo.dir.resolve("demo.pid")).doesNotExist();
        RunningDemo.Result again = demo.run(Map.of(), "--stop");
        assertThat(again.exit()).isZero();
        assertThat(again.output()).contains("no demo is running from " + demo.dir);
    }

    @Test
    @Order(0)
    void aDryRunStillRefusesAnOptionThatDoesNotExist() throws Exception {
        for (String c : List.of("./ripv server --data ~/d --no-such-option", "./ripv service serial --server localhost --no-such-option",
                "./ripv demo --no-such-option")) {
            ProcessBuilder pb = new ProcessBuilder("bash", "-c", RIPV.matcher(c).replaceAll(m -> Matcher.quoteReplacement(m.group(1)
                    + ROOT.resolve("ripv")))).directory(work.toFile()).redirectErrorStream(true);
            pb.environment().put("RIPV_PARSE_ONLY", "1");
            Process p = pb.start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            assertThat(p.waitFor(60, TimeUnit.SECONDS)).isTrue();
            assertThat(p.exitValue()).as(c + ": " + out).isEqualTo(2);
        }
    }
}
